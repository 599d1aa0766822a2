#!/usr/bin/env bash
# pathlab diff: metrics with exact answers on constant images, a heatmap, and errors (a reference
# holding a NaN or a negative value among them).
. "$(dirname "$0")/lib.sh"
$PFMTOOL const 8 4 1.5 1.5 1.5 "$TMP/a.pfm"
$PFMTOOL const 8 4 1 1 1 "$TMP/b.pfm"
$PFMTOOL const 4 4 1 1 1 "$TMP/small.pfm"
out=$($PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --heatmap "$TMP/h.ppm")
metric() { echo "$out" | awk -v k="$1" '$1 == k { print $2 }'; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { exit !(a - b <= t && b - a <= t) }'; }
# a = 1.5, ref = 1: d = 0.5 everywhere; relMSE = 0.25 / (1 + 0.01); PSNR = 10 log10(1 / 0.25)
for kvt in "RMSE 0.5 1e-6" "MAE 0.5 1e-6" "max 0.5 1e-6" "relMSE 0.247525 1e-6" "PSNR 6.0206 0.005"; do
    set -- $kvt
    if near "$(metric "$1")" "$2" "$3"; then pass "diff: $1 = $2"; else fail "diff: $1 is '$(metric "$1")', expected $2"; fi
done
if echo "$out" | grep -q '^mean *+0.5 +- 0 '; then pass "diff: mean signed difference +0.5, standard error 0"; else fail "diff: mean line: $(echo "$out" | grep mean)"; fi
if [ "$(head -c 2 "$TMP/h.ppm")" = "P6" ]; then pass "diff: heatmap written"; else fail "diff: no heatmap"; fi
expect_status "diff: sizes differ, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/small.pfm"
expect_err "diff: sizes named" "8x4.*4x4"
expect_status "diff: missing file, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/none.pfm"
expect_err "diff: missing file named" "none.pfm"
expect_status "diff: one image only, status 2" 2 $PATHLAB diff "$TMP/a.pfm"
for v in nan -1; do   # the reference is checked as the image is: a NaN one gave "RMSE nan, PSNR inf dB", exit 0
    $PFMTOOL const 8 4 1 "$v" 1 "$TMP/bad.pfm"
    expect_status "diff: a reference holding $v, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/bad.pfm"
    expect_err "diff: the reference's bad values named" "bad.pfm: 32 pixel-channels are (NaN|negative)"
done
expect_status "diff: three images, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" "$TMP/small.pfm"
expect_err "diff: the extra image named" "^pathlab diff: 3 images and no --ref: which one is the reference"
# flags before the file names: the same heatmap
$PATHLAB diff --heatmap "$TMP/h2.ppm" --scale 0 "$TMP/a.pfm" "$TMP/b.pfm" > /dev/null
if cmp -s "$TMP/h.ppm" "$TMP/h2.ppm"; then pass "diff: flags first, the same heatmap"; else fail "diff: flags first changed the heatmap"; fi
expect_status "diff: heatmap of an unknown format, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --heatmap "$TMP/h.jpg"
expect_err "diff: heatmap format explained" "^pathlab diff: --heatmap .*h.jpg: a heatmap is a picture: use .png or .ppm"
# a heatmap is a picture: a .pfm (without a sidecar, every other PFM has one) would pass for a render
expect_status "diff: a .pfm heatmap refused, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --heatmap "$TMP/h.pfm"
expect_err "diff: a .pfm heatmap: use .png or .ppm" "^pathlab diff: --heatmap .*h.pfm: a heatmap is a picture: use .png or .ppm"
expect_no_file "diff: no .pfm heatmap written" "$TMP/h.pfm"
expect_no_file "diff: no heatmap of an unknown format" "$TMP/h.jpg"
if [ ! -s "$TMP/out" ]; then pass "diff: bad arguments, no metrics printed"; else fail "diff: printed metrics before refusing the heatmap"; fi
expect_status "diff: --scale -1 refused (it was taken for 0), status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --scale -1
expect_err "diff: --scale -1 named" "^pathlab diff: --scale expects a number >= 0"
expect_status "diff: bad --scale, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --scale big
expect_err "diff: bad --scale named" "^pathlab diff: --scale expects a number, got 'big'"
expect_status "diff: unknown flag, status 2" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --colour
expect_err "diff: unknown flag named" "unknown flag '--colour'"
# (a review, 2026-12-08) the standard error of a greyscale image counted each value three times
# (sqrt 3 too small): a = [1, 3], ref = [0, 0] gives mean 2, sd sqrt 2 over 2 pixels, standard error 1
printf 'Pf\n2 1\n-1\n\x00\x00\x80\x3f\x00\x00\x40\x40' > "$TMP/ga.pfm"; printf 'Pf\n2 1\n-1\n\x00\x00\x00\x00\x00\x00\x00\x00' > "$TMP/gz.pfm"
out=$($PATHLAB diff "$TMP/ga.pfm" "$TMP/gz.pfm" 2> /dev/null)
if echo "$out" | grep -q '^mean *+2 +- 1 '; then pass "diff: a greyscale image's standard error over its pixels (1)"; else fail "diff: greyscale: $(echo "$out" | grep mean)"; fi
# a black reference: no PSNR (it printed inf dB, a perfect match's)
out=$($PATHLAB diff "$TMP/ga.pfm" "$TMP/gz.pfm" 2> /dev/null)
if echo "$out" | grep -q '^PSNR *n/a'; then pass "diff: a black reference: PSNR n/a"; else fail "diff: black reference: $(echo "$out" | grep PSNR)"; fi
# the default heatmap is white at the largest of what it shows (a one-channel difference of 1 was a third of the ramp)
$PFMTOOL const 1 1 1 0 0 "$TMP/r1.pfm"; $PFMTOOL const 1 1 0 0 0 "$TMP/k1.pfm"
$PATHLAB diff "$TMP/r1.pfm" "$TMP/k1.pfm" --heatmap "$TMP/h1.ppm" > /dev/null 2> "$TMP/err"
if [ "$(tail -c 3 "$TMP/h1.ppm" | od -An -tu1 | tr -s ' ')" = " 255 255 255" ]; then pass "diff: the default heatmap's largest difference is white"
else fail "diff: the default heatmap's pixel: $(tail -c 3 "$TMP/h1.ppm" | od -An -tu1)"; fi
expect_err "diff: the heatmap's scale said" "black 0 to white 0.3333"
expect_status "diff: --scale without --heatmap refused" 2 $PATHLAB diff "$TMP/a.pfm" "$TMP/b.pfm" --scale 2
exit 0
