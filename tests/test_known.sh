#!/usr/bin/env bash
# Scenes with known answers, for the full light transport:
#  - furnace: a closed box, every wall diffuse with albedo a = 0.5 and emitting Le = 1, so
#    L = Le (1 + a + a^2 + ...) = Le / (1 - a) = 2 everywhere;
#  - sphere-furnace (pbrt-v4's integrator test): inside a sphere with Kd = 0.5 emitting Le = 0.5,
#    L = 0.5 / (1 - 0.5) = 1 everywhere.
# Each render (16x16 pixels, 1024 spp) is checked against the exact constant image (variance 0) by
# tests/zcheck: per-block (8x8 pixels) and whole-image Z-tests, alpha = 0.01 with Sidak's
# correction. No per-pixel test here: light sampling near the box's corners, where
# cos cos / d^2 is unbounded, gives heavy-tailed pixel estimates whose variance 1024 samples do
# not pin down; means over 64 and 256 pixels do.
. "$(dirname "$0")/lib.sh"
$PFMTOOL const 16 16 0 0 0 "$TMP/zero.pfm"
known() {   # name scene value flags...
    local name=$1 scene=$2 value=$3; shift 3
    $PATHLAB render "scenes/$scene.obj" --quiet --size 16x16 --spp 1024 "$@" -o "$TMP/r.pfm" --variance "$TMP/r_var.pfm"
    $PFMTOOL const 16 16 "$value" "$value" "$value" "$TMP/exact.pfm"
    zcheck_expect "$name: L = $value" 0 "$TMP/r.pfm" "$TMP/r_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm" --pixel-pass 0
}
known "furnace, default estimators" furnace 2
known "furnace, light sampling only, cosine" furnace 2 --direct light --dir cosine
known "furnace, BRDF sampling only, uniform" furnace 2 --direct brdf --dir uniform
known "sphere furnace, default estimators" sphere-furnace 1
known "sphere furnace, mis-balance, power lights, no roulette, 40 bounces" sphere-furnace 1 --direct mis-balance --light power --rr off --bounces 0:40
# the check must see a wrong answer: L0..L3 of the furnace is 1 + .5 + .25 + .125 = 1.875, not 2
$PATHLAB render scenes/furnace.obj --quiet --size 16x16 --spp 1024 --bounces 0:3 -o "$TMP/f3.pfm" --variance "$TMP/f3_var.pfm"
$PFMTOOL const 16 16 2 2 2 "$TMP/exact.pfm"
zcheck_expect "furnace L0..L3 (1.875) is told apart from the full answer (2)" 1 "$TMP/f3.pfm" "$TMP/f3_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm" --pixel-pass 0
# and a 0.5% error: the furnace with its albedo at 0.5025 instead of 0.5 would give 2.01
$PFMTOOL const 16 16 2.01 2.01 2.01 "$TMP/exact.pfm"
$PATHLAB render scenes/furnace.obj --quiet --size 16x16 --spp 1024 -o "$TMP/r.pfm" --variance "$TMP/r_var.pfm"
zcheck_expect "furnace: an answer 0.5% off (2.01) is told apart" 1 "$TMP/r.pfm" "$TMP/r_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm" --pixel-pass 0

# Bounce by bounce: in the furnace L_k = Le a^k = 0.5^k exactly, for k = 0..6, with each --direct
# strategy (one --split render each). MIS gets the block and whole-image tests; light-only and
# BRDF-only get the whole-image test only: light sampling near the box's edges has unbounded
# variance (cos cos / d^2 ~ 1/d^2 as both points near the edge), which makes block variances
# unreliable, and Russian roulette (from bounce 3) multiplies the spikes.
for mode in "mis-power:8" "light:0" "brdf:0"; do
    direct=${mode%%:*}; block=${mode##*:}
    $PATHLAB render scenes/furnace.obj --quiet --size 16x16 --spp 1024 --bounces 0:6 --split --direct "$direct" \
        -o "$TMP/fk.pfm" --variance "$TMP/fkv.pfm"
    for k in 0 1 2 3 4 5 6; do
        v=$(awk -v k=$k 'BEGIN { printf "%.9g", 0.5 ^ k }')
        $PFMTOOL const 16 16 "$v" "$v" "$v" "$TMP/exact.pfm"
        zcheck_expect "furnace --direct $direct: L$k = 0.5^$k = $v" 0 "$TMP/fk_L$k.pfm" "$TMP/fkv_L$k.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm" --pixel-pass 0 --block "$block"
    done
done
exit 0
