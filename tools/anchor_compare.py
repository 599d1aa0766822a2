#!/usr/bin/env python3
"""tools/anchor_compare.py A.pfm B.pfm [BLOCK] — how far image A is from B: the relative difference of
the whole image's mean (per channel, the largest), and of each BLOCK x BLOCK block's mean luminance
(blocks whose mean in B is under 1% of the image's are skipped: their relative error is noise).
Prints both; exit 0 within 0.5% over the image and 3% per block, else 1."""
import struct, sys

def read(path):
    d = open(path, "rb").read()
    head = d.split(b"\n", 3)
    w, h = (int(x) for x in head[1].split())
    v = struct.unpack(("<" if float(head[2]) < 0 else ">") + "%df" % (3 * w * h), head[3][:12 * w * h])
    return w, h, v

wa, ha, a = read(sys.argv[1]); wb, hb, b = read(sys.argv[2])
assert (wa, ha) == (wb, hb), "sizes differ"
B = int(sys.argv[3]) if len(sys.argv) > 3 else 8
img = max(abs(sum(a[c::3]) / sum(b[c::3]) - 1) for c in range(3) if sum(b[c::3]) > 0)
lum = lambda v, i: 0.2126 * v[3 * i] + 0.7152 * v[3 * i + 1] + 0.0722 * v[3 * i + 2]
mean_b = sum(lum(b, i) for i in range(wa * ha)) / (wa * ha)
worst, nb = 0.0, 0
for by in range(0, ha - B + 1, B):
    for bx in range(0, wa - B + 1, B):
        ids = [y * wa + x for y in range(by, by + B) for x in range(bx, bx + B)]
        sa, sb = sum(lum(a, i) for i in ids) / len(ids), sum(lum(b, i) for i in ids) / len(ids)
        if sb < 0.01 * mean_b: continue
        nb += 1
        worst = max(worst, abs(sa / sb - 1))
print("image %.3f%% (largest channel), worst of %d blocks %.2f%%" % (100 * img, nb, 100 * worst))
sys.exit(0 if img <= 0.005 and worst <= 0.03 else 1)
