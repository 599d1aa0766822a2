#!/usr/bin/env python3
"""gen.py — scenes, exact images and image figures for the numerical stress suite (tests/stress/run.sh).
Python 3 standard library only; everything is written into a temporary folder at run time.

    gen.py scenes DIR                 write every stress scene (OBJ, MTL, view) and the exact images
                                      that have a closed form (PFM) into DIR
    gen.py mean IMG.pfm [VAR.pfm]     mean over pixels and channels, and its standard error
    gen.py exact NAME IMG.pfm EXACT.pfm TOL
                                      pixels whose value differs from EXACT by more than TOL (deterministic renders)
    gen.py between IMG VAR LO VLO HI VHI [BLOCK]
                                      is IMG between LO and HI (per channel, per BLOCK x BLOCK block and
                                      over the whole image) up to noise? (z-fighting: energy plausible)

Conventions of pathlab (README.md): f = Kd/pi + Ks (Ns+8)/(8 pi) cos^Ns(theta_h); emission on the
front face n = (b - a) x (c - a) only; camera as in src/scene/camera.c; PFM rows bottom to top.
"""
import math
import os
import struct
import sys
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "scenes")


def f32(x):
    """x rounded to the nearest binary32, as a Python float."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def num(x):
    """A number for an OBJ/view file: the shortest decimal that reads back as the same double."""
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(float(x))


# ---------------------------------------------------------------------------------------------
# Vectors (tuples of floats)

def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def length(a): return math.sqrt(dot(a, a))
def unit(a): return mul(a, 1.0 / length(a))


# ---------------------------------------------------------------------------------------------
# Images

def write_pfm(path, w, h, px):
    """px: list of (r, g, b) per pixel, row 0 at the top (as pathlab's image.c)."""
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        for y in range(h - 1, -1, -1):
            row = px[y * w:(y + 1) * w]
            f.write(struct.pack("<%df" % (3 * w), *[c for p in row for c in p]))


def read_pfm(path):
    """(w, h, px) with px a flat list of 3 floats per pixel, row 0 at the top."""
    with open(path, "rb") as f:
        data = f.read()
    parts, pos = [], 0
    while len(parts) < 4:   # magic, w, h, scale, each ended by whitespace
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        parts.append(data[start:pos].decode())
    pos += 1
    magic, w, h, scale = parts[0], int(parts[1]), int(parts[2]), float(parts[3])
    ch = 3 if magic == "PF" else 1
    fmt = ("<" if scale < 0 else ">") + "%df" % (ch * w * h)
    vals = struct.unpack(fmt, data[pos:pos + 4 * ch * w * h])
    px = []
    for y in range(h):
        src = (h - 1 - y) * w * ch
        for x in range(w):
            p = vals[src + x * ch: src + x * ch + ch]
            px.extend(p if ch == 3 else p * 3)
    return w, h, px


# ---------------------------------------------------------------------------------------------
# Camera (src/scene/camera.c, in double)

class Camera:
    def __init__(self, eye, target, up, fov, w, h):
        th = math.tan(0.5 * fov * math.pi / 180.0)
        self.eye, self.w_px, self.h_px = eye, w, h
        self.w = unit(sub(target, eye))
        side = cross(self.w, up)
        self.u = mul(unit(side), th * w / h)
        self.v = mul(unit(cross(side, self.w)), th)

    def ray(self, x, y):
        sx = 2.0 * x / self.w_px - 1.0
        sy = 1.0 - 2.0 * y / self.h_px
        return self.eye, unit(add(self.w, add(mul(self.u, sx), mul(self.v, sy))))

    def pixel_rays(self):
        """The rays of --pixel-center, row 0 at the top."""
        for py in range(self.h_px):
            for px in range(self.w_px):
                yield self.ray(px + 0.5, py + 0.5)


def view_text(eye, target, up, fov, size, comment):
    return "# %s\neye %s\ntarget %s\nup %s\nfov %s\nsize %d %d\n" % (
        comment, " ".join(num(c) for c in eye), " ".join(num(c) for c in target),
        " ".join(num(c) for c in up), num(fov), size[0], size[1])


# ---------------------------------------------------------------------------------------------
# Meshes

class Mesh:
    def __init__(self):
        self.P, self.index, self.groups = [], {}, []   # groups: (material, [triangles of indices])

    def vertex(self, p):
        p = tuple(float(c) for c in p)
        if p not in self.index:
            self.index[p] = len(self.P)
            self.P.append(p)
        return self.index[p]

    def add(self, material, tris):
        """tris: triangles of points (a, b, c), front face (b - a) x (c - a)."""
        self.groups.append((material, [tuple(self.vertex(p) for p in t) for t in tris]))

    def obj(self, mtllib, header):
        out = ["# " + line for line in header] + ["mtllib " + mtllib, ""]
        out += ["v %s %s %s" % tuple(num(c) for c in p) for p in self.P]
        for k, (mat, tris) in enumerate(self.groups):
            out += ["", "o part%d_%s" % (k, mat), "usemtl " + mat]
            out += ["f %d %d %d" % (a + 1, b + 1, c + 1) for a, b, c in tris]
        return "\n".join(out) + "\n"


def mtl_text(materials):
    """materials: list of (name, dict with Kd, Ks, Ns and optionally Ke)."""
    out = []
    for name, m in materials:
        out += ["newmtl " + name, "Kd %s %s %s" % tuple(num(c) for c in m.get("Kd", (0, 0, 0))),
                "Ks %s %s %s" % tuple(num(c) for c in m.get("Ks", (0, 0, 0))), "Ns %s" % num(m.get("Ns", 1))]
        if "Ke" in m:
            out.append("Ke %s %s %s" % tuple(num(c) for c in m["Ke"]))
        out.append("")
    return "\n".join(out)


def quad(a, b, c, d):
    """Two triangles of the quad a b c d (in order), front face (b - a) x (c - a)."""
    return [(a, b, c), (a, c, d)]


def facing(tri, n):
    """The triangle, reordered if needed so that its front face points along n."""
    a, b, c = tri
    return tri if dot(cross(sub(b, a), sub(c, a)), n) > 0 else (a, c, b)


def box_quads(lo, hi):
    """The 6 faces of an axis-aligned box, each as (quad corners, outward normal)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], (0, -1, 0)),
            ([(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)], (0, 1, 0)),
            ([(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)], (-1, 0, 0)),
            ([(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)], (1, 0, 0)),
            ([(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)], (0, 0, -1)),
            ([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], (0, 0, 1))]


def box_tris(lo, hi, inward, skip=()):
    """Triangles of a box's faces, facing into the box (inward) or out of it; faces in skip
    (outward normals) are left out."""
    tris = []
    for corners, n in box_quads(lo, hi):
        if tuple(n) in skip:
            continue
        face_n = mul(n, -1) if inward else n
        tris += [facing(t, face_n) for t in quad(*corners)]
    return tris


def write(d, name, text):
    with open(os.path.join(d, name), "w") as f:
        f.write(text)


def write_scene(d, name, mesh, materials, view, header):
    write(d, name + ".obj", mesh.obj(name + ".mtl", header))
    write(d, name + ".mtl", mtl_text(materials))
    write(d, name + ".view", view)


# ---------------------------------------------------------------------------------------------
# The Cornell box, read from scenes/, scaled and moved

def read_obj(path):
    """Vertices and the remaining lines (faces, groups) of an OBJ file."""
    P, rest = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == "v":
            P.append(tuple(float(c) for c in w[1:4]))
        elif w and w[0] in ("f", "o", "g", "usemtl"):
            rest.append(line.rstrip("\n"))
    return P, rest


def read_view(path):
    v = {}
    for line in open(path):
        w = line.split("#")[0].split()
        if w:
            v[w[0]] = [float(c) for c in w[1:]]
    return v


def cornell_faces():
    """The Cornell box's triangles by object name, as points."""
    P, rest = read_obj(os.path.join(SCENES, "cornell.obj"))
    groups, cur, mat = [], None, None
    for line in rest:
        w = line.split()
        if w[0] == "usemtl":
            mat = w[1]
            groups.append((mat, []))
        elif w[0] == "f":
            groups[-1][1].append(tuple(P[int(i.split("/")[0]) - 1] for i in w[1:4]))
    return groups


def cornell_materials():
    """(name, material) from scenes/cornell.mtl."""
    mats, cur = [], None
    for line in open(os.path.join(SCENES, "cornell.mtl")):
        w = line.split()
        if not w or w[0].startswith("#"):
            continue
        if w[0] == "newmtl":
            cur = {}
            mats.append((w[1], cur))
        elif w[0] in ("Kd", "Ks", "Ke"):
            cur[w[0]] = tuple(float(c) for c in w[1:4])
        elif w[0] == "Ns":
            cur["Ns"] = float(w[1])
    return mats


def cornell_view():
    v = read_view(os.path.join(SCENES, "cornell.view"))
    return tuple(v["eye"]), tuple(v["target"]), tuple(v["up"]), v["fov"][0]


def transformed_cornell(d, name, scale, shift, extra=None, materials=None, drop=()):
    """The Cornell box with every point p moved to scale p + (shift, shift, shift), camera too."""
    move = lambda p: tuple(scale * c + shift for c in p)
    m = Mesh()
    for mat, tris in cornell_faces():
        if mat in drop:
            continue
        m.add(mat, [tuple(move(p) for p in t) for t in tris])
    for mat, tris in (extra or []):
        m.add(mat, [tuple(move(p) for p in t) for t in tris])
    eye, target, up, fov = cornell_view()
    mats = materials or cornell_materials()
    write_scene(d, name, m, mats, view_text(move(eye), move(target), up, fov, (48, 48),
                                           "Cornell box camera, moved with the box"),
                ["The Cornell box (scenes/cornell.obj) with p -> %r p + %r (1, 1, 1)." % (scale, shift)])


# ---------------------------------------------------------------------------------------------
# Degenerate, needle and sliver triangles on the camera's wall of a furnace

def orient(a, b, c):
    """Exact orientation of 2D points (binary32 values, so exact as Fractions): > 0 counter-clockwise."""
    a, b, c = [tuple(Fraction(x) for x in p) for p in (a, b, c)]
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def sliver_face():
    """A triangulation of the square [-1, 1]^2 (corners only on its boundary) by 1 -> 3 splits at
    points placed to make needles (points within 2^-22 of a corner or of each other), slivers (points
    1 ulp off an edge) and, on purpose, zero-area triangles (a point exactly on an edge: one child
    has zero area, its neighbour gets a T-vertex). Returns (triangles, counts)."""
    C = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
    tris = [(C[0], C[1], C[2]), (C[0], C[2], C[3])]
    ulp = lambda x: math.ldexp(1.0, math.frexp(abs(x))[1] - 24)   # binary32 ulp of x
    pts = []
    # needles: a cascade toward corner (1, -1), each point 2^-k from it
    for k in range(4, 23, 3):
        pts.append((1.0 - math.ldexp(1.0, -k), -1.0 + math.ldexp(1.0, -k - 1)))
    # slivers: points 1, 2, 4 ulps above the diagonal x = y (inside the upper triangle), then inside
    # the sliver they made, then again
    for x in (0.25, -0.5, 0.625, -0.8125):
        pts.append((x, x + ulp(x)))
    for x in (0.375, -0.3125):
        pts.append((x, x - ulp(x)))      # 1 ulp below the diagonal
    # slivers along the face's own boundary: 1 ulp inside the edge x = -1 (shared with the x = -1 wall)
    for y in (-0.75, 0.0, 0.5):
        pts.append((-1.0 + ulp(1.0) / 2, y))
    # needle pairs: two points 2^-22 apart
    for x, y in ((0.1, 0.7), (-0.6, -0.2)):
        x, y = f32(x), f32(y)
        pts += [(x, y), (x + 4 * ulp(x), y + 4 * ulp(y))]
    # exactly on an interior edge (the diagonal, if it is still an edge there): a zero-area child
    pts.append((0.875, 0.875))
    zero = 0
    for q in pts:
        q = (f32(q[0]), f32(q[1]))
        assert -1 < q[0] < 1 and -1 < q[1] < 1, q
        for i, (a, b, c) in enumerate(tris):
            o = (orient(a, b, q), orient(b, c, q), orient(c, a, q))
            if min(o) >= 0:
                break
        else:
            raise AssertionError("no triangle holds %r" % (q,))
        zero += sum(1 for v in o if v == 0)
        tris[i:i + 1] = [(a, b, q), (b, c, q), (c, a, q)]
    # and plain zero-area triangles: a repeated corner, three exactly collinear points
    extra = [(C[0], C[0], C[2]), (C[0], (0.0, 0.0), C[2])]
    return tris, extra, {"points": len(pts), "zero_children": zero}


def degenerate_furnace(d):
    """The furnace cube [-1, 1]^3 (Kd 0.5, Ke 1 inward, L = 2 everywhere) whose +z wall, the one the
    camera faces, is the sliver triangulation above."""
    face, extra, info = sliver_face()
    m = Mesh()
    m.add("furnace", box_tris((-1, -1, -1), (1, 1, 1), True, skip=[(0, 0, 1)]))
    to3 = lambda p: (p[0], p[1], 1.0)
    m.add("furnace", [facing(tuple(to3(p) for p in t), (0, 0, -1)) if orient(*t) != 0 else tuple(to3(p) for p in t)
                      for t in face + extra])
    # what pathlab's parser keeps: |(b - a) x (c - a)| > 0 computed in binary32 (src/scene/obj.c)
    kept, dropped, dropped_nonzero = [], 0, 0
    for t in face + extra:
        a, b, c = [(f32(p[0]), f32(p[1]), 1.0) for p in t]
        e1 = [f32(b[i] - a[i]) for i in range(3)]
        e2 = [f32(c[i] - a[i]) for i in range(3)]
        cr = [f32(f32(e1[(i + 1) % 3] * e2[(i + 2) % 3]) - f32(e1[(i + 2) % 3] * e2[(i + 1) % 3])) for i in range(3)]
        if f32(f32(f32(cr[0] * cr[0]) + f32(cr[1] * cr[1])) + f32(cr[2] * cr[2])) == 0:
            dropped += 1
            dropped_nonzero += orient(*t) != 0
        else:
            kept.append(abs(float(orient(*t))) / 2)
    info.update(dropped=dropped, dropped_nonzero=dropped_nonzero, smallest=min(kept))
    write(d, "degenerate.dropped", "%d\n" % dropped)
    write_scene(d, "degenerate", m, [("furnace", {"Kd": (0.5,) * 3, "Ks": (0,) * 3, "Ns": 1, "Ke": (1,) * 3})],
                view_text((0, 0, 0), (0, 0, 1), (0, 1, 0), 90, (48, 48), "the centre, facing the sliver wall"),
                ["Furnace (L = 2) whose +z wall is %d triangles: needles, slivers, zero-area ones." % len(face)])
    return len(face) + len(extra), info


# ---------------------------------------------------------------------------------------------
# Glossy floor in an emitting enclosure: L = a(o), the Blinn lobe's directional albedo

def blinn_albedo(mu, Ns):
    """a(o) = int f cos(theta_i) dw_i for f = (Ns+8)/(8 pi) cos^Ns(theta_h) (Ks = 1), cos(theta_o) = mu.
    With the half vector h drawn from p(h) = (Ns+1)/(2 pi) cos^Ns(theta_h) (cos theta_h = u^(1/(Ns+1)), u
    uniform) and dw_i = 4 (o.h) dw_h:  a = (Ns+8)/(Ns+1) E[(o.h) max(0, i_z)], i = 2 (o.h) h - o.
    The azimuth integral is done in closed form, u by Gauss-Legendre on a graded mesh toward u = 0."""
    so, co = math.sqrt(max(0.0, 1 - mu * mu)), mu
    total = 0.0
    for lo, hi in U_PANELS:
        half, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
        for x, wgt in GL:
            u = mid + half * x
            ch = math.exp(math.log(u) / (Ns + 1))
            sh = math.sqrt(max(0.0, 1 - ch * ch))
            A, B = so * sh, co * ch
            # (A cos phi + B)(2 ch (A cos phi + B) - co) over phi where 2 ch (A cos phi + B) > co
            if A == 0:
                phi0 = math.pi if 2 * ch * B > co else 0.0
            else:
                k = (co / (2 * ch) - B) / A
                phi0 = math.pi if k <= -1 else 0.0 if k >= 1 else math.acos(k)
            s0, c0 = math.sin(phi0), math.cos(phi0)
            iP = 2 * A * s0 + 2 * B * phi0
            iP2 = A * A * (phi0 + s0 * c0) + 4 * A * B * s0 + 2 * B * B * phi0
            total += wgt * half * (2 * ch * iP2 - co * iP) / (2 * math.pi)
    return (Ns + 8) / (Ns + 1) * total


def blinn_albedo_normal(Ns):
    """The same at normal incidence, in closed form: (Ns+8) [c^(Ns+4) 2/(Ns+4) - c^(Ns+2)/(Ns+2)] from 1/sqrt2 to 1."""
    F = lambda c: 2 * c ** (Ns + 4) / (Ns + 4) - c ** (Ns + 2) / (Ns + 2)
    return (Ns + 8) * (F(1.0) - F(math.sqrt(0.5)))


def gauss_legendre(n):
    """Nodes and weights on [-1, 1] (Newton on the Legendre polynomial)."""
    out = []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-15:
                break
        out.append((x, 2 / ((1 - x * x) * dp * dp)))
    return out


GL = gauss_legendre(24)
U_PANELS = [(0.0, 1e-16)] + [(10.0 ** -(k + 1), 10.0 ** -k) for k in range(15, 0, -1)] + \
    [(0.1 * j, 0.1 * (j + 1)) for j in range(1, 10)]


GLOSSY_BOX = ((-2.0, 0.0, -2.0), (2.0, 3.0, 2.0))
GLOSSY_CAM = ((0.0, 1.2, -1.9), (0.0, 0.0, 0.6), (0.0, 1.0, 0.0), 70.0, (48, 48))


def glossy_scene(d, Ns):
    """Floor y = 0, Kd 0, Ks 1, Ns; walls and ceiling black (Kd 0) emitting Le = 1 inward. Every direction
    above the floor sees Le = 1, walls reflect nothing: floor L(o) = a(o) exactly, walls L = 1."""
    lo, hi = GLOSSY_BOX
    m = Mesh()
    m.add("floor", box_tris(lo, hi, True, skip=[(0, 1, 0), (-1, 0, 0), (1, 0, 0), (0, 0, -1), (0, 0, 1)]))
    m.add("sky", box_tris(lo, hi, True, skip=[(0, -1, 0)]))
    name = "glossy_ns%g" % Ns
    eye, target, up, fov, size = GLOSSY_CAM
    write_scene(d, name, m, [("floor", {"Kd": (0, 0, 0), "Ks": (1, 1, 1), "Ns": Ns}),
                             ("sky", {"Kd": (0, 0, 0), "Ks": (0, 0, 0), "Ns": 1, "Ke": (1, 1, 1)})],
                view_text(eye, target, up, fov, size, "looking down at the glossy floor"),
                ["Glossy floor (Kd 0, Ks 1, Ns %g) in a closed box of black walls emitting Le = 1:" % Ns,
                 "L(floor, o) = a(o) = integral of f cos over the hemisphere."])
    cam = Camera(eye, target, up, fov, *size)
    px, nfloor = [], 0
    cache = {}
    for o, dvec in cam.pixel_rays():
        t = -o[1] / dvec[1] if dvec[1] < 0 else math.inf
        p = add(o, mul(dvec, t)) if t < math.inf else None
        if p is not None and lo[0] <= p[0] <= hi[0] and lo[2] <= p[2] <= hi[2]:
            mu = -dvec[1]
            key = round(mu, 12)
            if key not in cache:
                cache[key] = blinn_albedo(mu, Ns)
            a = cache[key]
            px.append((a, a, a))
            nfloor += 1
        else:
            px.append((1.0, 1.0, 1.0))
    write_pfm(os.path.join(d, name + "_exact.pfm"), size[0], size[1], px)
    return nfloor


# ---------------------------------------------------------------------------------------------
# Lambert's formula: irradiance from a uniform polygon (one-sided emitter)

def lambert_E(x, n, poly, n_light, Le):
    """Irradiance at x (normal n) from polygon poly (entirely above x's tangent plane) of radiance Le
    emitted toward n_light only."""
    if dot(sub(x, poly[0]), n_light) <= 0:
        return 0.0
    s = 0.0
    for i in range(len(poly)):
        a, b = unit(sub(poly[i], x)), unit(sub(poly[(i + 1) % len(poly)], x))
        c = cross(a, b)
        theta = math.atan2(length(c), dot(a, b))
        s += theta * dot(n, unit(c))
    return Le * 0.5 * abs(s)


def ray_quad(o, d, quadpts):
    """t of the ray's hit on the (planar, convex) quad, or inf."""
    a, b, c, _ = quadpts
    n = cross(sub(b, a), sub(c, a))
    den = dot(n, d)
    if den == 0:
        return math.inf
    t = dot(n, sub(a, o)) / den
    if t <= 0:
        return math.inf
    p = add(o, mul(d, t))
    for i in range(4):
        e0, e1 = quadpts[i], quadpts[(i + 1) % 4]
        if dot(cross(sub(e1, e0), sub(p, e0)), n) < 0:
            return math.inf
    return t


def grazing_scene(d, name, light, front, cam_def, Le, comment):
    """A square light (corners in order) emitting toward `front`, black on both sides (Kd 0), over a
    40 x 40 diffuse plane (Kd 0.5) at y = 0: L = Kd/pi E on the plane (Lambert), Le or 0 on the light."""
    light = [tuple(f32(c) for c in p) for p in light]
    nL = unit(cross(sub(light[1], light[0]), sub(light[2], light[0])))
    if dot(nL, front) < 0:
        light, nL = light[::-1], mul(nL, -1)
    assert dot(nL, front) > 0.99
    assert all(p[1] > 0 for p in light)
    m = Mesh()
    m.add("plane", [facing(t, (0, 1, 0)) for t in quad((-20, 0, -20), (20, 0, -20), (20, 0, 20), (-20, 0, 20))])
    m.add("light", quad(*light))
    eye, target, up, fov, size = cam_def
    write_scene(d, name, m, [("plane", {"Kd": (0.5,) * 3, "Ks": (0,) * 3, "Ns": 1}),
                             ("light", {"Kd": (0,) * 3, "Ks": (0,) * 3, "Ns": 1, "Ke": (Le,) * 3})],
                view_text(eye, target, up, fov, size, comment), ["Grazing light: " + comment])
    cam = Camera(eye, target, up, fov, *size)
    px, lo, hi = [], math.inf, 0.0
    for o, dv in cam.pixel_rays():
        tl = ray_quad(o, dv, light)
        tp = -o[1] / dv[1] if dv[1] < 0 else math.inf
        if tl < tp:
            v = Le if dot(dv, nL) < 0 else 0.0
        elif tp < math.inf and abs(o[0] + tp * dv[0]) <= 20 and abs(o[2] + tp * dv[2]) <= 20:
            x = add(o, mul(dv, tp))
            v = 0.5 / math.pi * lambert_E(x, (0, 1, 0), light, nL, Le)
            lo, hi = min(lo, v), max(hi, v)
        else:
            v = 0.0
        px.append((v, v, v))
    write_pfm(os.path.join(d, name + "_exact.pfm"), size[0], size[1], px)
    return lo, hi


# ---------------------------------------------------------------------------------------------
# Rays along shared edges

def star_scene(d):
    """8 triangles around (0, 0, 1) on the plane z = 1, edges along x = 0, y = 0, x = y, x = -y:
    planes through the eye at the origin, so that with an odd image size the centre row, the centre
    column and both diagonals of pixel-centre rays lie exactly in the plane of a shared edge (the
    camera's u and v are exactly along -x and +y: d_x = d_y exactly on the diagonals), and the centre
    ray passes exactly through the vertex shared by 8 triangles. Black, emitting Le = 1 toward the eye:
    every pixel must be exactly 1."""
    ring = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]
    m = Mesh()
    m.add("e", [facing(((0, 0, 1), (a[0], a[1], 1), (b[0], b[1], 1)), (0, 0, -1))
                for a, b in zip(ring, ring[1:] + ring[:1])])
    write_scene(d, "star", m, [("e", {"Kd": (0,) * 3, "Ks": (0,) * 3, "Ns": 1, "Ke": (1, 1, 1)})],
                view_text((0, 0, 0), (0, 0, 1), (0, 1, 0), 90, (33, 33), "at the origin, facing the star"),
                ["A star of 8 triangles on z = 1 whose shared edges lie in planes through the eye."])


EDGE_BOX = ((0.0, -0.5, 2.0), (0.5, 0.0, 3.0))


def edge_box_scene(d):
    """A closed box [0, 0.5] x [-0.5, 0] x [2, 3] emitting Le = 1 outward (black), the eye at the origin:
    its top face lies in the plane y = 0 of the centre row of rays, its side face in the plane x = 0 of
    the centre column, and the centre ray runs exactly along the edge shared by those two faces, into
    the corner of the front face. Exact image: 1 where the pixel-centre ray meets the closed box
    (boundary included), 0 elsewhere."""
    m = Mesh()
    m.add("e", box_tris(EDGE_BOX[0], EDGE_BOX[1], False))
    write_scene(d, "edgebox", m, [("e", {"Kd": (0,) * 3, "Ks": (0,) * 3, "Ns": 1, "Ke": (1, 1, 1)})],
                view_text((0, 0, 0), (0, 0, 1), (0, 1, 0), 40, (33, 33), "eye in the planes of two faces"),
                ["A closed emitting box seen with its top and side faces edge-on."])


def edge_exact(d, name, eye, target, up, fov, size, inside):
    cam = Camera(eye, target, up, fov, *size)
    px = [(1.0,) * 3 if inside(o, dv) else (0.0,) * 3 for o, dv in cam.pixel_rays()]
    write_pfm(os.path.join(d, name), size[0], size[1], px)


def hits_box(o, dv, lo, hi):
    """Does the ray meet the closed box (slabs, boundary included)?"""
    t0, t1 = 0.0, math.inf
    for k in range(3):
        if dv[k] == 0:
            if not lo[k] <= o[k] <= hi[k]:
                return False
        else:
            a, b = (lo[k] - o[k]) / dv[k], (hi[k] - o[k]) / dv[k]
            t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    return t0 <= t1


# ---------------------------------------------------------------------------------------------
# Furnaces for tests/stress/acne.sh: (tag, scale, shift)

ACNE_CASES = (("scale1", 1.0, 0.0), ("scale1e-05", 1e-5, 0.0), ("scale0.001", 1e-3, 0.0), ("scale1000", 1e3, 0.0),
              ("scale100000", 1e5, 0.0), ("move10000", 1.0, 1e4), ("move1e+06", 1.0, 1e6),
              ("rot_scale1", 1.0, 0.0), ("rot_scale1000", 1e3, 0.0), ("rot_move1e+06", 1.0, 1e6))


def rotation(a, b, c):
    """The rotation by angles a, b, c (radians) about x, then y, then z, as a function of a point."""
    def R(p):
        x, y, z = p
        y, z = y * math.cos(a) - z * math.sin(a), y * math.sin(a) + z * math.cos(a)
        x, z = x * math.cos(b) + z * math.sin(b), -x * math.sin(b) + z * math.cos(b)
        x, y = x * math.cos(c) - y * math.sin(c), x * math.sin(c) + y * math.cos(c)
        return (x, y, z)
    return R


# ---------------------------------------------------------------------------------------------

def scenes(d):
    os.makedirs(d, exist_ok=True)
    lines = []
    # 1. the Cornell box scaled and moved
    transformed_cornell(d, "cornell", 1.0, 0.0)
    for s in (1e-5, 1e-3, 1e3, 1e5):
        transformed_cornell(d, "cornell_scale%g" % s, s, 0.0)
    for t in (1e4, 1e6):
        transformed_cornell(d, "cornell_move%g" % t, 1.0, t)
    # 2. degenerate, needle and sliver triangles
    n, info = degenerate_furnace(d)
    lines.append("degenerate: %d triangles on the sliver wall (%d 1->3 splits, %d zero-area children, 2 zero-area extras);"
                 " %d have a binary32 cross product 0 (the parser drops them), %d of those a nonzero exact area;"
                 " smallest area kept %.3g" % (n, info["points"], info["zero_children"], info["dropped"],
                                                info["dropped_nonzero"], info["smallest"]))
    # 3. coplanar overlapping faces in the Cornell box
    floor = [t for mat, tris in cornell_faces() if mat == "floor" for t in tris]
    (a, b, c), (_, _, e) = floor          # floor corners a b c e; triangles (a b c) (a c e)
    transformed_cornell(d, "coplanar_same", 1.0, 0.0, extra=[("floor", floor)])
    transformed_cornell(d, "coplanar_flip", 1.0, 0.0, extra=[("floor", [(b, a, e), (b, e, c)])])
    red_floor = cornell_materials() + [("floor_red", dict(dict(cornell_materials())["red"]))]
    transformed_cornell(d, "coplanar_mixed", 1.0, 0.0, extra=[("floor_red", [(b, e, a), (b, c, e)])],
                        materials=red_floor)
    transformed_cornell(d, "floor_red", 1.0, 0.0, extra=[("floor_red", floor)], materials=red_floor, drop=("floor",))
    # 4. Ns = 1, 1e2, 1e4, 1e6
    for Ns in (1, 1e2, 1e4, 1e6):
        nf = glossy_scene(d, Ns)
        lines.append("glossy Ns %g: a(normal) = %.6f (closed form %.6f), %d floor pixels"
                     % (Ns, blinn_albedo(1.0, Ns), blinn_albedo_normal(Ns), nf))
    # 5. a light of area ~1e-8 with the Cornell light's power, against a 0.1 mm light of the same power
    mats = dict(cornell_materials())
    ke_ref = mats["light"]["Ke"]
    A_ref = 130.0 * 105.0
    base = [m for m in cornell_materials() if m[0] != "light"]
    y = 547.8                                      # 1 mm below the ceiling, emitting down
    x0, z0 = 278.0, 279.5
    u = math.ldexp(1.0, -15)                       # binary32 ulp of x and z there
    tiny = [(x0, y, z0), (x0 + 3 * u, y, z0), (x0 + 3 * u, y, z0 + 4 * u), (x0, y, z0 + 4 * u)]
    A_tiny = (3 * u) * (4 * u)
    cx, cz = x0 + 1.5 * u, z0 + 2 * u
    small = [(cx - 0.05, y, cz - 0.05), (cx + 0.05, y, cz - 0.05), (cx + 0.05, y, cz + 0.05), (cx - 0.05, y, cz + 0.05)]
    A_small = f32(cx + 0.05) - f32(cx - 0.05)
    A_small *= f32(cz + 0.05) - f32(cz - 0.05)
    full_ceiling = [((556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2)), ((556, 548.8, 0), (0, 548.8, 559.2), (0, 548.8, 0))]
    for name, q, A in (("tinylight", tiny, A_tiny), ("smalllight", small, A_small)):
        ke = tuple(k * A_ref / A for k in ke_ref)
        transformed_cornell(d, name, 1.0, 0.0, drop=("light", "ceiling"),
                            extra=[("ceiling", [facing(t, (0, -1, 0)) for t in full_ceiling]),
                                   ("lamp", [facing(t, (0, -1, 0)) for t in quad(*q)])],
                            materials=base + [("lamp", {"Kd": (0, 0, 0), "Ks": (0, 0, 0), "Ns": 1, "Ke": ke})])
        lines.append("%s: area %.4g mm^2, Ke %.4g %.4g %.4g (power of the Cornell light)" % ((name, A) + ke))
    # 6. light at grazing angles
    e = math.radians(1.0)
    tilted = [(-0.5, 0.01, 0.0), (0.5, 0.01, 0.0), (0.5, 0.01 + math.cos(e), math.sin(e)),
              (-0.5, 0.01 + math.cos(e), math.sin(e))]
    lo, hi = grazing_scene(d, "grazing_tilt", tilted, (0, -math.sin(e), math.cos(e)),
                           ((0.0, 0.6, 6.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0), 40.0, (48, 48)), 10.0,
                           "a 1 x 1 light 1 degree from vertical, 0.01 above the plane, seen from in front")
    lines.append("grazing_tilt: exact L on the plane from %.3g to %.3g" % (lo, hi))
    flat = [(-0.5, 0.05, -0.5), (0.5, 0.05, -0.5), (0.5, 0.05, 0.5), (-0.5, 0.05, 0.5)]
    lo, hi = grazing_scene(d, "grazing_flat", flat, (0, -1, 0),
                           ((0.0, 1.0, -8.0), (0.0, 0.0, -2.0), (0.0, 1.0, 0.0), 30.0, (48, 48)), 10.0,
                           "a 1 x 1 light facing down 0.05 above the plane, seen nearly edge-on from the plane up to 8 away")
    lines.append("grazing_flat: exact L on the plane from %.3g to %.3g" % (lo, hi))
    # 7. rays along shared edges
    star_scene(d)
    edge_box_scene(d)
    for name, eye in (("star_exact.pfm", (0, 0, 0)), ("star_shift_exact.pfm", (1e-3, 2e-3, 0))):
        edge_exact(d, name, eye, add(eye, (0, 0, 1)), (0, 1, 0), 90, (33, 33),
                   lambda o, dv: hits_box(o, dv, (-1, -1, 1), (1, 1, 1)))
    for name, eye in (("edgebox_exact.pfm", (0, 0, 0)), ("edgebox_shift_exact.pfm", (-1e-3, 2e-3, 0))):
        edge_exact(d, name, eye, add(eye, (0, 0, 1)), (0, 1, 0), 40, (33, 33),
                   lambda o, dv: hits_box(o, dv, EDGE_BOX[0], EDGE_BOX[1]))
    # 8. furnaces for the acne measurement: the cube [0, 556]^3 (where the Cornell box is: walls on the
    # planes x = 0, y = 0, z = 0), scaled and moved like it; the camera at its centre looks at the
    # corner nearest the origin, where three walls lie on coordinate planes
    for tag, s, t in ACNE_CASES:
        lo, hi = (t, t, t), (556.0 * s + t,) * 3
        c = mul(add(lo, hi), 0.5)
        m = Mesh()
        target = lo
        if tag.startswith("rot"):   # the same cube turned about its corner lo (no wall on a coordinate plane)
            R = rotation(0.5, 0.7, 0.9)
            turn = lambda p: add(lo, R(sub(p, lo)))
            m.add("furnace", [tuple(turn(p) for p in tri) for tri in box_tris(lo, hi, True)])
            c, target = turn(c), turn(add(lo, mul(sub(hi, lo), 0.1)))
        else:
            m.add("furnace", box_tris(lo, hi, True))
        write_scene(d, "furnace_" + tag, m,
                    [("furnace", {"Kd": (0.5,) * 3, "Ks": (0,) * 3, "Ns": 1, "Ke": (1,) * 3})],
                    view_text(c, target, (0, 1, 0), 90, (32, 32), "the centre, facing the corner nearest the origin"),
                    ["Furnace: the inside of the cube [%r, %r]^3%s, Kd 0.5, Ke 1: L = 2 everywhere."
                     % (lo[0], hi[0], ", turned about its corner" if tag.startswith("rot") else "")])
    # 9. the Cornell box with a glossy floor, Ns 1 .. 1e6 (NaN/Inf count only)
    for Ns in (1, 1e2, 1e4, 1e6):
        mats = [(n, dict(m)) for n, m in cornell_materials()]
        for n, m in mats:
            if n == "floor":
                m.update({"Kd": tuple(0.5 * k for k in m["Kd"]), "Ks": (0.5,) * 3, "Ns": Ns})
        transformed_cornell(d, "cornell_ns%g" % Ns, 1.0, 0.0, materials=mats)
    for line in lines:
        print(line)


def mean(args):
    w, h, px = read_pfm(args[0])
    m = sum(px) / len(px)
    out = "mean %.7g" % m
    if len(args) > 1:
        _, _, v = read_pfm(args[1])
        # pixels are independent; the 3 channels of a pixel are taken as fully correlated (conservative)
        se = math.sqrt(sum((math.sqrt(v[3 * i]) + math.sqrt(v[3 * i + 1]) + math.sqrt(v[3 * i + 2])) ** 2
                           for i in range(w * h))) / (3 * w * h)
        out += " se %.3g" % se
    print(out)


def exact(args):
    name, img, ref, tol = args[0], args[1], args[2], float(args[3])
    w, h, a = read_pfm(img)
    _, _, b = read_pfm(ref)
    bad = [i // 3 for i in range(len(a)) if not (abs(a[i] - b[i]) <= tol)]
    bad = sorted(set(bad))
    lost = sum(1 for i in bad if a[3 * i] < b[3 * i])
    print("%d of %d pixels differ from the exact image (%d darker%s)" %
          (len(bad), w * h, lost, (", first at x %d y %d: %.6g vs %.6g" % (bad[0] % w, bad[0] // w, a[3 * bad[0]], b[3 * bad[0]]))
           if bad else ""))
    return 1 if bad else 0


def between(args):
    """Blocks (and the whole image) of IMG lie between LO and HI per channel, up to noise: for each, with
    sigma^2 the sum of the variances of the block means, lo - z sigma <= img <= hi + z sigma, z the
    Sidak-corrected one-sided critical value at alpha = 0.01 over all the blocks and channels."""
    img, vimg, lo, vlo, hi, vhi = [read_pfm(p) for p in args[:6]]
    block = int(args[6]) if len(args) > 6 else 8
    w, h = img[0], img[1]
    regions = [[(x, y) for y in range(by, min(h, by + block)) for x in range(bx, min(w, bx + block))]
               for by in range(0, h, block) for bx in range(0, w, block)]
    regions.append([(x, y) for y in range(h) for x in range(w)])
    ntests = 3 * len(regions)
    alpha = 1 - (1 - 0.01) ** (1.0 / ntests)
    z = normal_quantile(1 - alpha)
    bad, where = 0, []
    for r in regions:
        for ch in range(3):
            m = lambda im: sum(im[2][3 * (y * w + x) + ch] for x, y in r) / len(r)
            v = lambda im: sum(im[2][3 * (y * w + x) + ch] for x, y in r) / len(r) ** 2
            a, l, u = m(img), m(lo), m(hi)
            lo_ok = a >= l - z * math.sqrt(v(img) + v(lo))
            hi_ok = a <= u + z * math.sqrt(v(img) + v(hi))
            if not (lo_ok and hi_ok):
                bad += 1
            if r is regions[-1]:
                where.append((a - l) / (u - l) if u != l else float("nan"))
    print("%d of %d block-channels outside [lo, hi] (one-sided z %.2f); whole image at %.3f %.3f %.3f of the way from lo to hi"
          % (bad, ntests, z, where[0], where[1], where[2]))
    return 1 if bad else 0


def normal_quantile(p):
    """Inverse of the standard normal cdf (bisection on erfc: plenty for a test)."""
    lo, hi = -40.0, 40.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if 0.5 * math.erfc(-mid / math.sqrt(2)) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


if __name__ == "__main__":
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "scenes":
        scenes(args[0])
    elif cmd == "mean":
        mean(args)
    elif cmd == "exact":
        sys.exit(exact(args))
    elif cmd == "between":
        sys.exit(between(args))
    else:
        sys.exit("gen.py: unknown command " + cmd)
