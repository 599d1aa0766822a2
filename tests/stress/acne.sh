#!/usr/bin/env bash
# tests/stress/acne.sh — self-intersection ("acne") measured as lost energy in the furnace.
#
# A closed cube, every wall diffuse Kd = 0.5 emitting Le = 1 inward, has L = Le/(1 - Kd) = 2 in every
# pixel (tests/test_known.sh). A ray that hits the surface it leaves loses that bounce: the image
# gets darker. The cube is [0, 556]^3, where the Cornell box is (three walls on the planes x = 0,
# y = 0, z = 0), scaled by 1e-5 .. 1e5 and moved 1e4 and 1e6 away from the origin like the stress
# suite's Cornell boxes, and also turned (no wall on a coordinate plane); the camera at its centre
# faces the corner nearest the origin (32x32, 1024 spp, fov 90).
#
# pathlab has no switch to turn its ray offsets off, so this script builds two variants of the
# program in a temporary folder from the repository's src/ (never from a copy it keeps): the file that defines
# offset_ray_origin is compiled with it renamed, and one more file gives offset_ray_origin either as
# "no offset" (the origin is the hit point) or as "fixed epsilon" (1e-4 along the normal, the usual
# first try). Their figures are information; the test is on the program under test ($PATHLAB):
# with its robust offsets the furnace must stay at 2 within 0.1% at every scale (the standard error
# of the image mean, printed, is about 0.02%).
#
# Usage: tests/stress/acne.sh   (environment: PATHLAB, CC, ACNE_SPP, ACNE_VARIANT_SPP, ACNE_SCENES;
# prints PASS/FAIL lines, run by tests/stress/run.sh)
set -u
cd "$(dirname "$0")/../.."
PATHLAB=${PATHLAB:-./pathlab}
CC=${CC:-cc}
GEN="python3 tests/stress/gen.py"
ACNE_TMP=$(mktemp -d); trap 'rm -rf "$ACNE_TMP"' EXIT
SPP=${ACNE_SPP:-1024}          # the program under test (standard error ~0.02%)
VSPP=${ACNE_VARIANT_SPP:-256}  # the variants: information, their losses are percents
CASES="scale1 scale1e-05 scale0.001 scale1000 scale100000 move10000 move1e+06 rot_scale1 rot_move1e+06"

if ! command -v python3 >/dev/null 2>&1; then echo "FAIL acne: python3 is needed to write the scenes"; exit 1; fi
SC=${ACNE_SCENES:-$ACNE_TMP/s}   # run.sh passes the scenes it wrote
[ -f "$SC/furnace_scale1.obj" ] || $GEN scenes "$SC" > /dev/null || { echo "FAIL acne: tests/stress/gen.py could not write the scenes"; exit 1; }

# --- the variants: the same sources, offset_ray_origin replaced -------------------------------------
build_variant() {   # name body
    local d=$ACNE_TMP/$1 f ok=0
    mkdir -p "$d"
    cat > "$d/origin.c" <<EOF
/* acne.sh variant "$1" of offset_ray_origin, linked instead of src/$ORIGIN_C's */
#include "$ORIGIN_H"
$PROTO
{
    $2
}
EOF
    local flags="-std=c99 -O2 -D_POSIX_C_SOURCE=200809L -Isrc"
    for f in src/*/*.c; do
        o=$d/$(echo "${f#src/}" | tr / _); o=${o%.c}.o   # LAYER_NAME.o: cmd/grade.c and grade/grade.c both exist
        case $f in
            "src/$ORIGIN_C") echo "$CC $flags -Doffset_ray_origin=offset_ray_origin_robust -c -o $o $f" ;;
            *) echo "$CC $flags -c -o $o $f" ;;
        esac
    done > "$d/cmds"
    echo "$CC $flags -c -o $d/origin_variant.o $d/origin.c" >> "$d/cmds"
    echo "$CC $flags -c -o $d/web_assets.o ${BUILD:-build}/gen/web_assets.c" >> "$d/cmds"   # the viewer's, made by make
    if xargs -P "$(nproc 2>/dev/null || echo 2)" -I{} sh -c '{}' < "$d/cmds" > "$d/log" 2>&1 &&
       $CC -o "$d/pathlab" "$d"/*.o -lm -lpthread >> "$d/log" 2>&1; then ok=1; fi
    [ $ok = 1 ] || { echo "FAIL acne: could not build the '$1' variant: $(head -c 400 "$d/log")"; return 1; }
}
# the header that declares offset_ray_origin, the file that defines it (src/LAYER/NAME), and the
# prototype as declared (its parameters must include vec3 p and vec3 n)
ORIGIN_H=$(cd src && grep -l 'vec3 offset_ray_origin(' */*.h | head -n 1)
ORIGIN_C=${ORIGIN_H%.h}.c
PROTO=$(grep -o 'vec3 offset_ray_origin([^)]*)' "src/$ORIGIN_H" 2>/dev/null | head -n 1)
case $PROTO in *"vec3 p,"*"vec3 n"*) ;; *) echo "FAIL acne: no header of src/ declares offset_ray_origin(vec3 p, vec3 n, ...): '$PROTO'"; PROTO="" ;; esac
variants=""
[ -n "$PROTO" ] && build_variant nooffset "(void)n; return p;" && variants="$variants nooffset"
[ -n "$PROTO" ] && build_variant epsilon "return v3_madd(p, n, 1e-4f);" && variants="$variants epsilon"

# --- the furnace with each program ------------------------------------------------------------------
furnace() {   # program case spp -> prints "mean se nan" or "error: ..."
    local out=$ACNE_TMP/r_$RANDOM
    "$1" render "$SC/furnace_$2.obj" --spp "$3" -o "$out.pfm" --variance "${out}_v.pfm" 2> "$out.err" > /dev/null
    local rc=$? nan
    nan=$(sed -n 's/.* \([0-9][0-9]*\) NaN\/Inf samples.*/\1/p' "$out.err" | tail -n 1)
    if [ $rc -ne 0 ] || [ -z "$nan" ]; then echo "error: status $rc: $(tail -c 200 "$out.err")"; return; fi
    echo "$($GEN mean "$out.pfm" "${out}_v.pfm" | awk '{print $2, $4}') $nan"
}
rel() { awk -v m="$1" 'BEGIN { printf "%+.3f%%", (m / 2 - 1) * 100 }'; }

for c in $CASES; do
    set -- $(furnace "$PATHLAB" "$c" "$SPP")
    if [ "$1" = "error:" ]; then echo "FAIL acne, furnace $c: $PATHLAB $*"; continue; fi
    m=$1 se=$2 nan=$3
    info=""
    for v in $variants; do
        set -- $(furnace "$ACNE_TMP/$v/pathlab" "$c" "$VSPP")
        if [ "$1" = "error:" ]; then info="$info; $v: did not render"; else info="$info; $v: $(rel "$1")"; fi
    done
    figure="robust offsets: L = $m, $(rel "$m") +- $(awk -v s="$se" 'BEGIN { printf "%.3f%%", s / 2 * 100 }'), $nan NaN/Inf$info"
    if awk -v m="$m" 'BEGIN { exit !((m / 2 - 1) < 0.001 && (m / 2 - 1) > -0.001) }' && [ "$nan" = 0 ]; then
        echo "PASS acne, furnace $c: L = 2 within 0.1% ($figure)"
    else
        echo "FAIL acne, furnace $c: L = 2 within 0.1%: $figure"
    fi
done
exit 0
