#!/usr/bin/env python3
"""tests/materials/jump.py FILE.pfm — the largest jump of luminance between vertical neighbours
inside the middle half of the image, divided by the mean there: a faceted sphere's face edges (its
latitude bands, under a light above) make it large, a smooth one's shading keeps it near the noise. For tests/test_materials.sh."""
import struct, sys

d = open(sys.argv[1], "rb").read()
head = d.split(b"\n", 3)
w, h = (int(x) for x in head[1].split())
v = struct.unpack("<%df" % (3 * w * h), head[3][:12 * w * h])
lum = [0.2126 * v[3 * i] + 0.7152 * v[3 * i + 1] + 0.0722 * v[3 * i + 2] for i in range(w * h)]
ys, xs = range(h // 4, 3 * h // 4 - 1), range(w // 4, 3 * w // 4)
mean = sum(lum[y * w + x] for y in ys for x in xs) / (len(ys) * len(xs))
print("%.4f" % (max(abs(lum[(y + 1) * w + x] - lum[y * w + x]) for y in ys for x in xs) / mean))
