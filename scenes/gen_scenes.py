#!/usr/bin/env python3
"""gen_scenes.py — writes every file of pathlab's scenes/ folder (OBJ, MTL, view), reproducibly.

    python3 scenes/gen_scenes.py            # rewrite the scenes next to this script
    python3 scenes/gen_scenes.py --check    # rewrite nothing; fail if a file differs from what it would write

pathlab itself never runs this script (Python 3 standard library only). It also checks, while it
writes, that every triangle's front face, n = (b - a) x (c - a), points where it must: walls into the
room, blocks out of the block, emitters toward what they light. See scenes/README.md for the scenes.

The Cornell box colours are computed here from the measured spectra (tables below):
    XYZ = sum_l R(l) D65(l) cmf(l) / sum_l D65(l) ybar(l)      reflectances, lit by CIE D65
    XYZ = sum_l Le(l) cmf(l) / sum_l ybar(l)                   the light's emitted radiance
then linear sRGB = M XYZ, integrated every 1 nm over 380-780 nm with all tables linearly
interpolated and each measured spectrum held at its end value outside 400-700 nm.
"""
import math
import os
import sys

# ---------------------------------------------------------------------------------------------
# Data. Cornell box: "Cornell Box Data", Cornell University Program of Computer Graphics,
# https://www.graphics.cornell.edu/online/box/data.html (camera, geometry in mm, spectra).
# Reflectance spectra every 4 nm from 400 to 700 nm (76 samples).
CORNELL_WHITE = [
    0.343, 0.445, 0.551, 0.624, 0.665, 0.687, 0.708, 0.723, 0.715, 0.710, 0.745, 0.758, 0.739, 0.767, 0.777,
    0.765, 0.751, 0.745, 0.748, 0.729, 0.745, 0.757, 0.753, 0.750, 0.746, 0.747, 0.735, 0.732, 0.739, 0.734,
    0.725, 0.721, 0.733, 0.725, 0.732, 0.743, 0.744, 0.748, 0.728, 0.716, 0.733, 0.726, 0.713, 0.740, 0.754,
    0.764, 0.752, 0.736, 0.734, 0.741, 0.740, 0.732, 0.745, 0.755, 0.751, 0.744, 0.731, 0.733, 0.744, 0.731,
    0.712, 0.708, 0.729, 0.730, 0.727, 0.707, 0.703, 0.729, 0.750, 0.760, 0.751, 0.739, 0.724, 0.730, 0.740,
    0.737]
CORNELL_GREEN = [
    0.092, 0.096, 0.098, 0.097, 0.098, 0.095, 0.095, 0.097, 0.095, 0.094, 0.097, 0.098, 0.096, 0.101, 0.103,
    0.104, 0.107, 0.109, 0.112, 0.115, 0.125, 0.140, 0.160, 0.187, 0.229, 0.285, 0.343, 0.390, 0.435, 0.464,
    0.472, 0.476, 0.481, 0.462, 0.447, 0.441, 0.426, 0.406, 0.373, 0.347, 0.337, 0.314, 0.285, 0.277, 0.266,
    0.250, 0.230, 0.207, 0.186, 0.171, 0.160, 0.148, 0.141, 0.136, 0.130, 0.126, 0.123, 0.121, 0.122, 0.119,
    0.114, 0.115, 0.117, 0.117, 0.118, 0.120, 0.122, 0.128, 0.132, 0.139, 0.144, 0.146, 0.150, 0.152, 0.157,
    0.159]
CORNELL_RED = [
    0.040, 0.046, 0.048, 0.053, 0.049, 0.050, 0.053, 0.055, 0.057, 0.056, 0.059, 0.057, 0.061, 0.061, 0.060,
    0.062, 0.062, 0.062, 0.061, 0.062, 0.060, 0.059, 0.057, 0.058, 0.058, 0.058, 0.056, 0.055, 0.056, 0.059,
    0.057, 0.055, 0.059, 0.059, 0.058, 0.059, 0.061, 0.061, 0.063, 0.063, 0.067, 0.068, 0.072, 0.080, 0.090,
    0.099, 0.124, 0.154, 0.192, 0.255, 0.287, 0.349, 0.402, 0.443, 0.487, 0.513, 0.558, 0.584, 0.620, 0.606,
    0.609, 0.651, 0.612, 0.610, 0.650, 0.638, 0.627, 0.620, 0.630, 0.628, 0.642, 0.639, 0.657, 0.639, 0.635,
    0.642]
# The light's emission spectrum, given at 400, 500, 600 and 700 nm.
CORNELL_LIGHT = [(400, 0.0), (500, 8.0), (600, 15.6), (700, 18.4)]

# CIE 1931 2-degree standard observer, every 5 nm from 380 to 780 nm (CIE 015:2004 table; the same
# numbers as CVRL's ciexyz31 at 5 nm).
CIE_1931 = [
    (0.001368, 0.000039, 0.006450), (0.002236, 0.000064, 0.010550), (0.004243, 0.000120, 0.020050),
    (0.007650, 0.000217, 0.036210), (0.014310, 0.000396, 0.067850), (0.023190, 0.000640, 0.110200),
    (0.043510, 0.001210, 0.207400), (0.077630, 0.002180, 0.371300), (0.134380, 0.004000, 0.645600),
    (0.214770, 0.007300, 1.039050), (0.283900, 0.011600, 1.385600), (0.328500, 0.016840, 1.622960),
    (0.348280, 0.023000, 1.747060), (0.348060, 0.029800, 1.782600), (0.336200, 0.038000, 1.772110),
    (0.318700, 0.048000, 1.744100), (0.290800, 0.060000, 1.669200), (0.251100, 0.073900, 1.528100),
    (0.195360, 0.090980, 1.287640), (0.142100, 0.112600, 1.041900), (0.095640, 0.139020, 0.812950),
    (0.057950, 0.169300, 0.616200), (0.032010, 0.208020, 0.465180), (0.014700, 0.258600, 0.353300),
    (0.004900, 0.323000, 0.272000), (0.002400, 0.407300, 0.212300), (0.009300, 0.503000, 0.158200),
    (0.029100, 0.608200, 0.111700), (0.063270, 0.710000, 0.078250), (0.109600, 0.793200, 0.057250),
    (0.165500, 0.862000, 0.042160), (0.225750, 0.914850, 0.029840), (0.290400, 0.954000, 0.020300),
    (0.359700, 0.980300, 0.013400), (0.433450, 0.994950, 0.008750), (0.512050, 1.000000, 0.005750),
    (0.594500, 0.995000, 0.003900), (0.678400, 0.978600, 0.002750), (0.762100, 0.952000, 0.002100),
    (0.842500, 0.915400, 0.001800), (0.916300, 0.870000, 0.001650), (0.978600, 0.816300, 0.001400),
    (1.026300, 0.757000, 0.001100), (1.056700, 0.694900, 0.001000), (1.062200, 0.631000, 0.000800),
    (1.045600, 0.566800, 0.000600), (1.002600, 0.503000, 0.000340), (0.938400, 0.441200, 0.000240),
    (0.854450, 0.381000, 0.000190), (0.751400, 0.321000, 0.000100), (0.642400, 0.265000, 0.000050),
    (0.541900, 0.217000, 0.000030), (0.447900, 0.175000, 0.000020), (0.360800, 0.138200, 0.000010),
    (0.283500, 0.107000, 0.000000), (0.218700, 0.081600, 0.000000), (0.164900, 0.061000, 0.000000),
    (0.121200, 0.044580, 0.000000), (0.087400, 0.032000, 0.000000), (0.063600, 0.023200, 0.000000),
    (0.046770, 0.017000, 0.000000), (0.032900, 0.011920, 0.000000), (0.022700, 0.008210, 0.000000),
    (0.015840, 0.005723, 0.000000), (0.011359, 0.004102, 0.000000), (0.008111, 0.002929, 0.000000),
    (0.005790, 0.002091, 0.000000), (0.004109, 0.001484, 0.000000), (0.002899, 0.001047, 0.000000),
    (0.002049, 0.000740, 0.000000), (0.001440, 0.000520, 0.000000), (0.001000, 0.000361, 0.000000),
    (0.000690, 0.000249, 0.000000), (0.000476, 0.000172, 0.000000), (0.000332, 0.000120, 0.000000),
    (0.000235, 0.000085, 0.000000), (0.000166, 0.000060, 0.000000), (0.000117, 0.000042, 0.000000),
    (0.000083, 0.000030, 0.000000), (0.000059, 0.000021, 0.000000), (0.000042, 0.000015, 0.000000)]
# CIE standard illuminant D65, relative spectral power every 5 nm from 380 to 780 nm (CIE table).
D65 = [
    49.9755, 52.3118, 54.6482, 68.7015, 82.7549, 87.1204, 91.4860, 92.4589, 93.4318, 90.0570, 86.6823,
    95.7736, 104.865, 110.936, 117.008, 117.410, 117.812, 116.336, 114.861, 115.392, 115.923, 112.367,
    108.811, 109.082, 109.354, 108.578, 107.802, 106.296, 104.790, 106.239, 107.689, 106.047, 104.405,
    104.225, 104.046, 102.023, 100.000, 98.1671, 96.3342, 96.0611, 95.7880, 92.2368, 88.6856, 89.3459,
    90.0062, 89.8026, 89.5991, 88.6489, 87.6987, 85.4936, 83.2886, 83.4939, 83.6992, 81.8630, 80.0268,
    80.1207, 80.2146, 81.2462, 82.2778, 80.2810, 78.2842, 74.0027, 69.7213, 70.6652, 71.6091, 72.9790,
    74.3490, 67.9765, 61.6040, 65.7448, 69.8856, 72.4863, 75.0870, 69.3398, 63.5927, 55.0054, 46.4182,
    56.6118, 66.8054, 65.0941, 63.3828]
# sRGB (ITU-R BT.709) primaries, chromaticity xy.
SRGB_PRIMARIES = [(0.64, 0.33), (0.30, 0.60), (0.15, 0.06)]

# ---------------------------------------------------------------------------------------------
# Colour: spectra to linear sRGB.

def interp(samples, lam):
    """Piecewise linear through (wavelength, value) pairs, held at the end values outside."""
    if lam <= samples[0][0]:
        return samples[0][1]
    for (l0, v0), (l1, v1) in zip(samples, samples[1:]):
        if lam <= l1:
            return v0 + (v1 - v0) * (lam - l0) / (l1 - l0)
    return samples[-1][1]

def table(start, step, values):
    return [(start + step * i, v) for i, v in enumerate(values)]

CMF = [table(380, 5, [c[k] for c in CIE_1931]) for k in range(3)]
D65_SPD = table(380, 5, D65)
LAMBDAS = range(380, 781)   # 1 nm steps

def xyz_of(spd, illuminant=None):
    """Tristimulus of spd (radiance) or, with an illuminant, of a reflectance lit by it; Y of the
    illuminant (or of a flat unit radiance) is 1."""
    sums, norm = [0.0, 0.0, 0.0], 0.0
    for lam in LAMBDAS:
        light = interp(illuminant, lam) if illuminant else 1.0
        value = interp(spd, lam) * light
        for k in range(3):
            sums[k] += value * interp(CMF[k], lam)
        norm += light * interp(CMF[1], lam)
    return [s / norm for s in sums]

def inverse3(m):
    (a, b, c), (d, e, f), (g, h, i) = m
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]

def mul3(m, v):
    return [sum(m[r][k] * v[k] for k in range(3)) for r in range(3)]

def xyz_to_srgb_matrix(white):
    """XYZ -> linear sRGB from the primaries and the white point, derived rather than copied so that
    the white is exactly our integrated D65: a spectrally flat reflectance becomes R = G = B."""
    cols = [[x / y, 1.0, (1.0 - x - y) / y] for x, y in SRGB_PRIMARIES]
    p = [[cols[c][r] for c in range(3)] for r in range(3)]
    s = mul3(inverse3(p), white)
    rgb_to_xyz = [[p[r][c] * s[c] for c in range(3)] for r in range(3)]
    return inverse3(rgb_to_xyz)

D65_WHITE = xyz_of(table(380, 5, [1.0] * 81), D65_SPD)      # [x, 1, z]
XYZ_TO_SRGB = xyz_to_srgb_matrix(D65_WHITE)

def reflectance_rgb(values):
    return mul3(XYZ_TO_SRGB, xyz_of(table(400, 4, values), D65_SPD))

def radiance_rgb(samples):
    return mul3(XYZ_TO_SRGB, xyz_of(samples))

# ---------------------------------------------------------------------------------------------
# Geometry helpers. A Mesh holds vertices, triangles as 1-based vertex indices, and named parts
# (a run of triangles with one material, written as "o name" + "usemtl material").

def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def centroid(ps): return [sum(p[k] for p in ps) / len(ps) for k in range(3)]

class Mesh:
    def __init__(self):
        self.P, self.tris, self.parts = [], [], []    # parts: (name, material, first tri, count)

    def vertex(self, p):
        self.P.append([float(x) for x in p])
        return len(self.P)                             # OBJ indices start at 1

    def add(self, name, material, tris_as_points, faces_toward):
        """Adds triangles given as point triples whose fronts must face faces_toward(centroid):
        a direction vector. Returns how many had to be reversed (0 when the data's order was right)."""
        first, flipped = len(self.tris), 0
        for a, b, c in tris_as_points:
            n = cross(sub(b, a), sub(c, a))
            if dot(n, faces_toward(centroid([a, b, c]))) < 0:
                b, c = c, b
                flipped += 1
            self.tris.append([self.vertex(a), self.vertex(b), self.vertex(c)])
        self.parts.append((name, material, first, len(self.tris) - first))
        return flipped

def quad(p):
    """Two triangles of a quad p0 p1 p2 p3: a fan from p0. The published quads are convex; the red wall
    is slightly twisted (not planar), and this fixes which diagonal it folds along."""
    return [(p[0], p[1], p[2]), (p[0], p[2], p[3])]

def away_from(c): return lambda x: sub(x, c)
def toward(c): return lambda x: sub(c, x)
def along(d): return lambda x: d

def obj_text(mesh, header, mtllib):
    """OBJ text with shared vertices (exact duplicates merged, so neighbouring faces share edges)."""
    index, P, remap = {}, [], {}
    for i, p in enumerate(mesh.P, 1):
        key = tuple(fmt(x) for x in p)
        if key not in index:
            P.append(key)
            index[key] = len(P)
        remap[i] = index[key]
    out = ["# " + line if line else "#" for line in header] + ["mtllib " + mtllib, ""]
    out += ["v %s %s %s" % p for p in P]
    for name, material, first, count in mesh.parts:
        out += ["", "o " + name, "usemtl " + material]
        out += ["f %d %d %d" % tuple(remap[i] for i in t) for t in mesh.tris[first:first + count]]
    return "\n".join(out) + "\n"

def fmt(x):
    s = "%.9g" % x
    return "0" if s == "-0" else s

def rgb(c):
    return " ".join("%.4f" % x for x in c)

def mtl_text(header, materials):
    out = ["# " + line if line else "#" for line in header]
    for name, m in materials:
        out += ["", "newmtl " + name]
        for key in ("Kd", "Ks", "Ns", "Ke"):
            if key in m:
                out.append("%s %s" % (key, m[key] if key == "Ns" else rgb(m[key])))
    return "\n".join(out) + "\n"

def view_text(header, eye, target, up, fov, size, fov_note):
    out = ["# pathlab view"] + ["# " + line for line in header]
    out += ["eye %s %s %s" % tuple(fmt(x) for x in eye), "target %s %s %s" % tuple(fmt(x) for x in target),
            "up %s %s %s" % tuple(fmt(x) for x in up), "# " + fov_note, "fov %s" % fmt(fov),
            "# width height in pixels", "size %d %d" % size]
    return "\n".join(out) + "\n"

# ---------------------------------------------------------------------------------------------
# The Cornell box (published geometry, mm).

FLOOR = [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]
CEILING = [(556.0, 548.8, 0), (556.0, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)]
BACK = [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556.0, 548.8, 559.2)]
RIGHT_GREEN = [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]
LEFT_RED = [(552.8, 0, 0), (549.6, 0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0)]
LIGHT = [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0), (213.0, 548.8, 227.0)]
SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)]]
TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)]]

def ceiling_with_hole(outer, hole):
    """The ceiling minus the light's rectangle: four trapezoids between the outer edge and the hole,
    two triangles each, so that the light sits in the ceiling's plane without overlapping it."""
    # pair each outer corner with the nearest hole corner (both are listed in the same turning order)
    tris = []
    for i in range(4):
        o0, o1 = outer[i], outer[(i + 1) % 4]
        h0 = min(hole, key=lambda h: (h[0] - o0[0]) ** 2 + (h[2] - o0[2]) ** 2)
        h1 = min(hole, key=lambda h: (h[0] - o1[0]) ** 2 + (h[2] - o1[2]) ** 2)
        tris += [(o0, o1, h1), (o0, h1, h0)]
    return tris

def cornell_mesh(report):
    m = Mesh()
    room = centroid(FLOOR + CEILING)
    flips = {}
    flips["floor"] = m.add("floor", "floor", quad(FLOOR), toward(room))
    flips["ceiling"] = m.add("ceiling", "ceiling", ceiling_with_hole(CEILING, LIGHT), toward(room))
    flips["back_wall"] = m.add("back_wall", "back_wall", quad(BACK), toward(room))
    flips["right_wall_green"] = m.add("right_wall_green", "green", quad(RIGHT_GREEN), toward(room))
    flips["left_wall_red"] = m.add("left_wall_red", "red", quad(LEFT_RED), toward(room))
    for name, faces in (("short_block", SHORT_BLOCK), ("tall_block", TALL_BLOCK)):
        inside = centroid([p for f in faces for p in f])
        inside[1] = faces[0][0][1] / 2          # half way up: the faces list has no bottom
        flips[name] = m.add(name, name, [t for f in faces for t in quad(f)], away_from(inside))
    flips["light"] = m.add("light", "light", quad(LIGHT), along([0, -1, 0]))
    report.append("cornell: triangles reversed to face the right way: %s" %
                  ", ".join("%s %d" % kv for kv in flips.items()))
    return m

def cornell_colours():
    white, red, green = (reflectance_rgb(s) for s in (CORNELL_WHITE, CORNELL_RED, CORNELL_GREEN))
    return white, red, green, radiance_rgb(CORNELL_LIGHT)

CORNELL_SOURCE = [
    "Source: \"Cornell Box Data\", Cornell University Program of Computer Graphics,",
    "https://www.graphics.cornell.edu/online/box/data.html (geometry in mm, spectra).",
]

def cornell_mtl_header(title):
    return [title] + CORNELL_SOURCE + [
        "Colours computed by scenes/gen_scenes.py from the measured spectra, not guessed:",
        "  reflectances: lit by CIE illuminant D65, integrated against the CIE 1931 2-degree observer",
        "  every 1 nm (380-780 nm, spectra held at their 400/700 nm values outside 400-700 nm),",
        "  normalised so a perfect white has Y = 1, then XYZ -> linear sRGB (BT.709 primaries, white =",
        "  the integrated D65, so a flat reflectance gives R = G = B).",
        "  light: its emission spectrum (0, 8, 15.6, 18.4 at 400, 500, 600, 700 nm, linear between,",
        "  18.4 above 700 nm) the same way without an illuminant, normalised by the integral of ybar,",
        "  so Y is the ybar-weighted mean of the spectrum.",
        "For comparison, the RGB values common in renderers (e.g. Tungsten's Cornell box):",
        "  white 0.725 0.71 0.68, red 0.63 0.065 0.05, green 0.14 0.45 0.091, light Ke 17 12 4.",
        "Light Kd 0.78 (grey) as in Mitsuba's cbox scene; the Cornell page gives no light reflectance.",
    ]

def cornell_files(report):
    white, red, green, light = cornell_colours()
    report.append("cornell: white %s  red %s  green %s  light %s" % (rgb(white), rgb(red), rgb(green), rgb(light)))
    mesh = cornell_mesh(report)
    header = ["The Cornell box as published: floor, ceiling, back wall, left (red) and right (green) walls,",
              "short and tall blocks, the light. Millimetres; the front (z = 0) is open, the camera at z = -800.",
              "The light lies in the ceiling's plane (y = 548.8, as published) in a hole cut out of the",
              "ceiling; it emits downward. Walls and ceiling face into the room, blocks face out of themselves."]
    header += CORNELL_SOURCE + ["Generated by scenes/gen_scenes.py; do not edit by hand."]
    diffuse = lambda kd: {"Kd": kd, "Ks": [0, 0, 0], "Ns": 1}
    base = {"floor": diffuse(white), "ceiling": diffuse(white), "back_wall": diffuse(white),
            "short_block": diffuse(white), "tall_block": diffuse(white), "red": diffuse(red),
            "green": diffuse(green), "light": {"Kd": [0.78] * 3, "Ks": [0, 0, 0], "Ns": 1, "Ke": light}}
    order = ["floor", "ceiling", "back_wall", "red", "green", "short_block", "tall_block", "light"]
    # Glossy: Blinn lobes on the blocks and the floor, Kd scaled down so that Kd + Ks <= 1.
    glossy = dict(base)
    for name, ks, ns in (("tall_block", 0.3, 20), ("short_block", 0.3, 200), ("floor", 0.1, 1000)):
        glossy[name] = {"Kd": [c * (1 - ks) for c in white], "Ks": [ks] * 3, "Ns": ns}
    for m in glossy.values():
        assert all(kd + ks <= 1.0 for kd, ks in zip(m["Kd"], m["Ks"]))
    view = view_text(["Cornell box camera as published: at (278, 273, -800) looking along +z, up +y,",
                      "focal length 35 mm on a 25 mm x 25 mm film."],
                     (278, 273, -800), (278, 273, 0), (0, 1, 0), 2 * math.degrees(math.atan(12.5 / 35)),
                     (512, 512), "vertical field of view, degrees: 2 atan(12.5 / 35) = 39.3076")
    files = {
        "cornell.obj": obj_text(mesh, header, "cornell.mtl"),
        "cornell.mtl": mtl_text(cornell_mtl_header("Cornell box materials (Lambertian, as measured)."),
                                [(n, base[n]) for n in order]),
        "cornell.view": view,
        "cornell-glossy.obj": obj_text(mesh, header[:1] + ["Same geometry as cornell.obj; glossy materials."]
                                       + header[1:], "cornell-glossy.mtl"),
        "cornell-glossy.mtl": mtl_text(cornell_mtl_header(
            "Cornell box with Blinn lobes: tall block Ns 20 Ks 0.3, short block Ns 200 Ks 0.3, floor Ns 1000 "
            "Ks 0.1; their Kd is the white's times (1 - Ks)."),
            [(n, glossy[n]) for n in order]),
        "cornell-glossy.view": view,
    }
    return files, mesh

# ---------------------------------------------------------------------------------------------
# Test scenes with known answers.

def box_faces(lo, hi):
    """The 6 faces of an axis-aligned box as quads (any winding; add() orients them)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [[(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],   # bottom
            [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],   # top
            [(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)],   # x = x0
            [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],   # x = x1
            [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],   # z = z0
            [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]]   # z = z1

def furnace_files(report):
    m = Mesh()
    m.add("box", "furnace", [t for f in box_faces((-1, -1, -1), (1, 1, 1)) for t in quad(f)], toward([0, 0, 0]))
    header = ["Furnace: the inside of a closed cube [-1, 1]^3, every face diffuse Kd = 0.5 and emitting",
              "Ke = 1 toward the inside. Radiance after k bounces: L_k = Le a^k = 0.5^k, total L = Le / (1 - a) = 2.",
              "Generated by scenes/gen_scenes.py."]
    return {"furnace.obj": obj_text(m, header, "furnace.mtl"),
            "furnace.mtl": mtl_text(["Furnace material: Kd + Ks = 0.5 <= 1, emits 1 on its front (inner) side."],
                                    [("furnace", {"Kd": [0.5] * 3, "Ks": [0] * 3, "Ns": 1, "Ke": [1] * 3})]),
            "furnace.view": view_text(["From the centre of the cube toward the +z wall."], (0, 0, 0), (0, 0, 1),
                                      (0, 1, 0), 60, (256, 256), "vertical field of view, degrees")}, m

def quad_light_files(report):
    m = Mesh()
    m.add("plane", "plane", quad([(-10, 0, -10), (10, 0, -10), (10, 0, 10), (-10, 0, 10)]), along([0, 1, 0]))
    m.add("light", "light", quad([(-0.5, 1, -0.5), (0.5, 1, -0.5), (0.5, 1, 0.5), (-0.5, 1, 0.5)]),
          along([0, -1, 0]))
    header = ["Quad light: a 1 x 1 square at y = 1 centred over the origin, emitting Ke = 10 downward, over a",
              "20 x 20 diffuse plane (Kd = 0.5, y = 0, normal up). Nothing else: direct light only, one bounce.",
              "On the plane, E(x) = Le * sum over the square's edges of Lambert's polygon formula and",
              "L(x) = Kd / pi * E(x) (light reflected by the plane back to the square escapes: it is one-sided",
              "and black, Kd = 0, on both sides).",
              "Generated by scenes/gen_scenes.py."]
    mtl = mtl_text(["Quad light materials."],
                   [("plane", {"Kd": [0.5] * 3, "Ks": [0] * 3, "Ns": 1}),
                    ("light", {"Kd": [0] * 3, "Ks": [0] * 3, "Ns": 1, "Ke": [10] * 3})])
    view = view_text(["Looking down at the lit plane at about 28 degrees, from just below the light's height:",
                      "the whole frustum points below the horizon, so every pixel sees the plane and none sees",
                      "the light (whose back, seen from above, would be black)."],
                     (0, 0.95, -1.6), (0, 0, 0.2), (0, 1, 0), 40, (256, 256), "vertical field of view, degrees")
    return {"quad-light.obj": obj_text(m, header, "quad-light.mtl"), "quad-light.mtl": mtl,
            "quad-light.view": view}, m

def icosphere(levels):
    t = (1 + math.sqrt(5)) / 2
    P = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    unit = lambda p: [x / math.sqrt(dot(p, p)) for x in p]
    P = [unit(p) for p in P]
    for _ in range(levels):
        mid, F2 = {}, []
        def midpoint(i, j):
            key = (min(i, j), max(i, j))
            if key not in mid:
                P.append(unit([(a + b) / 2 for a, b in zip(P[i], P[j])]))
                mid[key] = len(P) - 1
            return mid[key]
        for a, b, c in F:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            F2 += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        F = F2
    return P, F

def sphere_furnace_files(report):
    P, F = icosphere(4)
    m = Mesh()
    m.add("sphere", "sphere", [(P[a], P[b], P[c]) for a, b, c in F], toward([0, 0, 0]))
    header = ["Sphere furnace (pbrt-v4's integrator test): the inside of a unit icosphere (4 subdivisions,",
              "%d triangles), diffuse Kd = 0.5, emitting Le = 0.5 inward. Any closed diffuse enclosure with" % len(F),
              "uniform Le and albedo a has radiance Le / (1 - a) = 1 everywhere, in every direction.",
              "Generated by scenes/gen_scenes.py."]
    return {"sphere-furnace.obj": obj_text(m, header, "sphere-furnace.mtl"),
            "sphere-furnace.mtl": mtl_text(["Sphere furnace material."],
                                           [("sphere", {"Kd": [0.5] * 3, "Ks": [0] * 3, "Ns": 1, "Ke": [0.5] * 3})]),
            "sphere-furnace.view": view_text(["At the centre of the sphere."], (0, 0, 0), (0, 0, 1), (0, 1, 0), 90,
                                             (256, 256), "vertical field of view, degrees")}, m

# ---------------------------------------------------------------------------------------------
# Veach's multiple importance sampling scene (Veach 1997, the idea of fig. 9.2; our own geometry).

def unit3(v):
    n = math.sqrt(dot(v, v))
    return [x / n for x in v]

def add3(a, b): return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
def mul(v, s): return [x * s for x in v]

MIS_EYE = [0.0, 2.0, 15.0]
MIS_TARGET = [0.0, -0.8, 2.0]
MIS_LIGHT_ROW = [0.0, 3.0, -1.5]          # the lights' centres lie on the line y = 3, z = -1.5
MIS_LIGHTS = [(-3.75, 0.06), (-1.25, 0.2), (1.25, 0.6), (3.75, 1.8)]   # (x, side of the square)
MIS_POWER = 16.0                           # Ke * side^2: the same emitted power for each light
MIS_PLATES = [((0.0, -3.6, 4.4), 10, 0.8), ((0.0, -3.0, 2.9), 50, 0.8), ((0.0, -2.3, 1.5), 300, 0.85),
              ((0.0, -1.5, 0.2), 2000, 0.9)]  # (centre, Ns, Ks), rough near the camera, sharp far
MIS_PLATE_HALF = (4.0, 0.5)                # half width (x), half depth

def mis_plates_files(report):
    m = Mesh()
    xaxis = [1.0, 0.0, 0.0]
    mats = []
    for i, (centre, ns, ks) in enumerate(MIS_PLATES):
        c = list(centre)
        # The mirror normal: halfway between the directions to the eye and to the middle of the light
        # row, so that every plate shows the four lights side by side in its middle.
        n = unit3(add3(unit3(sub(MIS_EYE, c)), unit3(sub(MIS_LIGHT_ROW, c))))
        t = cross(n, xaxis)                  # in the plate, across its width
        hw, hd = MIS_PLATE_HALF
        corners = [add3(add3(c, mul(xaxis, sx * hw)), mul(t, sy * hd)) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        name = "plate%d" % (i + 1)
        m.add(name, name, quad(corners), along(n))
        mats.append((name, {"Kd": [0.05] * 3, "Ks": [ks] * 3, "Ns": ns}))
        assert 0.05 + ks <= 1.0
    aim = centroid([list(p[0]) for p in MIS_PLATES])
    for j, (x, side) in enumerate(MIS_LIGHTS):
        c = [x, MIS_LIGHT_ROW[1], MIS_LIGHT_ROW[2]]
        d = unit3(sub(aim, c))               # each light faces the middle of the plates
        u = unit3(cross(d, xaxis))
        v = cross(d, u)
        h = side / 2
        corners = [add3(add3(c, mul(u, a * h)), mul(v, b * h)) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        name = "light%d" % (j + 1)
        m.add(name, name, quad(corners), along(d))
        mats.append((name, {"Kd": [0] * 3, "Ks": [0] * 3, "Ns": 1, "Ke": [MIS_POWER / side ** 2] * 3}))
    # A dark backdrop: a floor under the plates and a wall behind the lights, both facing the scene.
    m.add("floor", "backdrop", quad([(-12, -4.5, -4), (12, -4.5, -4), (12, -4.5, 16), (-12, -4.5, 16)]), along([0, 1, 0]))
    m.add("wall", "backdrop", quad([(-12, -4.5, -4), (12, -4.5, -4), (12, 8, -4), (-12, 8, -4)]), along([0, 0, 1]))
    mats.append(("backdrop", {"Kd": [0.1] * 3, "Ks": [0] * 3, "Ns": 1}))
    header = ["mis-plates: Veach's multiple importance sampling scene (Veach 1997, the idea of fig. 9.2).",
              "Four glossy plates, Ns = 10, 50, 300, 2000 from the nearest to the farthest, each tilted to",
              "mirror the middle of a row of four square lights (sides 0.06, 0.2, 0.6, 1.8, Ke = 16 / side^2:",
              "the same power each) toward the eye. A dark diffuse floor and back wall. Light sampling is",
              "noisy on the sharp plates, BRDF sampling on the rough plates for the small lights, MIS is not.",
              "Generated by scenes/gen_scenes.py."]
    view = view_text(["Looking down at the plates from in front of them; the lights are above and behind."],
                     MIS_EYE, MIS_TARGET, (0, 1, 0), 40, (512, 512), "vertical field of view, degrees")
    return {"mis-plates.obj": obj_text(m, header, "mis-plates.mtl"),
            "mis-plates.mtl": mtl_text(["mis-plates materials: plates Kd 0.05 + Ks <= 1, lights black and one-sided."],
                                       mats),
            "mis-plates.view": view}, m

# ---------------------------------------------------------------------------------------------
# Many lights: a hall whose ceiling is a grid of small lamps of many colours and strengths.

MANY_HALF = 18.0                     # the hall: x in [-18, 18], z in [0, 36], y in [0, 3]
MANY_HEIGHT = 3.0
MANY_GRID = 72                       # 72 x 72 ceiling lamps, 0.5 apart
MANY_LAMP = 0.05                     # half side of a lamp
MANY_STRENGTHS = [0.2, 0.6, 2, 6, 20, 60]
MANY_COLOURS = [[1, 1, 1], [1, 0.8, 0.6], [0.6, 0.8, 1], [1, 0.4, 0.3], [0.4, 1, 0.5], [0.5, 0.5, 1],
                [1, 1, 0.4], [1, 0.5, 1]]
MANY_BLOCKS = [((-3, 0, 5), (-2, 1.2, 6)), ((1.5, 0, 6), (2.5, 2.2, 7)), ((-1, 0, 9), (1, 0.8, 11)),
               ((10, 0, 22), (14, 1.6, 26)), ((-14, 0, 28), (-10, 2.6, 30)), ((0, 0, 30), (4, 1.0, 33))]

def many_lights_files(report):
    m = Mesh()
    h, H = MANY_HALF, MANY_HEIGHT
    m.add("floor", "white", quad([(-h, 0, 0), (h, 0, 0), (h, 0, 2 * h), (-h, 0, 2 * h)]), along([0, 1, 0]))
    m.add("ceiling", "grey", quad([(-h, H, 0), (h, H, 0), (h, H, 2 * h), (-h, H, 2 * h)]), along([0, -1, 0]))
    walls = [[(-h, 0, 0), (-h, H, 0), (-h, H, 2 * h), (-h, 0, 2 * h)], [(h, 0, 0), (h, H, 0), (h, H, 2 * h), (h, 0, 2 * h)],
             [(-h, 0, 0), (h, 0, 0), (h, H, 0), (-h, H, 0)], [(-h, 0, 2 * h), (h, 0, 2 * h), (h, H, 2 * h), (-h, H, 2 * h)]]
    m.add("walls", "grey", [t for w in walls for t in quad(w)], toward([0, H / 2, h]))
    for i, (lo, hi) in enumerate(MANY_BLOCKS):
        m.add("block%d" % (i + 1), "white", [t for f in box_faces(lo, hi) for t in quad(f)],
              away_from(centroid([list(lo), list(hi)])))
    # Lamps: a fixed pseudo-random material each (a linear congruential generator: reproducible),
    # grouped by material. Ceiling lamps 1 mm below the ceiling, facing down; two rows of wall lamps
    # facing into the hall.
    state, lamps = [12345], {}
    def rand(n):
        state[0] = (1103515245 * state[0] + 12345) % 2 ** 31
        return (state[0] >> 8) % n
    step, e = 2 * h / MANY_GRID, MANY_LAMP
    for i in range(MANY_GRID):
        for j in range(MANY_GRID):
            x, z, y = -h + step * (i + 0.5), step * (j + 0.5), H - 0.001
            lamps.setdefault(rand(len(MANY_COLOURS) * len(MANY_STRENGTHS)), []).append(
                ([(x - e, y, z - e), (x + e, y, z - e), (x + e, y, z + e), (x - e, y, z + e)], [0, -1, 0]))
    for side in (-1, 1):
        for j in range(48):
            x, z, y = side * (h - 0.001), 0.75 * (j + 0.5), 1.8
            lamps.setdefault(rand(len(MANY_COLOURS) * len(MANY_STRENGTHS)), []).append(
                ([(x, y - e, z - e), (x, y + e, z - e), (x, y + e, z + e), (x, y - e, z + e)], [-side, 0, 0]))
    mats = [("white", {"Kd": [0.5] * 3, "Ks": [0] * 3, "Ns": 1}), ("grey", {"Kd": [0.2] * 3, "Ks": [0] * 3, "Ns": 1})]
    for k in sorted(lamps):
        name = "lamp%02d" % k
        colour, strength = MANY_COLOURS[k % len(MANY_COLOURS)], MANY_STRENGTHS[k // len(MANY_COLOURS)]
        for n in ([0, -1, 0], [1, 0, 0], [-1, 0, 0]):   # one group per material and facing
            tris = [t for corners, d in lamps[k] if d == n for t in quad(corners)]
            if tris:
                m.add(name, name, tris, along(n))
        mats.append((name, {"Kd": [0] * 3, "Ks": [0] * 3, "Ns": 1, "Ke": [c * strength for c in colour]}))
    nlamps = sum(len(v) for v in lamps.values())
    header = ["many-lights: a hall 36 x 3 x 36 lit by %d small square lamps (%d emitting triangles):" % (nlamps, 2 * nlamps),
              "a %d x %d grid on the ceiling facing down and two rows on the side walls facing in, each of" % (MANY_GRID, MANY_GRID),
              "one of %d colours and %d strengths (Ke from 0.2 to 60 times the colour), a few diffuse blocks." % (
                  len(MANY_COLOURS), len(MANY_STRENGTHS)),
              "For choosing among many lights (--light tree against --light power).",
              "Generated by scenes/gen_scenes.py."]
    view = view_text(["From near the front wall, looking down at the floor and the blocks: no lamp is in view (a lamp",
                      "seen directly is noise that no choice of light changes)."], (0, 2.2, 2), (0, 0, 6), (0, 1, 0), 40,
                     (320, 240), "vertical field of view, degrees")
    return {"many-lights.obj": obj_text(m, header, "many-lights.mtl"),
            "many-lights.mtl": mtl_text(["many-lights materials: white and grey diffuse, lamps black and one-sided."], mats),
            "many-lights.view": view}, m

# ---------------------------------------------------------------------------------------------

def main():
    here = os.path.dirname(os.path.abspath(__file__))
    check = "--check" in sys.argv[1:]
    report, files = [], {}
    for make in (cornell_files, furnace_files, quad_light_files, sphere_furnace_files, mis_plates_files,
                 many_lights_files):
        f, _ = make(report)
        files.update(f)
    differ = []
    for name, text in sorted(files.items()):
        path = os.path.join(here, name)
        if check:
            old = open(path).read() if os.path.exists(path) else None
            if old != text:
                differ.append(name)
        else:
            with open(path + ".tmp", "w") as fp:
                fp.write(text)
            os.replace(path + ".tmp", path)
    for line in report:
        print(line)
    if check and differ:
        print("differs from what gen_scenes.py writes: " + ", ".join(differ))
        return 1
    print("%s %d files in %s" % ("checked" if check else "wrote", len(files), here))
    return 0

if __name__ == "__main__":
    sys.exit(main())
