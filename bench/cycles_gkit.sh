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
# Cycles: tools/cycles_gkit.py at CYCLES_SPP (1024) spp; pathlab: PATHLAB (./pathlab) at SPP (4096);
# each as two halves of different seeds, averaged, so that a reference's own noise is known
# (mean (A - B)^2 / 4 over pixels and RGB).
# The camera: pathlab reads the orbiter file and writes the view it makes (--write-view), which gives
# Cycles the same eye, target, up and vertical fov. Needs blender (make bench-cycles-deps).
# Then error against time on texbox (ROUNDS, default 2; 0 skips it): Cycles at 64 and 256 spp (T its
# CYCLES_DONE time), at once pathlab --time T; each MSE (over pixels and RGB) against each reference
# with that reference's noise taken off; the ratio (MSE x time of pathlab) / (MSE x time of Cycles),
# pathlab's target at most 0.5. About 12 minutes on 2 cores.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/cycles_gkit.sh GKIT_DATA [OUT]" >&2; exit 2; }
DATA=$1 OUT=${2:-build/bench/gkit}
PATHLAB=$(realpath "${PATHLAB:-./pathlab}") TOOLS=$(realpath tools)
SPP=${SPP:-4096} CYCLES_SPP=${CYCLES_SPP:-1024} SIZE=256x160 ROUNDS=${ROUNDS:-2}
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
# pfm.py avg A B OUT (prints the noise of OUT) | mse IMG REF NOISE (prints MSE - NOISE): stdlib only
cat > pfm.py <<'PY'
import struct, sys
def read(p):
    d = open(p, "rb").read(); h = d.split(b"\n", 3); w, hh = (int(x) for x in h[1].split())
    return h[:3], struct.unpack(("<" if float(h[2]) < 0 else ">") + "%df" % (3 * w * hh), h[3][:12 * w * hh])
if sys.argv[1] == "avg":
    (h, a), (_, b) = read(sys.argv[2]), read(sys.argv[3])
    open(sys.argv[4], "wb").write(b"\n".join(h[:2]) + b"\n-1\n" + struct.pack("<%df" % len(a), *[(x + y) / 2 for x, y in zip(a, b)]))
    print("%.6g" % (sum((x - y) ** 2 for x, y in zip(a, b)) / len(a) / 4))
else:
    (_, a), (_, b) = read(sys.argv[2]), read(sys.argv[3])
    print("%.6g" % (sum((x - y) ** 2 for x, y in zip(a, b)) / len(a) - float(sys.argv[4])))
PY
cam() { awk -v k="$1" '$1 == k { print $2 "," $3 "," $4 }' "$2"; }
cycles() {   # cycles SCENE SPP SEED OUT.pfm: prints the CYCLES_DONE seconds
    blender -b --factory-startup --python "$TOOLS/cycles_gkit.py" -- $1.obj --eye="$(cam eye $1.view)" --target="$(cam target $1.view)" \
        --up="$(cam up $1.view)" --fov "$(awk '$1 == "fov" { print $2 }' $1.view)" --size $SIZE --spp "$2" --seed "$3" \
        --out "${4%.pfm}.exr" --pfm "$4" > c.log 2>&1 || { echo "blender failed: $OUT/c.log" >&2; exit 1; }
    sed -n 's/^CYCLES_DONE \([0-9.]*\) s/\1/p' c.log | tail -n 1
}
plab() { "$PATHLAB" render $1.obj --orbiter cornell_orbiter.txt --material diffuse --size $SIZE --threads 2 "${@:2}"; }
status=0
for scene in cornell texbox; do
    plab $scene --spp 1 --quiet -o view.pfm --write-view $scene.view
    for s in 101 102; do
        plab $scene --spp $((SPP / 2)) --seed $s --quiet -o p_${scene}_$s.pfm
        cycles $scene $((CYCLES_SPP / 2)) $s c_${scene}_$s.pfm > /dev/null
    done
    python3 pfm.py avg p_${scene}_101.pfm p_${scene}_102.pfm p_$scene.pfm > p_$scene.noise
    python3 pfm.py avg c_${scene}_101.pfm c_${scene}_102.pfm c_$scene.pfm > c_$scene.noise
    printf '%-8s ' $scene
    python3 "$TOOLS/anchor_compare.py" p_$scene.pfm c_$scene.pfm 16 || status=1
done
[ "$ROUNDS" -gt 0 ] && echo "texbox, equal time: round level | Cycles s spp | pathlab s spp | ratio against pathlab's reference, Cycles'"
for r in $(seq "$ROUNDS"); do
    for level in 64 256; do
        T=$(cycles texbox $level $r c_eq.pfm)
        plab texbox --time "$T" --seed $r -o p_eq.pfm 2> p_eq.log
        read -r tp np <<< "$(awk '/ spp, .* Msamples\/s/ { s = $1; n = $3 } END { print s, n }' p_eq.log)"
        ratio() { python3 -c "print('%.2f' % (($1 * $tp) / ($2 * $T)))"; }
        mp=$(python3 pfm.py mse p_eq.pfm p_texbox.pfm "$(cat p_texbox.noise)"); mc=$(python3 pfm.py mse c_eq.pfm p_texbox.pfm "$(cat p_texbox.noise)")
        mp2=$(python3 pfm.py mse p_eq.pfm c_texbox.pfm "$(cat c_texbox.noise)"); mc2=$(python3 pfm.py mse c_eq.pfm c_texbox.pfm "$(cat c_texbox.noise)")
        echo "$r $level | $T $level | $tp $np | $(ratio "$mp" "$mc") $(ratio "$mp2" "$mc2")"
    done
done
exit $status
