#!/usr/bin/env python3
"""tests/materials/px.py FILE.pfm [X Y | stats] — prints a PFM's pixel (x, y), y from the top, as
"r g b"; with stats "min max nonfinite" over every value; without either every pixel, one row a
line from the top. For tests/test_materials.sh and tests/stress/run.sh."""
import math
import struct, sys

d = open(sys.argv[1], "rb").read()
head = d.split(b"\n", 3)
w, h = (int(x) for x in head[1].split())
little = float(head[2]) < 0
v = struct.unpack(("<" if little else ">") + "%df" % (3 * w * h), head[3][:12 * w * h])
def px(x, y):
    i = 3 * ((h - 1 - y) * w + x)   # rows are stored bottom to top
    return v[i:i + 3]
if len(sys.argv) == 3 and sys.argv[2] == "stats":
    fin = [x for x in v if math.isfinite(x)]
    print("%.6g %.6g %d" % (min(fin), max(fin), len(v) - len(fin)))
elif len(sys.argv) > 3:
    print("%.6g %.6g %.6g" % px(int(sys.argv[2]), int(sys.argv[3])))
else:
    for y in range(h):
        print(" ".join("%.4g,%.4g,%.4g" % px(x, y) for x in range(w)))
