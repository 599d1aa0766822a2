#!/usr/bin/env bash
# bench/cycles_sky.sh — pathlab against Blender Cycles on a sky scene: the Stanford bunny (Kd 0.5) on
# a floor (Kd 0.5) under a synthetic equirectangular sky (sky.hdr, 64 x 32: a blue gradient above,
# a brown ground below, a small bright sun at theta 40, phi 30 degrees), full transport.
#  1. agreement: pathlab and Cycles (bench/cycles_ref_sky.py) at REF_SPP spp each, two seeds each;
#     the whole image's mean per channel and the worst 25x25 block's, relative, with the noise of
#     the difference (from each renderer's two halves);
#  2. efficiency at equal time: Cycles at LEVEL spp takes T (its CYCLES_DONE time), pathlab renders
#     with --time T right after; each image's MSE against the other renderer's reference, the
#     reference's own noise taken off; efficiency = MSE x time, the ratio pathlab / Cycles.
# Usage: bench/cycles_sky.sh (from the project's root). Environment: SIZE (200x200), THREADS (2),
# REF_SPP (256, per seed), LEVEL (64), OUT (build/bench-sky).
set -eu
PATHLAB=${PATHLAB:-./pathlab} SIZE=${SIZE:-200x200} THREADS=${THREADS:-2} REF_SPP=${REF_SPP:-256} LEVEL=${LEVEL:-64}
OUT=${OUT:-build/bench-sky}
PY=/usr/bin/python3
BUNNY=../shared/data/meshes/bunny.obj
mkdir -p "$OUT"
# the sky as Cycles reads it: Blender decodes RGBE as m / 256 x 2^(e - 128), pathlab's img_read_hdr
# with Ward's half step, (m + 0.5) / 256 x 2^(e - 128): 0.2-0.4% more. pathlab gets sky.pfm, those
# same values as Blender's, so that the comparison is of the renderers and not of the decoders.
$PY - "$OUT/sky.hdr" "$OUT/sky.pfm" <<'PYEOF'
import math, sys
W, H = 64, 32
def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32: return bytes([0, 0, 0, 0])
    f, e = math.frexp(m); s = f * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])
rows = []
for j in range(H):
    t = math.pi * (j + 0.5) / H
    for i in range(W):
        p = 2 * math.pi * ((i + 0.5) / W - 0.5)
        if abs(math.degrees(t) - 40) < 6 and abs(math.degrees(p) - 30) < 6: c = (60.0, 55.0, 45.0)
        elif t < math.pi / 2: c = (0.3 + 0.3 * math.cos(t), 0.45 + 0.3 * math.cos(t), 0.9 + 0.3 * math.cos(t))
        else: c = (0.25, 0.2, 0.15)
        rows.append(rgbe(*c))
open(sys.argv[1], 'wb').write(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n' % (H, W) + b''.join(rows))
import struct
dec = [[q[k] / 256.0 * 2.0 ** (q[3] - 128) if q[3] else 0.0 for k in range(3)] for q in rows]
open(sys.argv[2], 'wb').write(b'PF\n%d %d\n-1\n' % (W, H) + b''.join(struct.pack('<3f', *dec[j * W + i]) for j in reversed(range(H)) for i in range(W)))
PYEOF
{ echo "mtllib scene.mtl"; echo "usemtl grey"; grep -E '^(v|f) ' "$BUNNY"
  n=$(grep -c '^v ' "$BUNNY"); y=$(awk '/^v /{ if (!s || $3 < m) { m = $3; s = 1 } } END { print m }' "$BUNNY")
  printf 'v -2 %s -2\nv 2 %s -2\nv 2 %s 2\nv -2 %s 2\nf %d %d %d\nf %d %d %d\n' $y $y $y $y $((n + 1)) $((n + 3)) $((n + 2)) $((n + 1)) $((n + 4)) $((n + 3))
} > "$OUT/scene.obj"
printf 'newmtl grey\nKd 0.5 0.5 0.5\n' > "$OUT/scene.mtl"
CAM="--eye=-0.05,0.2,0.38 --target=-0.017,0.09,0 --fov 40 --size $SIZE"
cycles() {   # spp seed out.exr: prints the render seconds
    blender -b --factory-startup --python bench/cycles_ref_sky.py -- "$OUT/scene.obj" $CAM --up 0,1,0 --spp "$1" --seed "$2" \
        --threads "$THREADS" --sky "$OUT/sky.hdr" --out "$3" 2>&1 | sed -n 's/^CYCLES_DONE \([0-9.]*\) s/\1/p'
}
pathlab() {  # out.pfm flags...: prints the render seconds
    local out=$1; shift
    $PATHLAB render "$OUT/scene.obj" $CAM --sky "$OUT/sky.pfm" --threads "$THREADS" -o "$out" "$@" 2>&1 | sed -n 's/^\([0-9.]*\) s, .*/\1/p'
}
for s in 1 2; do
    [ -f "$OUT/cref$s.exr" ] || echo "cycles ref seed $s: $(cycles $REF_SPP $s "$OUT/cref$s.exr") s"
    [ -f "$OUT/pref$s.pfm" ] || echo "pathlab ref seed $s: $(pathlab "$OUT/pref$s.pfm" --spp $REF_SPP --seed $s) s"
done
tc=$(cycles $LEVEL 3 "$OUT/c_level.exr")
tp=$(pathlab "$OUT/p_level.pfm" --time "$tc" --seed 3)
echo "equal time: Cycles $LEVEL spp in $tc s, pathlab --time $tc: $tp s"
$PY bench/sky_compare.py "$OUT" "$tc" "$tp"
