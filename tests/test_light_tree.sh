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
exit 0
