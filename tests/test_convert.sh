#!/usr/bin/env bash
# pathlab convert IN.pfm OUT: the figures it prints are the image's (exact on constant images), a
# PFM round trip keeps every byte, the PNG/PPM exposure scales the 8-bit values, bad input exits 2
# and writes nothing.
. "$(dirname "$0")/lib.sh"
$PFMTOOL const 8 4 0.25 0.5 2 "$TMP/c.pfm"
expect_status "convert: constant image, exit 0" 0 $PATHLAB convert "$TMP/c.pfm" "$TMP/c.png"
if grep -q "8 x 4" "$TMP/out" && grep -qE "red +mean 0.25  min 0.25  max 0.25" "$TMP/out" \
   && grep -qE "blue +mean 2  min 2  max 2" "$TMP/out"; then pass "convert: size, mean, min and max of a constant image"
else fail "convert: printed $(tr '\n' '|' < "$TMP/out")"; fi
$PATHLAB convert "$TMP/c.pfm" "$TMP/c2.pfm" > /dev/null
if cmp -s "$TMP/c.pfm" "$TMP/c2.pfm"; then pass "convert: PFM to PFM keeps every byte"
else fail "convert: PFM to PFM changed the file"; fi
# PPM: 0.25 with exposure +1 is 0.5, sRGB 0.5 -> 188; without, 0.25 -> 137 (the sRGB curve)
$PATHLAB convert "$TMP/c.pfm" "$TMP/e0.ppm" > /dev/null
$PATHLAB convert "$TMP/c.pfm" "$TMP/e1.ppm" --exposure 1 > /dev/null
r0=$(tail -c 96 "$TMP/e0.ppm" | od -An -tu1 -N1 | tr -d ' ')
r1=$(tail -c 96 "$TMP/e1.ppm" | od -An -tu1 -N1 | tr -d ' ')
if [ "$r0" = 137 ] && [ "$r1" = 188 ]; then pass "convert: exposure then sRGB (0.25 -> $r0, x2 -> $r1)"
else fail "convert: red bytes $r0 and $r1, expected 137 and 188"; fi
# flags and file names in any order: the same bytes
$PATHLAB convert --exposure 1 "$TMP/c.pfm" "$TMP/e1a.ppm" > /dev/null
$PATHLAB convert "$TMP/c.pfm" --exposure 1 "$TMP/e1b.ppm" > /dev/null
if cmp -s "$TMP/e1.ppm" "$TMP/e1a.ppm" && cmp -s "$TMP/e1.ppm" "$TMP/e1b.ppm"; then pass "convert: --exposure first, between or last: the same image"
else fail "convert: --exposure before or between the file names changed the image"; fi
expect_status "convert: negative exposure, exit 0" 0 $PATHLAB convert "$TMP/c.pfm" "$TMP/em.png" --exposure -2.5
expect_status "convert: exposure out of range, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.png" --exposure 200
expect_err "convert: exposure out of range, flag and value named" "^pathlab convert: --exposure expects .*got '200'"
expect_status "convert: one output only, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.png" "$TMP/n2.png"
expect_err "convert: the extra word named" "^pathlab convert: unexpected '.*n2.png'"
expect_status "convert: no output, exit 2" 2 $PATHLAB convert "$TMP/c.pfm"
expect_status "convert: unknown flag, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.png" --gamma 2
expect_err "convert: unknown flag named" "^pathlab convert: unknown flag '--gamma'"
expect_status "convert: --exposure without a value, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.png" --exposure
expect_no_file "convert: bad arguments write nothing" "$TMP/n.png" "$TMP/n2.png"
expect_status "convert: missing input, exit 2" 2 $PATHLAB convert "$TMP/none.pfm" "$TMP/n.png"
expect_err "convert: missing input named" "none.pfm"
expect_no_file "convert: missing input writes nothing" "$TMP/n.png"
expect_status "convert: unknown output format, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.jpg"
expect_err "convert: unknown output format explained" "n.jpg: unknown image format \\(use .pfm, .ppm or .png\\)"
expect_no_file "convert: unknown format writes nothing" "$TMP/n.jpg"
expect_status "convert: bad exposure, exit 2" 2 $PATHLAB convert "$TMP/c.pfm" "$TMP/n.png" --exposure abc
expect_err "convert: bad exposure, flag and value named" "--exposure expects .*got 'abc'"
expect_no_file "convert: bad exposure writes nothing" "$TMP/n.png"
printf 'PF\n8 4\n-1\nshort' > "$TMP/bad.pfm"
expect_status "convert: truncated PFM, exit 2" 2 $PATHLAB convert "$TMP/bad.pfm" "$TMP/n.png"
expect_no_file "convert: truncated PFM writes nothing" "$TMP/n.png"
exit 0
