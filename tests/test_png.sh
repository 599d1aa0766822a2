#!/usr/bin/env bash
# PNG output: the pixels are the PPM's bytes; the file is valid PNG for two independent decoders,
# OpenImageIO (libpng) and Python's zlib (every chunk CRC, the zlib stream and its Adler-32);
# images of several stored deflate blocks, and one that fills its last block exactly.
. "$(dirname "$0")/lib.sh"
R="$PATHLAB render scenes/cornell.obj --quiet --spp 2"

# pngcheck FILE PPM: parses FILE with Python, checks it and compares its pixels with PPM's bytes.
# Prints "ok <IDAT chunks> <stored blocks>" or the first problem.
pngcheck() {
    python3 - "$1" "$2" 2>&1 <<'EOF'
import struct, sys, zlib
png, ppm = open(sys.argv[1], 'rb').read(), open(sys.argv[2], 'rb').read()
def bad(msg): print(msg); sys.exit(1)
if png[:8] != b'\x89PNG\r\n\x1a\n': bad('no PNG signature')
pos, chunks = 8, []
while pos < len(png):
    n, kind = struct.unpack('>I4s', png[pos:pos + 8])
    data, crc = png[pos + 8:pos + 8 + n], struct.unpack('>I', png[pos + 8 + n:pos + 12 + n])[0]
    if zlib.crc32(kind + data) != crc: bad('bad CRC in a %s chunk' % kind.decode())
    chunks.append((kind, data)); pos += 12 + n
kinds = [k for k, _ in chunks]
if kinds[0] != b'IHDR' or kinds[-1] != b'IEND' or b'IDAT' not in kinds: bad('chunks out of order: %s' % kinds)
w, h, depth, ctype, comp, filt, lace = struct.unpack('>IIBBBBB', chunks[0][1])
if (depth, ctype, comp, filt, lace) != (8, 2, 0, 0, 0): bad('IHDR is not 8-bit RGB')
stream = b''.join(d for k, d in chunks if k == b'IDAT')
try: raw = zlib.decompress(stream)       # checks the zlib header, the blocks and the Adler-32
except zlib.error as e: bad('zlib: %s' % e)
stride = 3 * w + 1
if len(raw) != h * stride: bad('%d raw bytes, expected %d' % (len(raw), h * stride))
if any(raw[y * stride] != 0 for y in range(h)): bad('a row filter is not 0')
pixels = b''.join(raw[y * stride + 1:(y + 1) * stride] for y in range(h))
header = b'P6\n%d %d\n255\n' % (w, h)
if not ppm.startswith(header) or ppm[len(header):] != pixels: bad('pixels differ from the PPM')
blocks = (len(raw) + 65534) // 65535
print('ok %d IDAT, %d stored blocks' % (kinds.count(b'IDAT'), blocks))
EOF
}

# 1. the same render as PPM and PNG: the same pixels, for Python and for OpenImageIO
$R --size 64x48 -o "$TMP/a.ppm"
$R --size 64x48 -o "$TMP/a.png"
msg=$(pngcheck "$TMP/a.png" "$TMP/a.ppm")
if [ $? -eq 0 ]; then pass "64x48 PNG: CRCs, zlib stream, Adler-32 and pixels = PPM ($msg)"; else fail "64x48 PNG: $msg"; fi
if ! have_oiio; then skip "OpenImageIO reads the PNG with the PPM's pixel values (needs oiiotool)"
elif oiiotool --dumpdata "$TMP/a.png" | tail -n +2 > "$TMP/png.txt" && oiiotool --dumpdata "$TMP/a.ppm" | tail -n +2 > "$TMP/ppm.txt" \
   && [ -s "$TMP/png.txt" ] && cmp -s "$TMP/png.txt" "$TMP/ppm.txt"; then pass "OpenImageIO reads the PNG with the PPM's pixel values"
else fail "OpenImageIO: PNG and PPM pixel dumps differ or do not read"; fi

# 2. large images: 200 x 150 is 90 150 raw bytes (2 stored blocks, the last one partial);
# 171 x 255 rows of 514 bytes are exactly 2 x 65535 bytes (the last block full, no empty block)
for size in 200x150 171x255; do
    $R --spp 1 --size $size --exposure 1 -o "$TMP/big.ppm"
    $R --spp 1 --size $size --exposure 1 -o "$TMP/big.png"
    msg=$(pngcheck "$TMP/big.png" "$TMP/big.ppm")
    if [ $? -eq 0 ]; then pass "$size PNG with --exposure 1 ($msg)"; else fail "$size PNG: $msg"; fi
    if ! have_oiio; then skip "$size: idiff finds PNG = PPM (needs idiff)"
    elif idiff "$TMP/big.png" "$TMP/big.ppm" > "$TMP/idiff" 2>&1; then pass "$size: idiff finds PNG = PPM"
    else fail "$size: idiff: $(tail -3 "$TMP/idiff" | xargs)"; fi
done

# 3. a 1 x 1 image, an upper-case extension, --split images as PNG
$R --size 1x1 -o "$TMP/one.PNG" && $R --size 1x1 -o "$TMP/one.ppm"
msg=$(pngcheck "$TMP/one.PNG" "$TMP/one.ppm")
if [ $? -eq 0 ]; then pass "1x1 image, extension .PNG ($msg)"; else fail "1x1 .PNG: $msg"; fi
$R --size 16x16 --bounces 0:1 --split -o "$TMP/s.png"
if [ -s "$TMP/s_L0.png" ] && [ -s "$TMP/s_L1.png" ] && { ! have_oiio || oiiotool --info "$TMP/s_L1.png" > /dev/null 2>&1; }; then pass "--split writes s_L0.png, s_L1.png"
else fail "--split with .png"; fi

# 4. pathlab diff --heatmap out.png
$PFMTOOL const 8 4 1.5 1.5 1.5 "$TMP/c1.pfm"
$PFMTOOL const 8 4 1 1 1 "$TMP/c2.pfm"
if ! have_oiio; then skip "diff --heatmap heat.png is an 8x4 PNG (needs oiiotool)"
elif $PATHLAB diff "$TMP/c1.pfm" "$TMP/c2.pfm" --heatmap "$TMP/heat.png" > /dev/null && oiiotool --info "$TMP/heat.png" 2>&1 | grep -q '8 x *4, 3 channel, uint8 png'
then pass "diff --heatmap heat.png is an 8x4 PNG"; else fail "diff --heatmap heat.png: $(oiiotool --info "$TMP/heat.png" 2>&1)"; fi

# 5. errors: no folder, no file left behind; the message lists the formats
expect_status "PNG into a missing folder: status 2 (checked before rendering)" 2 $R --size 8x8 -o "$TMP/none/x.png"
expect_no_file "PNG into a missing folder: nothing written" "$TMP/none/x.png"
expect_status "unknown extension: status 2" 2 $R --size 8x8 -o "$TMP/x.jpg"
expect_err "unknown extension: the message lists .png" "\.pfm, \.ppm or \.png"
exit 0
