#!/usr/bin/env bash
# Materials, shading normals, textures and --mtl, as gKit reads them (docs/gkit.md), on small scenes
# written by tests/materials/gen.py:
#  - --material diffuse ignores Ks: on McGuire's glossy box it gives, bit for bit, the image of the
#    same box whose MTL has no Ks lines (given by --mtl); the Kd + Ks > 1 warning comes once under
#    blinn, never under diffuse; the sidecar records the flag;
#  - shading normals: the sphere furnace with every vn equal to its face's normal still gives 1
#    (zcheck, 24x24 x 1024 spp, alpha 0.01, precision 1e-3); a 12 x 8 UV sphere with smooth vn has
#    vertical jumps of luminance less than half the faceted one's (L1, 32x32 x 256 spp); --normals
#    geometric on it gives the faceted sphere's image bit for bit; a quad whose vn are all tilted 30
#    degrees under a small lamp at +-45 degrees: L1 = Kd/pi E cos(theta - alpha) to 0.5% (1x1 x 4096 spp);
#  - textures: map_Ke seen directly (L0, pixel centres) is the texel gKit picks, v up (nearest), and
#    the bilinear mix of the four around; map_Kd of a constant 0.5 texture with Kd 1 gives the image of
#    Kd 0.5 bit for bit; a texture named twice is read once; a map_Kd outside the scene's folder, a
#    link out of it, a FIFO, a texture holding a NaN or a negative value are refused (exit 2, file:line);
#  - --mtl FILE replaces the mtllib, its textures relative to FILE's folder; recorded in the sidecar;
#  - --texture-decode: an 8-bit texel 128 is 128/255 raw, 0.2159 srgb; a PFM texture is linear either
#    way; a texture cut short is refused at its MTL line.
. "$(dirname "$0")/lib.sh"
S=$TMP/s
python3 tests/materials/gen.py "$S" || fail "tests/materials/gen.py failed"
PX="python3 tests/materials/px.py"
CAM="--eye 0,0,3 --target 0,0,0 --fov 36.8699 --size 4x4 --pixel-center --spp 1 --quiet"

# --material
G=../shared/data/cornell-mcguire
[ -d "$G" ] || G=$(dirname "$0")/../../shared/data/cornell-mcguire
if [ -f "$G/CornellBox-Glossy.obj" ]; then   # McGuire's box of ../shared/data (beside the clone)
    $PATHLAB render $G/CornellBox-Glossy.obj --size 16x16 --spp 4 -o "$TMP/blinn.pfm" 2> "$TMP/err"
    n=$(grep -c "creates energy" "$TMP/err")
    if [ "$n" = 1 ] && grep -q "and 1 other material" "$TMP/err"; then pass "blinn: the Kd + Ks > 1 warning once, naming the first and counting the other"
    else fail "blinn: $n warnings: $(head -c 400 "$TMP/err")"; fi
    $PATHLAB render $G/CornellBox-Glossy.obj --size 16x16 --spp 4 --material diffuse -o "$TMP/diffuse.pfm" 2> "$TMP/err"
    if ! grep -q "creates energy" "$TMP/err" && grep -q -- "--material diffuse" "$TMP/diffuse.pfm.meta"; then pass "diffuse: no energy warning; the sidecar says --material diffuse"
    else fail "diffuse: $(grep energy "$TMP/err") / $(grep flags "$TMP/diffuse.pfm.meta")"; fi
    grep -v "^ *Ks" $G/CornellBox-Glossy.mtl > "$TMP/noks.mtl"
    $PATHLAB render $G/CornellBox-Glossy.obj --size 16x16 --spp 4 --mtl "$TMP/noks.mtl" -o "$TMP/noks.pfm" --quiet
    if cmp -s "$TMP/diffuse.pfm" "$TMP/noks.pfm" && ! cmp -s "$TMP/diffuse.pfm" "$TMP/blinn.pfm"; then pass "--material diffuse = the MTL without Ks (--mtl), bit for bit; blinn differs"
    else fail "--material diffuse differs from the MTL without Ks, or equals blinn"; fi
    grep -q -- "--mtl $TMP/noks.mtl" "$TMP/noks.pfm.meta" && pass "--mtl FILE in the sidecar's flags" || fail "--mtl not in the sidecar: $(grep flags "$TMP/noks.pfm.meta")"
    expect_status "--material phong: refused" 2 $PATHLAB render $G/CornellBox-Glossy.obj --material phong -o "$TMP/x.pfm"
    expect_err "--material phong: the choices named" "blinn.*diffuse"
else skip "--material on McGuire's glossy box: no $G (../shared/data beside the project)"; fi

# shading normals
$PATHLAB render "$S/flatvn-furnace.obj" --eye 0,0,0 --target 0,0,1 --fov 90 --size 24x24 --spp 1024 --quiet -o "$TMP/f.pfm" --variance "$TMP/f_var.pfm"
$BUILD/tests/pfmtool const 24 24 1 1 1 "$TMP/one.pfm"; $BUILD/tests/pfmtool const 24 24 0 0 0 "$TMP/zero.pfm"
zcheck_expect "sphere furnace with vn = the face normals: L = 1" 0 "$TMP/f.pfm" "$TMP/f_var.pfm" "$TMP/one.pfm" "$TMP/zero.pfm" --pixel-pass 0 --precision 1e-3
SPH="--eye 0,0,4 --target 0,0,0 --fov 35 --size 32x32 --spp 256 --bounces 1:1 --light solid-angle --quiet"
$PATHLAB render "$S/smooth.obj" $SPH -o "$TMP/smooth.pfm"
$PATHLAB render "$S/faceted.obj" $SPH -o "$TMP/faceted.pfm"
$PATHLAB render "$S/smooth.obj" $SPH --normals geometric -o "$TMP/geo.pfm"
js=$(python3 tests/materials/jump.py "$TMP/smooth.pfm"); jf=$(python3 tests/materials/jump.py "$TMP/faceted.pfm")
if awk -v s="$js" -v f="$jf" 'BEGIN { exit !(s < 0.5 * f) }'; then pass "smooth vn: largest vertical jump $js of the mean, faceted $jf"
else fail "smooth vn: largest vertical jump $js, not under half the faceted sphere's $jf"; fi
cmp -s "$TMP/geo.pfm" "$TMP/faceted.pfm" && pass "--normals geometric: the faceted sphere's image, bit for bit" || fail "--normals geometric differs from the sphere without vn"
grep -q -- "--normals geometric" "$TMP/geo.pfm.meta" && pass "--normals geometric in the sidecar" || fail "--normals geometric not in the sidecar"
# the BRDF's cosine is the shading normal's: a quad whose vn are tilted 30 degrees, a small lamp 45
# degrees off its normal on either side; L1 at the origin against gen.py's quadrature (0.5%; 4096 spp of
# a 0.2-wide lamp at distance 10: the estimate's own spread is about 0.02%)
for t in plus minus; do
    $PATHLAB render "$S/tilt-$t.obj" --eye 0,3,3 --target 0,0,0 --fov 10 --size 1x1 --pixel-center --spp 4096 --bounces 1:1 --quiet -o "$TMP/tilt.pfm"
    got=$($PX "$TMP/tilt.pfm" 0 0 | cut -d' ' -f1); want=$(awk -v n="tilt-$t" '$1 == n { print $2 }' "$S/tilt.expect")
    if awk -v g="$got" -v w="$want" 'BEGIN { exit !(g > 0.995 * w && g < 1.005 * w) }'; then pass "vn tilted 30 degrees, lamp at $t 45: L1 $got, exact $want"
    else fail "vn tilted 30 degrees, lamp at $t 45: L1 $got, exact $want (0.0900 would be the face normal's)"; fi
done

# textures: the 2x2 map_Ke (bottom row red green, top row blue white) seen from +z
$PATHLAB render "$S/lamp.obj" $CAM -o "$TMP/l.pfm"
got="$($PX "$TMP/l.pfm" 0 0) | $($PX "$TMP/l.pfm" 3 0) | $($PX "$TMP/l.pfm" 0 3) | $($PX "$TMP/l.pfm" 3 3)"
[ "$got" = "0 0 1 | 1 1 1 | 1 0 0 | 0 1 0" ] && pass "map_Ke, nearest: v up, the file's top row at the top ($got)" || fail "map_Ke nearest: corners $got"
$PATHLAB render "$S/lamp.obj" $CAM --texture-filter bilinear -o "$TMP/b.pfm"
got="$($PX "$TMP/b.pfm" 0 3) | $($PX "$TMP/b.pfm" 1 1)"
[ "$got" = "0.625 0.25 0.25 | 0.375 0.25 0.75" ] && pass "map_Ke, bilinear: the four texels around, repeated ($got)" || fail "bilinear: $got"
W="--eye 0,0,2.9 --target 0,0,0 --fov 40 --size 16x16 --spp 8 --quiet"
$PATHLAB render "$S/wall.obj" $W -o "$TMP/w.pfm"; $PATHLAB render "$S/wall-plain.obj" $W -o "$TMP/wp.pfm"
cmp -s "$TMP/w.pfm" "$TMP/wp.pfm" && pass "map_Kd 0.5 with Kd 1 = Kd 0.5, bit for bit" || fail "map_Kd 0.5 x Kd 1 differs from Kd 0.5"
$PATHLAB render "$S/wall.obj" $W -o "$TMP/w.pfm" 2>&1 --quiet; $PATHLAB render "$S/wall.obj" --size 4x4 --spp 1 -o "$TMP/w.pfm" 2> "$TMP/err"
grep -q "5 materials, 2 textures" "$TMP/err" && pass "half.pfm named twice (half.pfm, ./half.pfm): read once" || fail "textures: $(head -c 300 "$TMP/err")"
mkdir -p "$TMP/elsewhere"; cp "$S/half.pfm" "$TMP/elsewhere/"
sed 's|map_Kd half.pfm|map_Kd ../elsewhere/half.pfm|' "$S/tex.mtl" > "$S/tex2.mtl"; sed 's|tex.mtl|tex2.mtl|' "$S/wall.obj" > "$S/wall2.obj"
expect_status "map_Kd ../elsewhere/half.pfm: refused" 2 $PATHLAB render "$S/wall2.obj" -o "$TMP/x.pfm"
expect_err "map_Kd outside: file:line, outside the scene's folder" "tex2.mtl:6: map_Kd '../elsewhere/half.pfm' is outside the scene's folder"
ln -s "$TMP/elsewhere/half.pfm" "$S/link.pfm"; sed 's|map_Kd half.pfm|map_Kd link.pfm|' "$S/tex.mtl" > "$S/tex2.mtl"
expect_status "map_Kd through a link out of the folder: refused" 2 $PATHLAB render "$S/wall2.obj" -o "$TMP/x.pfm"
mkfifo "$S/fifo.pfm"; sed 's|map_Kd half.pfm|map_Kd fifo.pfm|' "$S/tex.mtl" > "$S/tex2.mtl"
expect_status "map_Kd a FIFO: refused, not blocked" 2 timeout 10 $PATHLAB render "$S/wall2.obj" -o "$TMP/x.pfm"
expect_err "map_Kd a FIFO: not a regular file" "not a regular file"
expect_no_file "no image after a refused texture" "$TMP/x.pfm"
for v in nan -5; do   # a PFM can hold any float: a NaN texel blackened every path, a negative one gave a negative image
    "$PFMTOOL" const 2 2 0.5 "$v" 0.5 "$S/bad.pfm"; sed 's|map_Kd half.pfm|map_Kd bad.pfm|' "$S/tex.mtl" > "$S/tex2.mtl"
    expect_status "map_Kd a PFM holding $v: refused" 2 $PATHLAB render "$S/wall2.obj" -o "$TMP/x.pfm"
    expect_err "map_Kd a PFM holding $v: the pixel and why" "bad.pfm: pixel \(0, 0\) of the file is $v: a texture's values must be finite and >= 0"
    expect_err "map_Kd a PFM holding $v: the MTL's line" "tex2.mtl:6: cannot read the texture"
done
expect_no_file "no image after a texture of bad values" "$TMP/x.pfm"

# --mtl FILE: a teacher's MTL in another folder; its map_Ke relative to it
mkdir -p "$TMP/teacher"; printf 'newmtl lamp\nKe 2\nmap_Ke t.pfm\n' > "$TMP/teacher/t.mtl"; cp "$S/t2x2.pfm" "$TMP/teacher/t.pfm"
$PATHLAB render "$S/lamp.obj" $CAM --mtl "$TMP/teacher/t.mtl" -o "$TMP/t.pfm"
[ "$($PX "$TMP/t.pfm" 0 0)" = "0 0 2" ] && pass "--mtl: the teacher's Ke 2 and its texture, relative to its folder" || fail "--mtl: pixel $($PX "$TMP/t.pfm" 0 0)"
expect_status "--mtl a missing file: refused" 2 $PATHLAB render "$S/lamp.obj" --mtl "$TMP/nope.mtl" -o "$TMP/x.pfm"
expect_err "--mtl a missing file: named" "nope.mtl"
printf 'newmtl other\nKd 1\n' > "$TMP/teacher/o.mtl"
expect_status "--mtl without the OBJ's usemtl names: refused" 2 $PATHLAB render "$S/lamp.obj" --mtl "$TMP/teacher/o.mtl" -o "$TMP/x.pfm"
expect_err "--mtl: the unknown name at its OBJ line" "lamp.obj:[0-9]+: unknown material 'lamp'"

# --texture-decode: an 8-bit texel of 128 is 128/255 raw (gKit) and 0.2159 through the sRGB curve; a
# float texture (PFM) is linear either way
printf 'P3\n2 1\n255\n128 128 128 255 0 0\n' > "$S/t.ppm"; printf 'newmtl lamp\nKe 1\nmap_Ke t.ppm\n' > "$S/p.mtl"
$PATHLAB render "$S/lamp.obj" $CAM --mtl "$S/p.mtl" -o "$TMP/raw.pfm"
$PATHLAB render "$S/lamp.obj" $CAM --mtl "$S/p.mtl" --texture-decode srgb -o "$TMP/srgb.pfm"
got="$($PX "$TMP/raw.pfm" 0 0) | $($PX "$TMP/srgb.pfm" 0 0) | $($PX "$TMP/srgb.pfm" 3 0)"
[ "$got" = "0.501961 0.501961 0.501961 | 0.215861 0.215861 0.215861 | 1 0 0" ] && pass "PPM texel 128: raw 128/255, srgb 0.2159 ($got)" || fail "--texture-decode: $got"
grep -q -- "--texture-decode srgb" "$TMP/srgb.pfm.meta" && pass "--texture-decode srgb in the sidecar" || fail "--texture-decode srgb not in the sidecar"
$PATHLAB render "$S/lamp.obj" $CAM --texture-decode srgb -o "$TMP/l2.pfm"
cmp -s "$TMP/l.pfm" "$TMP/l2.pfm" && pass "a PFM texture is linear whatever --texture-decode says" || fail "--texture-decode srgb changed a PFM texture"
printf 'P6\n2 2\n255\n' > "$S/short.ppm"; printf 'newmtl lamp\nKe 1\nmap_Ke short.ppm\n' > "$S/s.mtl"
expect_status "a texture cut short: refused" 2 $PATHLAB render "$S/lamp.obj" --mtl "$S/s.mtl" -o "$TMP/x.pfm"
expect_err "a texture cut short: the MTL line named" "s.mtl:3: cannot read the texture"
# a lamp written twice (the same corners, one face each winding) and a lamp alone: the first is
# warned about once (a ray sees one copy, light sampling draws both); the second is not
printf 'mtllib d.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -3\nv 4 0 -3\nv 0 4 -3\nusemtl lamp\nf 1 2 3\nf 1 3 2\nusemtl wall\nf 4 5 6\n' > "$S/twice.obj"
printf 'mtllib d.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -3\nv 4 0 -3\nv 0 4 -3\nusemtl lamp\nf 1 2 3\nusemtl wall\nf 4 5 6\n' > "$S/once.obj"
printf 'newmtl lamp\nKd 0 0 0\nKe 1 1 1\nnewmtl wall\nKd 0.5 0.5 0.5\n' > "$S/d.mtl"
expect_status "a lamp written twice: rendered" 0 $PATHLAB render "$S/twice.obj" --size 8x8 --spp 1 --eye 0.3,0.3,3 --target 0.3,0.3,0 -o "$TMP/x.pfm"
expect_err "a lamp written twice: warned" "twice.obj: 1 emitting triangle has the same three corners as another"
expect_status "a lamp alone: rendered" 0 $PATHLAB render "$S/once.obj" --size 8x8 --spp 1 --eye 0.3,0.3,3 --target 0.3,0.3,0 -o "$TMP/x.pfm"
if grep -q "same three corners" "$TMP/err"; then fail "a lamp alone: warned as written twice"; else pass "a lamp alone: no warning"; fi
