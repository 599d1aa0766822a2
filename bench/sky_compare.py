"""bench/cycles_sky.sh's numbers: pathlab against Cycles on the sky scene. Run with /usr/bin/python3 (OpenImageIO).
  sky_compare.py OUT TC TP   reads OUT/cref1.exr, cref2.exr, pref1.pfm, pref2.pfm, c_level.exr, p_level.pfm"""
import sys
import OpenImageIO as oiio
from OpenImageIO import ImageBuf, ImageBufAlgo as IBA, ROI

out, tc, tp = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
def load(p):
    b = ImageBuf(p)
    if not b.read(0, 0, True, oiio.FLOAT): sys.exit('sky_compare.py: cannot read %s' % p)
    return IBA.channels(b, (0, 1, 2))
def avg(a, b): return IBA.mul(IBA.add(a, b), 0.5)
def mean(a, roi=None): return IBA.computePixelStats(a, roi=roi).avg if roi else IBA.computePixelStats(a).avg
def sq(a, b):
    d = IBA.sub(a, b); return IBA.mul(d, d)

c1, c2, p1, p2 = load(out + '/cref1.exr'), load(out + '/cref2.exr'), load(out + '/pref1.pfm'), load(out + '/pref2.pfm')
C, P = avg(c1, c2), avg(p1, p2)
vC, vP = IBA.mul(sq(c1, c2), 0.25), IBA.mul(sq(p1, p2), 0.25)   # per-pixel variance of each reference
w, h = C.spec().width, C.spec().height
def rel(roi, n):
    mc, mp, v = mean(C, roi), mean(P, roi), [a + b for a, b in zip(mean(vC, roi), mean(vP, roi))]
    return [(p - c) / c for p, c in zip(mp, mc)], [(x / n) ** 0.5 / c for x, c in zip(v, mc)]
r, se = rel(None, w * h)
print('whole image: pathlab / Cycles - 1 per channel: %s (noise of the difference: %s)' %
      (' '.join('%+.4f' % x for x in r), ' '.join('%.4f' % x for x in se)))
B = 25
worst = (0, None, None)
for by in range(0, h, B):
    for bx in range(0, w, B):
        roi = ROI(bx, min(bx + B, w), by, min(by + B, h), 0, 1, 0, 3)
        rb, sb = rel(roi, (roi.xend - roi.xbegin) * (roi.yend - roi.ybegin))
        k = max(range(3), key=lambda i: abs(rb[i]))
        if abs(rb[k]) > worst[0]: worst = (abs(rb[k]), (bx, by, k), (rb[k], sb[k]))
print('worst %dx%d block: at (%d, %d) channel %d: %+.4f (noise %.4f)' % (B, B, worst[1][0], worst[1][1], worst[1][2], worst[2][0], worst[2][1]))
cl, pl = load(out + '/c_level.exr'), load(out + '/p_level.pfm')
for name, ref, vref in (('Cycles', C, vC), ('pathlab', P, vP)):
    noise = sum(mean(vref)) / 3
    mc, mp = sum(mean(sq(cl, ref))) / 3 - noise, sum(mean(sq(pl, ref))) / 3 - noise
    print('against the %s reference: MSE Cycles %.3e in %.2f s, pathlab %.3e in %.2f s; MSE x time pathlab / Cycles = %.2f'
          % (name, mc, tc, mp, tp, (mp * tp) / (mc * tc)))
