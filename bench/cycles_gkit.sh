#!/usr/bin/env bash
# bench/cycles_gkit.sh GKIT_DATA [OUT] — gKit's own scenes, rendered by pathlab and by Blender Cycles,
# compared by tools/anchor_compare.py (the whole image's mean within 0.5%, every 16x16 block's within 3%).
#
# GKIT_DATA: a gKit copy's data/ folder (gkit2light's, e.g. TomClabault/M2-synthese@371c7d6), holding
# cornell.obj, cornell.mtl, cornell_orbiter.txt, simple_plane_base_color.jpg (a JPEG) and
# debug2x2red.png. Two scenes, both under --material diffuse (the Monte Carlo tutorials' model,
# docs/gkit.md; Cycles' Diffuse BSDF), seen through gKit's orbiter file at 256x160:
#   cornell  gKit's Cornell box as it is;
#   texbox   the same box with its floor textured by the JPEG (texcoords 0..2: repeated) and its back
#            wall by the PNG, nearest texel, raw bytes / 255 (gKit's sampling and decoding).
# Cycles: tools/cycles_gkit.py at CYCLES_SPP (1024) spp; pathlab: PATHLAB (./pathlab) at SPP (4096).
# The camera: pathlab reads the orbiter file and writes the view it makes (--write-view), which gives
# Cycles the same eye, target, up and vertical fov. Needs blender (make bench-cycles-deps).
# About 8 minutes on 2 cores.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/cycles_gkit.sh GKIT_DATA [OUT]" >&2; exit 2; }
DATA=$1 OUT=${2:-build/bench/gkit}
PATHLAB=$(realpath "${PATHLAB:-./pathlab}") TOOLS=$(realpath tools)
SPP=${SPP:-4096} CYCLES_SPP=${CYCLES_SPP:-1024} SIZE=256x160
mkdir -p "$OUT"
for f in cornell.obj cornell.mtl cornell_orbiter.txt simple_plane_base_color.jpg debug2x2red.png; do
    cp "$DATA/$f" "$OUT/" || { echo "bench/cycles_gkit.sh: $DATA/$f is missing" >&2; exit 2; }
done
cd "$OUT"
# texbox: the floor's and the back wall's faces get texcoords from their positions
python3 - <<'PY'
src = open("cornell.obj").read().splitlines()
P = [list(map(float, l.split()[1:4])) for l in src if l.startswith("v ")]
out, vts, mat = [], [], None
for l in src:
    if l.startswith("mtllib"): out.append("mtllib texbox.mtl"); continue
    if l.startswith("usemtl"):
        mat = l.split()[1]
        l = {"floor.001": "usemtl floorTex", "backWall.001": "usemtl backTex"}.get(mat, l)
    if l.startswith("f ") and mat in ("floor.001", "backWall.001"):
        ws = []
        for i in (int(t.split("/")[0]) for t in l.split()[1:]):
            x, y, z = P[i - 1]
            u, v = ((x + 1.02) / 2.02 * 2, (z + 1.04) / 2.03 * 2) if mat == "floor.001" else ((x + 1.02) / 2.02, y / 1.99)
            vts.append("vt %.6f %.6f" % (u, v)); ws.append("%d/%d" % (i, len(vts)))
        l = "f " + " ".join(ws)
    out.append(l)
open("texbox.obj", "w").write("\n".join(vts + out) + "\n")
open("texbox.mtl", "w").write(open("cornell.mtl").read() + "\nnewmtl floorTex\nKd 1 1 1\nmap_Kd simple_plane_base_color.jpg\n"
                              "\nnewmtl backTex\nKd 0.8 0.8 0.8\nmap_Kd debug2x2red.png\n")
PY
status=0
for scene in cornell texbox; do
    "$PATHLAB" render $scene.obj --orbiter cornell_orbiter.txt --material diffuse --size $SIZE --spp "$SPP" \
        --threads 2 --quiet -o p_$scene.pfm --write-view $scene.view
    cam() { awk -v k="$1" '$1 == k { print $2 "," $3 "," $4 }' $scene.view; }
    blender -b --factory-startup --python "$TOOLS/cycles_gkit.py" -- $scene.obj --eye="$(cam eye)" --target="$(cam target)" \
        --up="$(cam up)" --fov "$(awk '$1 == "fov" { print $2 }' $scene.view)" --size $SIZE --spp "$CYCLES_SPP" \
        --out c_$scene.exr --pfm c_$scene.pfm > c_$scene.log 2>&1 || { echo "blender failed: $OUT/c_$scene.log" >&2; exit 1; }
    printf '%-8s ' $scene
    python3 "$TOOLS/anchor_compare.py" p_$scene.pfm c_$scene.pfm 16 || status=1
done
exit $status
