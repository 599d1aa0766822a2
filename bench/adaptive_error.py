#!/usr/bin/env python3
"""bench/adaptive_error.py REF.pfm REF_VAR.pfm IMAGE.pfm... — the error of each IMAGE against a
reference, with the reference's own noise taken out: MSE = mean over pixel-channels of (a - r)^2
minus the mean of the reference's variance of the mean (an unbiased estimate of the image's MSE
against the true image), relMSE = the mean of ((a - r)^2 - var_r) / (r^2 + 0.01) (pathlab diff's
relMSE, same epsilon), and relMSE_d = the mean of ((a - r)^2 - var_r) / max(|r|, d)^2 with d = 0.1 x the
mean of |r|: the relative error with the floor adaptive sampling uses (pathlab diff's epsilon 0.01 is
(0.1)^2, above most pixels of a Cornell box whose median is 0.026, so its relMSE is nearly an
absolute MSE there). Prints one line per image: 'IMAGE rmse R relmse Q relmse_d Q_d'."""
import math
import struct
import sys


def read(path):
    with open(path, "rb") as f:
        magic, size, scale, data = f.read().split(b"\n", 3)
    w, h = map(int, size.split())
    return struct.unpack(("<" if float(scale) < 0 else ">") + "%df" % (3 * w * h), data[:12 * w * h])


ref, rv = read(sys.argv[1]), read(sys.argv[2])
floor = 0.1 * sum(abs(r) for r in ref) / len(ref)
for p in sys.argv[3:]:
    a = read(p)
    se = rel = reld = 0.0
    for x, r, v in zip(a, ref, rv):
        d2 = (x - r) ** 2 - v
        se += d2
        rel += d2 / (r * r + 1e-2)
        reld += d2 / max(abs(r), floor) ** 2
    n = len(ref)
    print("%s rmse %.6g relmse %.6g relmse_d %.6g" % (p, math.sqrt(max(se / n, 0.0)), rel / n, reld / n))
