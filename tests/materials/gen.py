#!/usr/bin/env python3
"""tests/materials/gen.py OUT_DIR — the scenes of tests/test_materials.sh, written into OUT_DIR:
- flatvn-furnace: scenes/sphere-furnace.obj with every corner given its face's normal as vn (the
  shading normal then equals the geometric one: the furnace's answer, 1, must hold);
- smooth.obj / faceted.obj: a low-poly UV sphere (12 x 8) with vn = the position (smooth), or none,
  under a large emitting quad;
- tex.obj: a quad facing the camera, vt 0..1, material 'lamp' with map_Ke t2x2.pfm (L0 is the texture)
  and 'wall' with map_Kd half.pfm (constant 0.5); tex-plain.obj the same wall with Kd 0.5 and no map;
- wild.obj: the wall quad with vn far from the triangle's normal, lit from behind (stress: nothing
  comes through it); wild-furnace.obj: the sphere furnace with a random unit vn at every corner,
  half of them pointing into the surface (stress: finite, non-negative).
- tilt-plus.obj / tilt-minus.obj: a quad whose vn are tilted 30 degrees, under a small lamp 45 degrees off
  its normal on either side; tilt.expect holds L1 at the origin (a quadrature).
- texroom.obj (tests/test_grade_gkit.sh): a room of gKit's kinds: floor and back wall textured with
  the 8-bit tex8.ppm (asymmetric), glossy side walls (Ks), a smooth sphere (vn), a lamp; and the
  variants a student's mistakes give: texroom-flipv.obj (texcoord v read as 1 - v), texroom-notex.obj
  (map_Kd ignored, Kd the texture's mean); skysphere.obj, a smooth sphere on a floor for the image
  sky sky.pfm, and sky-flipped.pfm (rows reversed), sky-turned.pfm (turned half a turn about +Y).
PFM textures are written by hand (little-endian, rows bottom to top)."""
import math, os, random, struct, sys

out = sys.argv[1]
os.makedirs(out, exist_ok=True)

def write(name, text):
    with open(os.path.join(out, name), "w") as f:
        f.write(text)

def pfm(name, w, h, rows_bottom_up):
    with open(os.path.join(out, name), "wb") as f:
        f.write(b"PF\n%d %d\n-1\n" % (w, h))
        for row in rows_bottom_up:
            for px in row:
                f.write(struct.pack("<3f", *px))

# the sphere furnace with flat vn
src = open("scenes/sphere-furnace.obj").read().splitlines()
P, lines, nv = [], [], 0
for l in src:
    if l.startswith("v "):
        P.append([float(x) for x in l.split()[1:4]])
for l in src:
    if l.startswith("mtllib"):
        lines.append("mtllib flatvn-furnace.mtl")
    elif l.startswith("f "):
        ids = [int(c.split("/")[0]) for c in l.split()[1:]]
        a, b, c = (P[i - 1] for i in ids[:3])
        e1 = [b[k] - a[k] for k in range(3)]
        e2 = [c[k] - a[k] for k in range(3)]
        n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        ln = math.sqrt(sum(x * x for x in n))
        lines.append("vn %.9g %.9g %.9g" % tuple(x / ln for x in n))
        nv += 1
        lines.append("f " + " ".join("%d//%d" % (i, nv) for i in ids))
    else:
        lines.append(l)
write("flatvn-furnace.obj", "\n".join(lines) + "\n")
write("flatvn-furnace.mtl", open("scenes/sphere-furnace.mtl").read())

# a low-poly UV sphere under a large light
def sphere(smooth):
    nu, nvv = 12, 8
    s = ["mtllib sphere.mtl"]
    for j in range(nvv + 1):
        th = math.pi * j / nvv
        for i in range(nu):
            ph = 2 * math.pi * i / nu
            p = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            s.append("v %.9g %.9g %.9g" % p)
            s.append("vn %.9g %.9g %.9g" % p)
    s.append("usemtl grey")
    def vid(j, i):
        return j * nu + (i % nu) + 1
    for j in range(nvv):
        for i in range(nu):
            a, b, c, d = vid(j, i), vid(j, i + 1), vid(j + 1, i + 1), vid(j + 1, i)
            for tri in ((a, b, c), (a, c, d)):
                if smooth:
                    s.append("f " + " ".join("%d//%d" % (k, k) for k in tri))
                else:
                    s.append("f " + " ".join("%d" % k for k in tri))
    n = len([x for x in s if x.startswith("v ")])
    s += ["usemtl lamp", "v -4 4 -4", "v 4 4 -4", "v 4 4 4", "v -4 4 4",
          "f %d %d %d %d" % (n + 1, n + 2, n + 3, n + 4)]
    return "\n".join(s) + "\n"
write("smooth.obj", sphere(True))
write("faceted.obj", sphere(False))
write("sphere.mtl", "newmtl grey\nKd 0.8\nnewmtl lamp\nKe 1\n")

# textured quads, facing +z toward a camera on the +z axis
quad = ("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n")
write("tex.obj", "mtllib tex.mtl\n" + quad + "usemtl %s\nf 1/1 2/2 3/3 4/4\n")
write("lamp.obj", "mtllib tex.mtl\n" + quad + "usemtl lamp\nf 1/1 2/2 3/3 4/4\n")
write("wall.obj", "mtllib tex.mtl\n" + quad + "usemtl wall\nf 1/1 2/2 3/3 4/4\n"
      "usemtl light\nv -1 -1 3\nv -1 1 3\nv 1 1 3\nv 1 -1 3\nf 5 6 7 8\n")
write("wall-plain.obj", "mtllib tex.mtl\n" + quad + "usemtl plain\nf 1/1 2/2 3/3 4/4\n"
      "usemtl light\nv -1 -1 3\nv -1 1 3\nv 1 1 3\nv 1 -1 3\nf 5 6 7 8\n")
write("tex.mtl", "newmtl lamp\nKe 1\nmap_Ke t2x2.pfm\n"
      "newmtl wall\nKd 1\nmap_Kd half.pfm\nnewmtl wall2\nKd 1\nmap_Kd ./half.pfm\n"
      "newmtl plain\nKd 0.5\nnewmtl light\nKe 1\n")
# 2x2: bottom row red, green; top row blue, white
pfm("t2x2.pfm", 2, 2, [[(1, 0, 0), (0, 1, 0)], [(0, 0, 1), (1, 1, 1)]])
pfm("half.pfm", 4, 4, [[(0.5, 0.5, 0.5)] * 4] * 4)

# the wall with wild vn: light on its back (z < 0 side faces the light at z = -3), camera at +z
wild = ["mtllib tex.mtl", "v -1 -1 0", "v 1 -1 0", "v 1 1 0", "v -1 1 0",
        "vn 0 0 -1", "vn 1 0 0.01", "vn -0.7 0.7 -0.1", "vn 0 -1 0",
        "usemtl plain", "f 1//1 2//2 3//3 4//4",
        "usemtl light", "v -1 -1 -3", "v 1 -1 -3", "v 1 1 -3", "v -1 1 -3", "f 5 6 7 8"]
write("wild.obj", "\n".join(wild) + "\n")

# the sphere furnace with random vn at every corner (seeded: the same file every run)
rng = random.Random(7)
lines, nv = [], 0
for l in src:
    if l.startswith("mtllib"):
        lines.append("mtllib flatvn-furnace.mtl")
    elif l.startswith("f "):
        ids = [int(c.split("/")[0]) for c in l.split()[1:]]
        corners = []
        for i in ids:
            g = [rng.gauss(0, 1) for _ in range(3)]
            lines.append("vn %.6g %.6g %.6g" % tuple(g))
            nv += 1
            corners.append("%d//%d" % (i, nv))
        lines.append("f " + " ".join(corners))
    else:
        lines.append(l)
write("wild-furnace.obj", "\n".join(lines) + "\n")

# a flat quad (face normal +y) whose four vn are all tilted by alpha = 30 degrees toward +x, lit by a
# small square lamp (side 0.2, Ke 1000) at distance 10 in the xy plane, at theta = +45 or -45 degrees
# from +y, facing the origin: at the origin L1 = Kd/pi * integral over the lamp of
# Ke max(0, n_s . w) cos_lamp / r^2 dA, which is near Kd/pi * Ke A / D^2 * cos(theta - alpha) (0.123 and
# 0.0329; the face normal's cosine would give 0.0900 both). Written to tilt.expect, midpoint rule.
def tilt(theta_deg, alpha_deg=30.0, D=10.0, s=0.2, Le=1000.0):
    a, t = math.radians(alpha_deg), math.radians(theta_deg)
    n = (math.sin(a), math.cos(a), 0.0)
    c = (D * math.sin(t), D * math.cos(t), 0.0)
    w = (-math.sin(t), -math.cos(t), 0.0)
    u, v = (0.0, 0.0, 1.0), (-math.cos(t), math.sin(t), 0.0)    # u x v = w: the lamp faces the origin
    corners = [tuple(c[k] + su * s / 2 * u[k] + sv * s / 2 * v[k] for k in range(3))
               for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    o = ["mtllib tilt.mtl", "v -1 0 1", "v 1.2 0 1", "v 1.2 0 -1.3", "v -1 0 -1.3",   # origin off the diagonal
         "vn %.9f %.9f %.9f" % n, "usemtl white", "f 1//1 2//1 3//1 4//1"]
    o += ["v %.9f %.9f %.9f" % p for p in corners] + ["usemtl bright", "f 5 6 7 8"]
    N, tot = 200, 0.0
    for i in range(N):
        for j in range(N):
            su, sv = (i + 0.5) / N * 2 - 1, (j + 0.5) / N * 2 - 1
            q = [c[k] + su * s / 2 * u[k] + sv * s / 2 * v[k] for k in range(3)]
            r2 = sum(x * x for x in q)
            d = [x / math.sqrt(r2) for x in q]
            cs = max(0.0, sum(n[k] * d[k] for k in range(3)))
            tot += Le * cs * max(0.0, -sum(w[k] * d[k] for k in range(3))) / r2 * (s * s / N / N)
    return "\n".join(o) + "\n", tot / math.pi
expect = []
for name, th in (("tilt-plus", 45.0), ("tilt-minus", -45.0)):
    text, L = tilt(th)
    write(name + ".obj", text)
    expect.append("%s %.6f" % (name, L))
write("tilt.mtl", "newmtl white\nKd 1\nnewmtl bright\nKe 1000\n")
write("tilt.expect", "\n".join(expect) + "\n")


# texroom: a 2 x 2 x 2 room open toward +z, its lamp facing down (one-sided: checked below)
def ppm(name, w, h, rows_top_down):
    with open(os.path.join(out, name), "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h))
        for row in rows_top_down:
            for px in row:
                f.write(bytes(px))
A, B, Y = (200, 60, 60), (60, 60, 200), (230, 230, 60)
tex = [[(A if (i + j) % 2 else B) for i in range(8)] for j in range(8)]
for j in range(2):
    for i in range(2):
        tex[j][i] = Y                       # the file's top-left corner: what a flip moves
ppm("tex8.ppm", 8, 8, tex)
mean = [sum(px[k] for row in tex for px in row) / 64 / 255 for k in range(3)]

def texroom(flip_v, mtl):
    v, vt, o = [], [], ["mtllib " + mtl]
    def quad(mat, corners, uv=None):
        base = len(v)
        v.extend(corners)
        if uv:
            vb = len(vt)
            vt.extend((a, 1 - b if flip_v else b) for a, b in uv)
            o.append("usemtl %s\nf %s" % (mat, " ".join("%d/%d" % (base + k + 1, vb + k + 1) for k in range(4))))
        else:
            o.append("usemtl %s\nf %s" % (mat, " ".join("%d" % (base + k + 1) for k in range(4))))
    uv = [(0, 0), (1, 0), (1, 1), (0, 1)]
    quad("floor", [(-1, 0, 1), (1, 0, 1), (1, 0, -1), (-1, 0, -1)], uv)
    quad("back", [(-1, 0, -1), (1, 0, -1), (1, 2, -1), (-1, 2, -1)], uv)
    quad("left", [(-1, 0, 1), (-1, 0, -1), (-1, 2, -1), (-1, 2, 1)])
    quad("right", [(1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1)])
    quad("white", [(-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1)])
    quad("lamp", [(-0.3, 1.99, -0.3), (0.3, 1.99, -0.3), (0.3, 1.99, 0.3), (-0.3, 1.99, 0.3)])
    a, b, c = v[-4:-1]
    e1 = [b[k] - a[k] for k in range(3)]; e2 = [c[k] - a[k] for k in range(3)]
    assert e1[2] * e2[0] - e1[0] * e2[2] < 0, "the lamp must face down"
    text = ["v %.9g %.9g %.9g" % p for p in v] + ["vt %.9g %.9g" % t for t in vt] + o
    nv = len(v)
    sph = sphere(True).splitlines()
    for l in sph:      # the smooth sphere, radius 0.35 at (0.35, 0.35, -0.3), its lamp dropped
        if l.startswith("v "):
            x, y, z = (float(t) for t in l.split()[1:])
            text.append("v %.9g %.9g %.9g" % (0.35 + 0.35 * x, 0.35 + 0.35 * y, -0.3 + 0.35 * z))
        elif l.startswith("vn "):
            text.append(l)
        elif l.startswith("f ") and len(l.split()) == 4:
            text.append("f " + " ".join("%d//%d" % (int(c.split("//")[0]) + nv, int(c.split("//")[1])) for c in l.split()[1:]))
        elif l == "usemtl grey":
            text.append("usemtl ball")
        elif l == "usemtl lamp":
            break
    return "\n".join(text) + "\n"
write("texroom.obj", texroom(False, "texroom.mtl"))
write("texroom-flipv.obj", texroom(True, "texroom.mtl"))
write("texroom-notex.obj", texroom(False, "texroom-notex.mtl"))
walls = ("newmtl left\nKd 0.6 0.1 0.1\nKs 0.3\nNs 20\nnewmtl right\nKd 0.1 0.5 0.1\nKs 0.3\nNs 20\n"
         "newmtl white\nKd 0.7\nnewmtl ball\nKd 0.7\nKs 0.25\nNs 40\nnewmtl lamp\nKe 12\n")
write("texroom.mtl", walls + "newmtl floor\nKd 1\nmap_Kd tex8.ppm\nnewmtl back\nKd 0.8\nmap_Kd tex8.ppm\n")
write("texroom-notex.mtl", walls + "newmtl floor\nKd %.6f %.6f %.6f\nnewmtl back\nKd %.6f %.6f %.6f\n"
      % (tuple(mean) + tuple(0.8 * m for m in mean)))

# skysphere: the smooth sphere on a floor (Kd 0.5), for an image sky bright above, with a warm
# side (+x) and a cool side (-x): turning or flipping it changes the picture
sky = sphere(True).splitlines()
sky = [l for l in sky if l.split()[:2] != ["usemtl", "lamp"] and not (l.startswith("v ") and l.split()[2] == "4")]
sky = [l for l in sky if not (l.startswith("f ") and "//" not in l)]
sky = [l.replace("sphere.mtl", "skysphere.mtl") for l in sky]
n = len([l for l in sky if l.startswith("v ")])
sky += ["usemtl floor", "v -3 -1 3", "v 3 -1 3", "v 3 -1 -3", "v -3 -1 -3", "f %d %d %d %d" % (n + 1, n + 2, n + 3, n + 4)]
write("skysphere.obj", "\n".join(sky) + "\n")
write("skysphere.mtl", "newmtl grey\nKd 0.8\nnewmtl floor\nKd 0.5\n")
W, H = 16, 8
def sky_px(i, j):      # column i (u), row j counted from the bottom (v)
    up = (j + 0.5) / H
    warm = 0.5 + 0.5 * math.cos(2 * math.pi * (i + 0.5) / W)
    return (0.2 + 1.5 * up * warm, 0.2 + 1.0 * up, 0.2 + 1.5 * up * (1 - warm))
rows = [[sky_px(i, j) for i in range(W)] for j in range(H)]
pfm("sky.pfm", W, H, rows)
pfm("sky-flipped.pfm", W, H, rows[::-1])
pfm("sky-turned.pfm", W, H, [r[W // 2:] + r[:W // 2] for r in rows])
