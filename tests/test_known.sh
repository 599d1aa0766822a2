#!/usr/bin/env bash
# Scenes with known answers, for the full light transport with the default estimators:
#  - furnace: a closed box, every wall diffuse with albedo a = 0.5 and emitting Le = 1, so
#    L = Le (1 + a + a^2 + ...) = Le / (1 - a) = 2 everywhere;
#  - sphere-furnace (pbrt-v4's integrator test): inside a sphere with Kd = 0.5 emitting Le = 0.5,
#    L = 0.5 / (1 - 0.5) = 1 everywhere.
# Each render is checked against a constant image of zero variance by tests/zcheck (per-pixel,
# per-block and whole-image Z-tests, alpha = 0.01 with Sidak's correction).
. "$(dirname "$0")/lib.sh"
ZCHECK=$BUILD/tests/zcheck
known() {   # name scene value flags...
    local name=$1 scene=$2 value=$3; shift 3
    $PATHLAB render "scenes/$scene.obj" --quiet --size 32x32 --spp 64 "$@" -o "$TMP/$name.pfm" --variance "$TMP/${name}_var.pfm"
    oiiotool --pattern constant:color=$value,$value,$value 32x32 3 -d float -o "$TMP/exact.pfm" 2>/dev/null
    oiiotool --pattern constant:color=0,0,0 32x32 3 -d float -o "$TMP/zero.pfm" 2>/dev/null
    if msg=$($ZCHECK "$TMP/$name.pfm" "$TMP/${name}_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm"); then
        pass "$name: L = $value ($msg)"
    else fail "$name: expected L = $value: $msg"; fi
}
known "furnace, default estimators" furnace 2
known "furnace, light sampling only, cosine" furnace 2 --direct light --dir cosine
known "furnace, BRDF sampling only, uniform" furnace 2 --direct brdf --dir uniform
known "sphere furnace, default estimators" sphere-furnace 1
known "sphere furnace, mis-balance, power lights, no roulette, 40 bounces" sphere-furnace 1 --direct mis-balance --light power --rr off --bounces 0:40
# the check must see a wrong answer: L0..L3 of the furnace is 1 + .5 + .25 + .125 = 1.875, not 2
$PATHLAB render scenes/furnace.obj --quiet --size 32x32 --spp 64 --bounces 0:3 -o "$TMP/f3.pfm" --variance "$TMP/f3_var.pfm"
if msg=$($ZCHECK "$TMP/f3.pfm" "$TMP/f3_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm"); then fail "furnace L0..L3 passes as the full answer: $msg"
else pass "furnace L0..L3 (1.875) is told apart from the full answer (2)"; fi
exit 0
