#!/usr/bin/env bash
# The sky (--sky), with answers known exactly. Each render is checked against the exact constant
# image by tests/zcheck (per-block 8x8 and whole-image Z-tests, alpha = 0.01 with Sidak's
# correction, --precision 1e-2: the whole-image test must be sharp enough to see a 1% error, from
# 16x16 pixels x 1024 samples; a wrong pdf1 or MIS weight is off by far more):
#  - a convex object of albedo rho under a constant sky of radiance 1: every reflected ray leaves,
#    so L = L1 = rho exactly (a sphere of 24 x 12 facets, rho = 0.6, filling the frame);
#  - a sky of radiance 1 in its upper half (theta < 90 degrees from +Y) and 0 below: a diffuse
#    plane whose normal is at theta from +Y receives pi (1 + cos theta) / 2, so L = L1 =
#    rho (1 + cos theta) / 2 (a large quad filling the frame, at 0, 60, 90 and 120 degrees);
#  - the choice between the sky and an emitter (by power): light sampling alone, which makes that
#    choice, against BRDF sampling alone, which does not, on a plane under an emitter and a sky.
# Each with light sampling alone, BRDF sampling alone and MIS (the default), so that a wrong pdf1
# or a wrong MIS weight shows.
. "$(dirname "$0")/lib.sh"

# sphere: a UV sphere of radius 1 at the origin, 24 x 12 facets (a convex polyhedron)
awk 'BEGIN { pi = atan2(0, -1); nu = 24; nv = 12
    print "mtllib rho.mtl"; print "usemtl rho"
    print "v 0 1 0"; for (j = 1; j < nv; j++) for (i = 0; i < nu; i++) {
        t = pi * j / nv; p = 2 * pi * i / nu; printf "v %.9f %.9f %.9f\n", sin(t) * cos(p), cos(t), sin(t) * sin(p) }
    print "v 0 -1 0"; last = 2 + (nv - 1) * nu
    for (i = 0; i < nu; i++) printf "f 1 %d %d\n", 2 + (i + 1) % nu, 2 + i
    for (j = 0; j < nv - 2; j++) for (i = 0; i < nu; i++) {
        a = 2 + j * nu + i; b = 2 + j * nu + (i + 1) % nu; c = a + nu; d = b + nu
        printf "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c }
    for (i = 0; i < nu; i++) printf "f %d %d %d\n", last, 2 + (nv - 2) * nu + i, 2 + (nv - 2) * nu + (i + 1) % nu }' > "$TMP/sphere.obj"
printf 'newmtl rho\nKd 0.6 0.6 0.6\n' > "$TMP/rho.mtl"
# pfm W H FILE R,G,B...: a PFM of W x H pixels given from the top row down (written bottom to top)
pfm() {
    python3 -c 'import struct, sys
w, h = int(sys.argv[1]), int(sys.argv[2]); px = [[float(x) for x in p.split(",")] for p in sys.argv[4:]]
rows = [px[r * w:(r + 1) * w] for r in range(h)][::-1]
open(sys.argv[3], "wb").write(b"PF\n%d %d\n-1\n" % (w, h) + b"".join(struct.pack("<3f", *p) for row in rows for p in row))' "$@"
}
pfm 1 2 "$TMP/upper.pfm" 1,1,1 0,0,0   # the sky of the upper half

sky_known() {   # name scene.obj value spp camera-and-other-flags...
    local name=$1 obj=$2 value=$3 spp=$4; shift 4
    $PATHLAB render "$obj" --quiet --size 16x16 --spp "$spp" "$@" -o "$TMP/r.pfm" --variance "$TMP/r_var.pfm"
    $PFMTOOL const 16 16 "$value" "$value" "$value" "$TMP/exact.pfm"
    $PFMTOOL const 16 16 0 0 0 "$TMP/zero.pfm"
    zcheck_expect "$name: L = $value" 0 "$TMP/r.pfm" "$TMP/r_var.pfm" "$TMP/exact.pfm" "$TMP/zero.pfm" --pixel-pass 0 --precision 1e-2
}
# from (0, 0, 3) the sphere subtends 19.5 degrees each side: a 20 degree field sees only the sphere
cam="--eye 0.3,0.2,3 --target 0,0,0 --fov 20"
for d in mis-power light brdf; do
    sky_known "sphere rho 0.6 under --sky 1,1,1, --direct $d, 16x16 x 1024 spp" "$TMP/sphere.obj" 0.6 1024 $cam --sky 1,1,1 --direct $d
done
sky_known "sphere under --sky 1,1,1, L1 alone, --dir cosine --direct light, 16x16 x 1024 spp" "$TMP/sphere.obj" 0.6 1024 $cam --sky 1,1,1 --bounce 1 --direct light --dir cosine

# L0, the sky seen directly, and the image's orientation: an 8 x 2 sky whose pixel (i, j) has
# radiance (i + 1, j + 1, 1). Looking at phi = atan2(z, x) = pi/8 + k pi/4 and theta = 45 or 135
# degrees from +Y through a 2 degree field sees pixel (4 + k, 0) or (4 + k, 1) only (tracer/sky.h).
pfm 8 2 "$TMP/eight.pfm" 1,1,1 2,1,1 3,1,1 4,1,1 5,1,1 6,1,1 7,1,1 8,1,1 1,2,1 2,2,1 3,2,1 4,2,1 5,2,1 6,2,1 7,2,1 8,2,1
for k in -4 -1 0 2 3; do
    for row in 0 1; do
        target=$(awk -v k=$k -v r=$row 'BEGIN { pi = atan2(0, -1); p = pi / 8 + k * pi / 4; t = (r ? 3 : 1) * pi / 4
            printf "%.9f,%.9f,%.9f", 100 + sin(t) * cos(p), cos(t), sin(t) * sin(p) }')
        $PATHLAB render "$TMP/sphere.obj" --quiet --size 4x4 --spp 4 --eye 100,0,0 --target "$target" --fov 2 --sky "$TMP/eight.pfm" --bounce 0 -o "$TMP/l0.pfm"
        $PFMTOOL const 4 4 $((5 + k)) $((row + 1)) 1 "$TMP/want.pfm"
        if $PFMTOOL close "$TMP/l0.pfm" "$TMP/want.pfm" 0 > "$TMP/close" 2>&1; then pass "L0: the sky at phi = pi/8 + $k pi/4, row $row is its pixel ($((4 + k)), $row)"
        else fail "L0: the sky at phi = pi/8 + $k pi/4, row $row is not its pixel ($((4 + k)), $row): $(cat "$TMP/close")"; fi
    done
done

# a plane of normal (sin t, cos t, 0), 40 x 40, and a camera 3 along its normal
plane() {   # degrees file [half-size, default 20]
    awk -v deg="$1" -v half="${3:-20}" 'BEGIN { t = deg * atan2(0, -1) / 180; nx = sin(t); ny = cos(t)
        ux = cos(t); uy = -sin(t)   # in the plane, with (0, 0, 1)
        print "mtllib rho.mtl"; print "usemtl rho"
        for (k = 0; k < 4; k++) { a = (k == 0 || k == 3) ? -half : half; b = (k < 2) ? -half : half
            printf "v %.9f %.9f %.9f\n", a * ux, a * uy, b }
        print "f 1 2 3"; print "f 1 3 4" }' > "$2"
}
for deg in 0 60 90 120; do
    plane $deg "$TMP/plane.obj"
    eye=$(awk -v deg=$deg 'BEGIN { t = deg * atan2(0, -1) / 180; printf "%.9f,%.9f,0", 3 * sin(t), 3 * cos(t) }')
    value=$(awk -v deg=$deg 'BEGIN { printf "%.9f", 0.6 * (1 + cos(deg * atan2(0, -1) / 180)) / 2 }')
    for d in mis-power light brdf; do
        spp=1024; [ $deg = 120 ] && [ $d = light ] && spp=2048   # a third of the sky seen: noisier
        sky_known "plane at $deg degrees under the upper-half sky, --direct $d, 16x16 x $spp spp" "$TMP/plane.obj" "$value" $spp \
            --eye "$eye" --target 0,0,0 --up 0,0,1 --fov 40 --sky "$TMP/upper.pfm" --direct $d
    done
done

# the choice between the sky and the emitters: a 6 x 6 floor under a 2 x 2 quad facing down at
# height 1 (Ke 4: power 16 pi) and a sky of (0.1, 0.14, 0.2) (power pi R^2 x 4 pi x 0.136 = 31 pi
# with R = 4.27: chosen 2 times in 3). Light sampling alone chooses the sky or the quad by power
# at every vertex; BRDF sampling alone finds each by chance: they must agree (both renders noisy:
# zcheck compares them with both variances, blocks and whole image at alpha 0.01, 16x16 x 1024 spp;
# no per-pixel test: the quad's light seen from the floor below it has heavy-tailed pixel values).
plane 0 "$TMP/choice.obj" 3
awk '/^mtllib|^usemtl/ { next } { print }' "$TMP/choice.obj" > "$TMP/floor.part"
{ echo "mtllib rho.mtl"; echo "mtllib lamp.mtl"; echo "usemtl rho"; cat "$TMP/floor.part"
  echo "usemtl lamp"; echo "v -1 1 -1"; echo "v 1 1 -1"; echo "v 1 1 1"; echo "v -1 1 1"; echo "f 5 6 7"; echo "f 5 7 8"; } > "$TMP/choice.obj"
printf 'newmtl lamp\nKd 0 0 0\nKe 4 4 4\n' > "$TMP/lamp.mtl"
choice=(--size 16x16 --spp 1024 --eye 2.5,2,0.5 --target 0,0,0 --fov 50 --sky 0.1,0.14,0.2)
$PATHLAB render "$TMP/choice.obj" --quiet "${choice[@]}" --direct light -o "$TMP/cl.pfm" --variance "$TMP/cl_var.pfm"
$PATHLAB render "$TMP/choice.obj" --quiet "${choice[@]}" --direct brdf --seed 2 -o "$TMP/cb.pfm" --variance "$TMP/cb_var.pfm"
$PATHLAB render "$TMP/choice.obj" --quiet "${choice[@]}" --light power --seed 3 -o "$TMP/cm.pfm" --variance "$TMP/cm_var.pfm"
zcheck_expect "sky and an emitter: light sampling alone (the choice by power) = BRDF sampling alone" 0 "$TMP/cl.pfm" "$TMP/cl_var.pfm" "$TMP/cb.pfm" "$TMP/cb_var.pfm" --pixel-pass 0
zcheck_expect "sky and an emitter: MIS, --light power = BRDF sampling alone" 0 "$TMP/cm.pfm" "$TMP/cm_var.pfm" "$TMP/cb.pfm" "$TMP/cb_var.pfm" --pixel-pass 0

# Framing (scene/mesh.h, mesh_framing_bounds): without a view, the camera frames the scene but not a
# backdrop that dwarfs it. The sphere on a 40 x 40 floor gets the sphere's own view; the Cornell
# box (its blocks and light span more than a quarter of it) keeps the whole box's.
cp "$TMP/sphere.obj" "$TMP/floored.obj"
n=$(grep -c "^v " "$TMP/sphere.obj")
printf 'v -20 -1 -20\nv 20 -1 -20\nv 20 -1 20\nv -20 -1 20\nf %d %d %d\nf %d %d %d\n' $((n + 1)) $((n + 3)) $((n + 2)) $((n + 1)) $((n + 4)) $((n + 3)) >> "$TMP/floored.obj"
for s in sphere floored; do
    $PATHLAB render "$TMP/$s.obj" --quiet --size 8x8 --spp 1 --sky 1,1,1 -o "$TMP/$s.pfm" --write-view "$TMP/$s.view"
done
if diff <(grep -v "^#" "$TMP/sphere.view") <(grep -v "^#" "$TMP/floored.view") > /dev/null; then pass "framing: a sphere on a floor 20 times its size gets the sphere's view"
else fail "framing: the floor changed the view: $(grep -v '^#' "$TMP/floored.view" | tr '\n' ' ')"; fi
cp scenes/cornell.obj scenes/cornell.mtl "$TMP/"
$PATHLAB render "$TMP/cornell.obj" --quiet --size 8x8 --spp 1 -o "$TMP/c.pfm" --write-view "$TMP/c.view"
want=$(awk '/^v / { for (k = 2; k <= 4; k++) { if (!n || $k < lo[k]) lo[k] = $k; if (!n || $k > hi[k]) hi[k] = $k } n = 1 }
    END { printf "target %.9g %.9g %.9g", (lo[2] + hi[2]) / 2, (lo[3] + hi[3]) / 2, (lo[4] + hi[4]) / 2 }' "$TMP/cornell.obj")
got=$(grep "^target" "$TMP/c.view")
if awk -v a="$want" -v b="$got" 'BEGIN { split(a, x); split(b, y); for (k = 2; k <= 4; k++) if ((x[k] - y[k])^2 > 1e-8) exit 1 }'; then
    pass "framing: the Cornell box without its view frames the whole box ($got)"
else fail "framing: the Cornell box frames '$got', not the whole box's '$want'"; fi

# One command for a mesh from the wild: bunny.obj (no MTL: the default grey diffuse) under a
# constant sky is lit and fills the picture: over a quarter of the pixels are the bunny (darker
# than the sky's 1), and it spans over half the width.
bunny=../shared/data/meshes/bunny.obj
if [ -f "$bunny" ]; then
    $PATHLAB render "$bunny" --sky 1,1,1 --size 40x40 --spp 16 -o "$TMP/bunny.pfm" 2> "$TMP/err"; rc=$?
    fill=$(python3 -c 'import struct, sys
b = open(sys.argv[1], "rb").read().split(b"\n", 3); w, h = map(int, b[1].split()); v = struct.unpack("<%df" % (3 * w * h), b[3])
obj = [i for i in range(w * h) if v[3 * i] < 0.95]; cols = [i % w for i in obj]
lit = sum(v[3 * i] for i in obj) / max(1, len(obj))
print("%.2f %.2f %.2f" % (len(obj) / (w * h), (max(cols) - min(cols) + 1) / w if cols else 0, lit))' "$TMP/bunny.pfm")
    read -r area span lit <<< "$fill"
    if [ $rc -eq 0 ] && ! grep -q "black" "$TMP/err" && awk -v a="$area" -v s="$span" -v l="$lit" 'BEGIN { exit !(a > 0.25 && s > 0.5 && l > 0.1) }'; then
        pass "bunny.obj --sky 1,1,1: lit and framed (object $area of the pixels, $span of the width, mean $lit)"
    else fail "bunny.obj --sky 1,1,1: status $rc, object $area of the pixels, $span of the width, mean $lit: $(head -c 200 "$TMP/err")"; fi
else skip "bunny.obj --sky 1,1,1: $bunny is not here"; fi

# --sky FILE.hdr (Radiance RGBE, image/rgbe.h) is the same sky as its PFM conversion: the same image
python3 -c 'import sys; open(sys.argv[1], "wb").write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n" + bytes([128, 64, 32, 129, 200, 100, 50, 130, 0, 0, 0, 0, 10, 20, 30, 125]))' "$TMP/sky.hdr"
$PATHLAB convert "$TMP/sky.hdr" "$TMP/sky_hdr.pfm" > /dev/null 2> "$TMP/err"
$PATHLAB render "$TMP/plane.obj" --quiet --size 8x8 --spp 8 --eye 0,3,0.5 --target 0,0,0 --sky "$TMP/sky.hdr" -o "$TMP/h1.pfm"
$PATHLAB render "$TMP/plane.obj" --quiet --size 8x8 --spp 8 --eye 0,3,0.5 --target 0,0,0 --sky "$TMP/sky_hdr.pfm" -o "$TMP/h2.pfm"
if cmp -s "$TMP/h1.pfm" "$TMP/h2.pfm"; then pass "--sky FILE.hdr renders as its PFM conversion"; else fail "--sky FILE.hdr differs from its PFM conversion"; fi
expect_status "--sky with a negative radiance: status 2" 2 $PATHLAB render "$TMP/plane.obj" --sky 1,-1,1 -o "$TMP/x.pfm"
expect_err "--sky -1: the flag named" "--sky"
expect_status "--sky of a missing file: status 2" 2 $PATHLAB render "$TMP/plane.obj" --sky "$TMP/none.pfm" -o "$TMP/x.pfm"
expect_no_file "--sky of a missing file: no image" "$TMP/x.pfm"
expect_status "--sky nonsense: status 2" 2 $PATHLAB render "$TMP/plane.obj" --sky blue -o "$TMP/x.pfm"
pfm 1 1 "$TMP/nan.pfm" nan,1,1
expect_status "--sky of a PFM holding a NaN: status 2" 2 $PATHLAB render "$TMP/plane.obj" --sky "$TMP/nan.pfm" -o "$TMP/x.pfm"
expect_err "--sky NaN: the file and pixel named" "nan.pfm: pixel \(0, 0\)"
if grep -q -- "--sky $TMP/sky.hdr" "$TMP/h1.pfm.meta"; then
    pass "the sidecar's flags record --sky"; else fail "the sidecar does not record --sky: $(grep flags "$TMP/h1.pfm.meta")"; fi
# a black sky is no sky, and the warning said "no --sky" when one was given (a review, 2026-12-08)
"$PFMTOOL" const 8 4 0 0 0 "$TMP/black_sky.pfm"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$TMP/nolight.obj"
expect_status "a black --sky over a scene without emitters: renders (black)" 0 $PATHLAB render "$TMP/nolight.obj" --sky "$TMP/black_sky.pfm" --size 8x8 --spp 1 -o "$TMP/bs.pfm"
expect_err "a black --sky: the warning says the sky is black" "the --sky given is black"
