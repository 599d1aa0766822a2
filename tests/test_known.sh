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
exit 0
