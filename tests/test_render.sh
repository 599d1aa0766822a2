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

# 2. L0 + L1 against the reference (ref/MANIFEST.md says how it was made), per-pixel, per-block and
# whole-image Z-tests at alpha = 0.01 with Sidak's correction (tests/zcheck.c)
L01="--bounces 0:1 --direct light --light area --size 128x128 --spp 64 --seed 7"
$PATHLAB render scenes/cornell.obj --quiet $L01 -o "$TMP/l01.pfm" --variance "$TMP/l01_var.pfm"
if msg=$($ZCHECK "$TMP/l01.pfm" "$TMP/l01_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm); then
    pass "L0+L1 Cornell box matches ref/ within noise ($msg)"
else fail "L0+L1 Cornell box differs from ref/: $msg"; fi
# idiff, a check independent of our own statistics: no pixel off by more than a loose bound
if idiff -fail 0.5 -failpercent 1 -warn 0.2 -warnpercent 5 "$TMP/l01.pfm" ref/cornell_L01.pfm > "$TMP/idiff" 2>&1; then
    pass "L0+L1 against ref/ with idiff ($(grep -E 'Mean error' "$TMP/idiff" | head -1 | xargs))"
else
    rc=$?; [ $rc -eq 1 ] && pass "L0+L1 against ref/ with idiff (warnings only)" || fail "idiff: $(tail -3 "$TMP/idiff")"
fi

# the same check must reject bias: 2% too bright, and L2 added
oiiotool "$TMP/l01.pfm" --mulc 1.02 -o "$TMP/bright.pfm" 2>/dev/null
if msg=$($ZCHECK "$TMP/bright.pfm" "$TMP/l01_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm); then
    fail "an image 2% too bright passes the regression check: $msg"
else pass "an image 2% too bright fails the regression check"; fi
$PATHLAB render scenes/cornell.obj --quiet ${L01/0:1/0:2} -o "$TMP/l02.pfm" --variance "$TMP/l02_var.pfm"
if msg=$($ZCHECK "$TMP/l02.pfm" "$TMP/l02_var.pfm" ref/cornell_L01.pfm ref/cornell_L01_var.pfm); then
    fail "L0..L2 passes as L0+L1: $msg"
else pass "L0..L2 is told apart from L0+L1"; fi

# 3. --split: the bounce images sum to the image without --split (same seed), up to float rounding
$R --spp 4 --bounces 0:3 -o "$TMP/full.pfm"
$R --spp 4 --bounces 0:3 --split -o "$TMP/sp.pfm"
oiiotool "$TMP/sp_L0.pfm" "$TMP/sp_L1.pfm" --add "$TMP/sp_L2.pfm" --add "$TMP/sp_L3.pfm" --add -o "$TMP/sum.pfm" 2>/dev/null
if cmp -s "$TMP/full.pfm" "$TMP/sp.pfm" && idiff -fail 1e-5 -failrelative 1e-5 -warn 1e-5 -warnrelative 1e-5 "$TMP/sum.pfm" "$TMP/full.pfm" > /dev/null 2>&1; then
    pass "--split: L0+L1+L2+L3 images sum to the full image, which is unchanged by --split"
else fail "--split images do not sum to the full image"; fi
exit 0
