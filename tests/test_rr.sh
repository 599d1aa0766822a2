#!/usr/bin/env bash
# Russian roulette is unbiased bounce by bounce: renders with and without it (--bounces 0:6 --split,
# with the variance of each bounce's image) agree for every L_k, k = 0..6, and in total.
#  1. Cornell box, default estimators, --rr 1 (roulette from the first bounce on: L2..L6 depend on
#     it) against --rr off;
#  2. the same with the default --rr 3 (L4..L6 depend on it) against the same --rr off render; a
#     path red wall -> green wall -> white reaches the roulette with throughput (0.025, 0.014,
#     0.003) and survives with the clamped probability 0.05;
#  3. the Cornell box with --rr 1 --rr-below 0.2 (p_survive = max(beta) / 0.2) against --rr off;
#  4. glossy Cornell box, light sampling and cosine directions: on the Ns = 1000 floor f cos / pdf
#     reaches 13, so the throughput exceeds 1 and the survival probability is clamped to 1.
# Each comparison is tests/zcheck's (see tests/test_estimators.sh): per-pixel Z-test at alpha 0.01
# with Sidak's correction over the pixels, 99.75% of the pixel-channels must pass; 8x8 blocks and
# the whole image at alpha = 1 - 0.99^(1/n) over the n comparisons of this file.
# L5 and L6 get the block and whole-image tests only (their pixel pass rate is printed): the
# survival probability follows the throughput's largest channel, so the minor channels of coloured
# paths (green light off the red wall) survive rarely, with large weights; at 5 and 6 bounces their
# pixel estimates are skewed enough that the sample variances are unreliable (L6 at 8192 spp: 0 to 4
# failing pixel-channels of 1728 on the Cornell box, 6 on the glossy one, always with the roulette's
# estimate low; 7 to 13 at 4096 spp), while blocks and whole images stay well inside their bounds.
# Pixels are jittered here (the default): both sides of each comparison use the same estimator.
# PATHLAB_FAST=1 (sanitizer builds): comparison 1 only, L0..L4 at 4096 spp.
. "$(dirname "$0")/lib.sh"
ZCHECK=$BUILD/tests/zcheck
FAST=${PATHLAB_FAST:-0}
KBAR=4           # the per-pixel bar applies to L0..L4 and to the total
if [ "$FAST" = 1 ]; then KMAX=4 SPP=4096 ncomp=1; else KMAX=6 SPP=8192 ncomp=4; fi
R="--size 24x24 --bounces 0:$KMAX --split --spp $SPP"
ASUITE=$(awk -v n=$((ncomp * (KMAX + 2))) 'BEGIN { printf "%.3g", 1 - exp(log(0.99) / n) }')

render() {   # OUT SCENE FLAGS...: OUT.pfm, OUT_L0..pfm and their variances OUTv.pfm, OUTv_L0..pfm
    local out=$1 scene=$2; shift 2
    # shellcheck disable=SC2086
    $PATHLAB render "scenes/$scene.obj" $R "$@" -o "$TMP/$out.pfm" --variance "$TMP/${out}v.pfm" 2> "$TMP/err"; local rc=$?
    if [ "$rc" -ne 0 ]; then
        fail "render $scene $*: $(ran "$rc" "$TMP/err" $PATHLAB render "scenes/$scene.obj" $R "$@" -o "$TMP/$out.pfm" --variance "$TMP/${out}v.pfm")"; return 1
    fi
    grep -q ' 0 NaN/Inf samples' "$TMP/err" || fail "render $scene $*: NaN or infinite samples: $(tail -1 "$TMP/err")"
}

# check NAME BAR A VA B VB: per-pixel test at alpha 0.01 (at least BAR of the pixel-channels pass),
# block and whole-image tests at ASUITE
check() {
    local name=$1 bar=$2; shift 2
    local out1 out2 rc1 rc2 frac rest
    out1=$("$ZCHECK" "$@" --alpha 0.01 --block 0 --pixel-pass "$bar" 2>&1); rc1=$?
    out2=$("$ZCHECK" "$@" --alpha "$ASUITE" --block 8 --pixel-pass 0 2>&1); rc2=$?
    if [ $rc1 -eq 2 ] || [ $rc2 -eq 2 ]; then fail "$name: zcheck could not compare: $out1 $out2"; return; fi
    frac=$(echo "$out1" | sed -n 's/.*pixels \([0-9.]*\) pass (|z| < \([0-9.]*\).*/\1 (|z| < \2)/p')
    rest=$(echo "$out2" | sed -n 's/.*; \(blocks [^;]*\); \(image |z| [0-9.]* (crit [0-9.]*)\).*/\1, \2/p')
    if awk -v f="${frac%% *}" -v b="$bar" 'BEGIN { exit !(f >= b) }' && [ $rc2 -eq 0 ]; then
        pass "$name: pixels $frac pass, bar $bar; $rest at alpha $ASUITE"
    else
        fail "$name: pixels $frac pass, bar $bar; $rest at alpha $ASUITE"
    fi
}

compare() {   # LABEL A B: every bounce and the total
    local label=$1 a=$2 b=$3 k bar
    for k in $(seq 0 $KMAX); do
        if [ "$k" -le $KBAR ]; then bar=0.9975; else bar=0; fi
        check "$label: L$k" $bar "$TMP/${a}_L$k.pfm" "$TMP/${a}v_L$k.pfm" "$TMP/${b}_L$k.pfm" "$TMP/${b}v_L$k.pfm"
    done
    check "$label: L0..L$KMAX" 0.9975 "$TMP/$a.pfm" "$TMP/${a}v.pfm" "$TMP/$b.pfm" "$TMP/${b}v.pfm"
}

render off cornell --seed 11 --rr off &&
render rr1 cornell --seed 12 --rr 1 &&
compare "Cornell box, default estimators, --rr 1 against --rr off, $SPP spp" rr1 off
if [ "$FAST" = 0 ]; then
    render rr3 cornell --seed 13 --rr 3 &&
    compare "Cornell box, default estimators, --rr 3 against --rr off, $SPP spp" rr3 off
    # --rr-below 0.2: p_survive = 5 max(beta), so a survivor's throughput is up to 0.2, not 1
    render rrb cornell --seed 16 --rr 1 --rr-below 0.2 &&
    compare "Cornell box, default estimators, --rr 1 --rr-below 0.2 against --rr off, $SPP spp" rrb off
    G="--direct light --light solid-angle --dir cosine"
    # shellcheck disable=SC2086
    render goff cornell-glossy $G --seed 14 --rr off &&
    render grr1 cornell-glossy $G --seed 15 --rr 1 &&
    compare "glossy box, $G, --rr 1 against --rr off, $SPP spp" grr1 goff
fi
exit 0
