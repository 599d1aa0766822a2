#!/usr/bin/env bash
# pathlab grade and the everyday mistakes of a class (issue 10): every mistake a student makes with
# an honest renderer must fail (exit 1) or be refused (exit 2); honest images must pass.
#
# Honest: the Cornell box at 64x64 (against ref/cornell.pfm) and 128x128 (ref/cornell-128.pfm),
# full transport, default estimators, 1 4 16 64 256 spp, 2 seeds each: 20 images, at most one may
# fail (alpha 0.01: P(>= 2 of 20) ~ 1.7%). Mistakes (tests/mistakes.py) on the 16 and 64 spp
# images of both sizes, both seeds (8 bases): flipped, rotated, grey (PF and Pf), sRGB or gamma
# encoded, clamped, quantised to 8 bits, scaled (pi, 1/pi, 2, 0.5, 1.3), a big-endian header on
# little-endian data, CRLF header, truncated, trailing bytes, one NaN / inf / negative pixel, no L0
# (full - L0), direct light only (L0 + L1), at most 3 bounces (--bounces 0:3), the wrong size.
# One line per case with grade's verdict. About 40 s on 2 cores (python starts in ~0.8 s here:
# tests/mistakes.py makes all the single-image mistakes of a base in one process). PATHLAB_FAST (the
# sanitizer build): 64x64 only, one seed.
. "$(dirname "$0")/lib.sh"
SIZES="64 128" SEEDS="11 12"
[ "${PATHLAB_FAST:-0}" != 0 ] && SIZES=64 SEEDS=11
M="python3 tests/mistakes.py"
REF64=ref/cornell.pfm REF128=ref/cornell-128.pfm
R="$PATHLAB render scenes/cornell.obj --quiet"

# verdict: grade's verdict line and reasons (or its error) on one line
verdict() {
    { grep -E '^(PASS|FAIL)|^  (brighter|darker|no block|[0-9]+ pixel)' "$TMP/g.out"; head -1 "$TMP/g.err"; } |
        sed 's/^ *//' | paste -sd ';' - | cut -c1-220
}
# grade_case IMAGE REF: grades, leaves the status in $rc
grade_case() { $PATHLAB grade "$1" --ref "$2" > "$TMP/g.out" 2> "$TMP/g.err"; rc=$?; }

# 1. honest images: at most one false alarm in 20
false_alarms=0 honest_n=0
for size in $SIZES; do
    ref=$REF64; [ $size = 128 ] && ref=$REF128
    for spp in 1 4 16 64 256; do
        for seed in $SEEDS; do
            img=$TMP/h_${size}_${spp}_$seed.pfm
            $R --size ${size}x$size --spp $spp --seed $((seed + 1000 * spp + 7 * size)) -o "$img"
            grade_case "$img" "$ref"
            honest_n=$((honest_n + 1))
            if [ "$rc" = 0 ]; then echo "ok   honest ${size}x$size $spp spp seed $seed: [$(verdict)]"
            else false_alarms=$((false_alarms + 1)); echo "note honest ${size}x$size $spp spp seed $seed: exit $rc [$(verdict)]"; fi
        done
    done
done
if [ "$false_alarms" -le 1 ]; then pass "honest images: $false_alarms false alarm(s) of $honest_n (at most 1)"
else fail "honest images: $false_alarms false alarms of $honest_n (at most 1)"; fi

# 2. the mistakes, on each base image (16 and 64 spp, both sizes, both seeds)
mistake() {   # mistake NAME BASE_LABEL IMAGE REF: wants exit 1 or 2
    local name=$1 label=$2 img=$3 ref=$4
    [ -s "$img" ] || { fail "$name ($label): $img was not made"; return; }   # else exit 2 would pass
    grade_case "$img" "$ref"
    if [ "$rc" = 1 ] || [ "$rc" = 2 ]; then pass "$name ($label): exit $rc [$(verdict)]"
    else fail "$name ($label): exit $rc, wanted 1 or 2 [$(verdict)]"; fi
}
for size in $SIZES; do
    ref=$REF64 other=$REF128; [ $size = 128 ] && ref=$REF128 other=$REF64
    for spp in 16 64; do
        for seed in $SEEDS; do
            base=$TMP/h_${size}_${spp}_$seed.pfm label="${size}x$size $spp spp seed $seed"
            m=$TMP/m.pfm
            rm -rf "$TMP/all"; mkdir "$TMP/all"
            $M all "$base" "$TMP/all" $((size / 3)) $((size / 2)) ||   # nan, inf, negative at that pixel
                fail "mistakes.py all $base: exit $?"
            for k in flip-v flip-h rotate-180 grey grey-pf srgb gamma clamp1 quant8 quant8-srgb \
                     big-endian-header crlf truncated trailing; do
                mistake "$k" "$label" "$TMP/all/$k.pfm" "$ref"
            done
            for f in 3.14159265 0.318309886 2 0.5 1.3; do
                mistake "scale $f" "$label" "$TMP/all/scale_$f.pfm" "$ref"
            done
            for k in nan inf negative; do
                mistake "$k pixel" "$label" "$TMP/all/$k.pfm" "$ref"
            done
            # layers from a --bounces 0:3 --split render of the same spp (another seed)
            $R --size ${size}x$size --spp $spp --seed $((seed + 5000 + spp)) --bounces 0:3 --split -o "$TMP/sp.pfm"
            rm -f "$m"; $M sub "$base" "$TMP/sp_L0.pfm" "$m"; mistake "no L0 (full - L0)" "$label" "$m" "$ref"
            rm -f "$m"; $M add "$TMP/sp_L0.pfm" "$TMP/sp_L1.pfm" "$m"; mistake "direct only (L0 + L1)" "$label" "$m" "$ref"
            mistake "at most 3 bounces (--bounces 0:3)" "$label" "$TMP/sp.pfm" "$ref"
            mistake "wrong size" "$label" "$base" "$other"
        done
    done
done
