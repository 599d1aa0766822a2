#!/usr/bin/env bash
# Renders: reproducible whatever the thread count; the L0+L1 Cornell box agrees with ref/ up to its
# noise, and the same check rejects a biased image; --split images sum to the full image.
. "$(dirname "$0")/lib.sh"
ZCHECK=$BUILD/tests/zcheck
R="$PATHLAB render scenes/cornell.obj --quiet --size 64x64"

# 1. one thread or two: the same bytes (pixels own their random streams)
$R --spp 8 --threads 1 -o "$TMP/t1.pfm" --variance "$TMP/v1.pfm"
$R --spp 8 --threads 2 -o "$TMP/t2.pfm" --variance "$TMP/v2.pfm"
if cmp -s "$TMP/t1.pfm" "$TMP/t2.pfm" && cmp -s "$TMP/v1.pfm" "$TMP/v2.pfm"; then pass "1 thread and 2 threads: identical image and variance"
else fail "1 thread and 2 threads give different files"; fi
$R --spp 8 --threads 2 --seed 2 -o "$TMP/s2.pfm"
if ! cmp -s "$TMP/t1.pfm" "$TMP/s2.pfm"; then pass "another seed gives another image"; else fail "--seed has no effect"; fi

# 2. L0 + L1 against the reference (ref/MANIFEST.md says how it was made: 8192 spp), per-pixel,
# per-block and whole-image Z-tests at alpha = 0.01 with Sidak's correction (tests/zcheck.c).
# The variance of the 64-spp test render is predicted from the reference's (same estimator, 128
# times the samples: var = ref_var x 8192/64): its own estimate from 64 samples is unreliable where
# few samples see the light (zero variance on the light's edge although the pixel is noisy).
# --sampler independent: the predicted variance (ref_var x 128) is that of independent samples
L01="--bounces 0:1 --direct light --light area --size 128x128 --spp 64 --seed 7 --sampler independent"
$PATHLAB render scenes/cornell.obj --quiet $L01 -o "$TMP/l01.pfm"
$PFMTOOL scale ref/cornell_L01_var.pfm 128 "$TMP/pred_var.pfm"
zcheck_expect "L0+L1 Cornell box matches ref/ within noise" 0 "$TMP/l01.pfm" "$TMP/pred_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm
# idiff, a check independent of our statistics: fewer than 1% of pixels off by more than 0.5
if have_oiio; then idiff -fail 0.5 -failpercent 1 -warn 0.5 -warnpercent 1 "$TMP/l01.pfm" ref/cornell_L01.pfm > "$TMP/idiff" 2>&1; rc=$?; fi
if ! have_oiio; then skip "L0+L1 against ref/ with idiff (needs OpenImageIO's idiff)"
elif [ $rc -eq 0 ]; then pass "L0+L1 against ref/ with idiff ($(grep -E 'Mean error' "$TMP/idiff" | xargs))"
else fail "L0+L1 against ref/ with idiff (status $rc): $(tail -4 "$TMP/idiff" | xargs)"; fi

# the same check must reject bias: an image 2% too bright, and one with L2 added
$PFMTOOL scale "$TMP/l01.pfm" 1.02 "$TMP/bright.pfm"
zcheck_expect "an image 2% too bright fails the regression check" 1 "$TMP/bright.pfm" "$TMP/pred_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm
$PATHLAB render scenes/cornell.obj --quiet ${L01/0:1/0:2} -o "$TMP/l02.pfm"
zcheck_expect "L0..L2 is told apart from L0+L1" 1 "$TMP/l02.pfm" "$TMP/pred_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm

# 3. --split: the bounce images sum to the total up to float rounding, and the total is the
# image rendered without --split, bit for bit (same seed)
$R --spp 4 --bounces 0:3 -o "$TMP/full.pfm"
$R --spp 4 --bounces 0:3 --split -o "$TMP/sp.pfm"
$PFMTOOL sum "$TMP/sum.pfm" "$TMP/sp_L0.pfm" "$TMP/sp_L1.pfm" "$TMP/sp_L2.pfm" "$TMP/sp_L3.pfm"
if cmp -s "$TMP/full.pfm" "$TMP/sp.pfm"; then pass "--split leaves the total image unchanged"; else fail "--split changes the total image"; fi
if ! have_oiio; then skip "--split images sum to the total (needs OpenImageIO's idiff)"
elif idiff -fail 1e-5 -failrelative 1e-5 -warn 1e-5 -warnrelative 1e-5 "$TMP/sum.pfm" "$TMP/full.pfm" > "$TMP/idiff" 2>&1; then
    pass "--split: L0+L1+L2+L3 images sum to the total"
else fail "--split images do not sum to the total: $(tail -3 "$TMP/idiff" | xargs)"; fi
exit 0
