#!/usr/bin/env bash
# A student's malformed PFM is an input error (exit 2) that names the file and the cause, for
# pathlab convert, pathlab diff and (once it has --report) pathlab grade: each bad file is written
# with python3 from ref/cornell.pfm (little-endian, 64 x 64, header "PF\n64 64\n-1.0\n").
. "$(dirname "$0")/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then pass "pfm input errors (skipped: no python3)"; exit 0; fi
REF=ref/cornell.pfm
python3 - "$REF" "$TMP" <<'PY'
import struct, sys
ref, tmp = sys.argv[1], sys.argv[2]
d = open(ref, 'rb').read()
hdr = b'PF\n64 64\n-1.0\n'
assert d.startswith(hdr) and len(d) == len(hdr) + 64 * 64 * 12
data = d[len(hdr):]
n = len(data) // 4
v = list(struct.unpack('<%df' % n, data))
def out(name, b): open('%s/%s.pfm' % (tmp, name), 'wb').write(b)
def le(vals): return struct.pack('<%df' % len(vals), *vals)
out('byteorder', b'PF\n64 64\n1.0\n' + data)                    # little-endian data, positive scale
out('byteorder-be', b'PF\n64 64\n-1.0\n' + struct.pack('>%df' % n, *v))  # big-endian data, negative scale
out('crlf', b'PF\r\n64 64\r\n-1.0\r\n' + data)
out('blank', b'PF\n\n64 64\n-1.0\n' + data)
out('comment', b'PF\n# my renderer\n64 64\n-1.0\n' + data)
out('nolf', b'PF\n64 64\n-1.0' + data)                          # the data starts with a 0 byte
out('truncated', d[:-1000])
out('trailing', d + d)                                          # the image written twice
# NaN at x 12, y 0 (file row 63: the top row is stored last) and a negative value at x 5, y 10
w = list(v); w[3 * (63 * 64 + 12)] = float('nan'); w[3 * ((63 - 10) * 64 + 5) + 1] = -0.5
nan = list(v); nan[3 * (63 * 64 + 12)] = float('nan')
neg = list(v); neg[3 * ((63 - 10) * 64 + 5) + 1] = -0.5
out('nan', hdr + le(nan))
out('negative', hdr + le(neg))
out('grey', b'Pf\n64 64\n-1.0\n' + le([v[3 * i + 1] for i in range(n // 3)]))
PY
[ -f "$TMP/grey.pfm" ] || { fail "pfm input errors: python3 could not write the bad files"; exit 0; }

# check KIND PATTERN LABEL COMMAND...: COMMAND exits 2, its stderr names the bad file and matches PATTERN
check() {
    local kind=$1 pat=$2 label=$3; shift 3
    expect_status "$label $kind: exit 2" 2 "$@"
    expect_err "$label $kind: the cause" "$pat"
    expect_err "$label $kind: the file named" "$kind\.pfm"
}
BYTEORDER="scale \+1\.0 says big-endian, but read so the values are absurd .*read little-endian they are ordinary \(0 to 2[0-9.]*\): write the scale as -1\.0"
BYTEORDER_BE="scale -1\.0 says little-endian, but read so the values are absurd .*write the scale as 1\.0 for big-endian"
CRLF="lines end with CR LF .*open the file in binary mode"
BLANK="the header has a blank line"
COMMENT="the header has a comment"
NOLF="no line feed after the scale '-1\.0'"
TRUNC="truncated: expected 64 x 64 x 3 x 4 = 49152 bytes of pixels .*found 48152: 1000 bytes missing \(83\.33 pixels\)"
TRAIL="49166 bytes after the pixel data: expected exactly 64 x 64 x 3 x 4 = 49152 bytes .*a second image or a header written twice"
NAN="1 pixel-channel is NaN, at x 12, y 0 \(red\); y = 0 is the top row"
NEG="1 pixel-channel is negative .*at x 5, y 10 \(green -0\.5\)"
GREY="greyscale .*1 channel.* but .*colour"

for c in "byteorder:$BYTEORDER" "byteorder-be:$BYTEORDER_BE" "crlf:$CRLF" "blank:$BLANK" "comment:$COMMENT" \
         "nolf:$NOLF" "truncated:$TRUNC" "trailing:$TRAIL"; do
    kind=${c%%:*}; pat=${c#*:}
    check "$kind" "$pat" convert $PATHLAB convert "$TMP/$kind.pfm" "$TMP/out.png"
    check "$kind" "$pat" diff $PATHLAB diff "$TMP/$kind.pfm" "$REF"
done
expect_no_file "convert: no image written from a bad file" "$TMP/out.png"
# radiance and channels: convert still shows such a file, diff refuses it
for c in "nan:$NAN" "negative:$NEG" "grey:$GREY"; do
    kind=${c%%:*}; pat=${c#*:}
    check "$kind" "$pat" diff $PATHLAB diff "$TMP/$kind.pfm" "$REF"
done
expect_status "convert nan: still converts (NaN shown black)" 0 $PATHLAB convert "$TMP/nan.pfm" "$TMP/nan.png"
# the good files still read: the reference and pathlab's own writing
expect_status "diff: the reference against itself" 0 $PATHLAB diff "$REF" "$REF"
$PATHLAB convert "$REF" "$TMP/copy.pfm" 2> "$TMP/err"
expect_status "convert: pathlab's own PFM reads back" 0 $PATHLAB diff "$TMP/copy.pfm" "$REF"

# pathlab grade: the same input errors, exit 2, never a bias percentage
for c in "byteorder:$BYTEORDER" "byteorder-be:$BYTEORDER_BE" "crlf:$CRLF" "blank:$BLANK" "comment:$COMMENT" \
             "nolf:$NOLF" "truncated:$TRUNC" "trailing:$TRAIL" "nan:$NAN" "negative:$NEG" "grey:greyscale"; do
    kind=${c%%:*}; pat=${c#*:}
    check "$kind" "$pat" grade $PATHLAB grade "$TMP/$kind.pfm" --ref "$REF"
done
# ... and in a class, the readable images are graded and the report names the unreadable ones
$PATHLAB grade "$REF" "$TMP/nan.pfm" "$TMP/crlf.pfm" --ref "$REF" --report "$TMP/class.csv" > "$TMP/out" 2> "$TMP/err"; rc=$?
if [ $rc -eq 2 ] && grep -q '^"[^"]*nan.pfm",UNREADABLE' "$TMP/class.csv" && grep -q '^"[^"]*crlf.pfm",UNREADABLE' "$TMP/class.csv" \
   && grep -q "^summary: 3 images, 1 pass, 0 fail, 2 could not be read" "$TMP/out"; then pass "grade: a class with two unreadable images: exit 2, each named in the report"
else fail "grade: a class with two unreadable images: exit $rc, $(cat "$TMP/out" "$TMP/class.csv" | head -c 400)"; fi
exit 0
