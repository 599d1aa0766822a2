#!/usr/bin/env bash
# --light tree is unbiased on a scene of many lights: on scenes/many-lights (10560 emitting
# triangles of 48 colours x strengths, on the ceiling and the walls of a hall), L1 with --light tree agrees
# with --light power within their noise, each render with its own variance (--variance), at the
# pixels' centres (--pixel-center: the same camera hits for both), 24x18 pixels.
#  - --direct light --light tree: the tree's sampler and the pdf its descent returns;
#  - --direct mis-balance --light tree: also light_pdf_area, the pdf recomputed along an emitter's
#    path for the directions that hit an emitter (the MIS weights use it).
# Each against --direct light --light power at 8192 spp (seed 2), by tests/zcheck at alpha 0.001
# for each of its families (per pixel, Sidak over the 1296 pixel-channels, 99.75% must pass; the 36
# blocks of 6x6 pixels, Sidak; the whole image), with --precision 0.02: the whole-image test must be
# able to see a 2% error. Measured when it was written: tree 4096 spp against power 8192, image
# |z| 1.64 and 2.02, tolerance 1.1% of the mean. A pdf that skips the last level of the tree (each
# emitter's probability off by its last choice) gave a 3.2% bias with mis-balance, image |z| 10.8; a
# descent that does not rescale u0, a 15-20% bias, |z| 122 and 141: each FAILs.
. "$(dirname "$0")/lib.sh"
ZCHECK=$BUILD/tests/zcheck
R="$PATHLAB render scenes/many-lights.obj --quiet --size 24x18 --pixel-center --bounce 1"
run_ok "many-lights, --light power, 8192 spp" $R --spp 8192 --direct light --light power --seed 2 -o "$TMP/power.pfm" --variance "$TMP/power_v.pfm"
for d in light mis-balance; do
    run_ok "many-lights, --direct $d --light tree, 4096 spp" $R --spp 4096 --direct $d --light tree --seed 3 -o "$TMP/tree-$d.pfm" --variance "$TMP/tree-${d}_v.pfm"
    out=$("$ZCHECK" "$TMP/tree-$d.pfm" "$TMP/tree-${d}_v.pfm" "$TMP/power.pfm" "$TMP/power_v.pfm" --alpha 0.001 --block 6 --pixel-pass 0.9975 --precision 0.02 2>&1); rc=$?
    if [ $rc -eq 0 ]; then pass "many-lights L1: --direct $d --light tree = --light power within noise: $out"
    else fail "many-lights L1: --direct $d --light tree differs from --light power (zcheck exit $rc): $out"; fi
done
# A known answer the tree once missed: a floor (Kd 0.5) under a 20 x 20 panel of Le 1 at height 40,
# and two 2-mm emitters of Ke 1e12 just under the floor, facing sideways. Seen from the floor's
# centre, L1 = Kd/pi x E with E = pi x the form factor of the panel (four 10 x 10 corner
# rectangles at h = 40): 0.0367388. Without the normal at p, the cluster under the floor took all
# but 7e-12 of the tree's choices: --direct light --light tree rendered 0. With it, the cluster
# gets 0 there. Pass: the image mean within 5 standard errors (from --variance) of the answer, the
# standard error under 1% of it; 48x48, 16 spp.
cat > "$TMP/under.obj" <<'OBJ'
mtllib under.mtl
v -0.5 0 -0.5
v -0.5 0 0.5
v 0.5 0 0.5
v 0.5 0 -0.5
v -10 40 -10
v 10 40 -10
v 10 40 10
v -10 40 10
v 0 -0.004 -0.001
v 0 -0.002 0
v 0 -0.004 0.001
usemtl floor
f 1 2 3
f 1 3 4
usemtl panel
f 5 6 7
f 5 7 8
usemtl hot
f 9 10 11
f 9 11 10
OBJ
printf 'newmtl floor\nKd 0.5 0.5 0.5\nnewmtl panel\nKd 0 0 0\nKe 1 1 1\nnewmtl hot\nKd 0 0 0\nKe 1e12 1e12 1e12\n' > "$TMP/under.mtl"
cat > "$TMP/mean.py" <<'PYEND'
import struct, sys, math
def rd(fn):
    d = open(fn, 'rb').read().split(b'\n', 3)
    w, h = map(int, d[1].split())
    return struct.unpack('<%df' % (3 * w * h), d[3][:12 * w * h])
m, v = rd(sys.argv[1]), rd(sys.argv[2])
mean, se = sum(m) / len(m), math.sqrt(sum(v)) / len(m)
want = 0.0367388
print("%d %.6f %.2g" % (abs(mean - want) < 5 * se and se < 0.01 * want, mean, se))
PYEND
run_ok "a floor under a panel, a bright cluster under the floor: --direct light --light tree" $PATHLAB render "$TMP/under.obj" --quiet --eye 0,0.06,-0.06 --target 0,0,0 --up 0,1,0 --fov 40 --size 48x48 --spp 16 --bounce 1 --direct light --light tree -o "$TMP/under.pfm" --variance "$TMP/under_v.pfm"
read -r ok mean se <<< "$(python3 "$TMP/mean.py" "$TMP/under.pfm" "$TMP/under_v.pfm")"
if [ "$ok" = 1 ]; then pass "cluster under the floor: L1 of the floor by the tree $mean (standard error $se), the answer 0.0367388"
else fail "cluster under the floor: L1 of the floor by the tree $mean (standard error $se), want 0.0367388 within 5 standard errors"; fi
exit 0
