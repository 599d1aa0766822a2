"""Image and scene helpers of bench/cycles.sh (pathlab against Blender Cycles); pathlab never runs this.
Needs Debian's python3-openimageio only (no numpy: every sum is an ImageBufAlgo call). Run with /usr/bin/python3.

  dedup IN.obj OUT.obj       copy an OBJ without faces that repeat an earlier face's corner positions
                             (Cycles skips self-hits by primitive id, so an exact duplicate shadows its
                             twin and both come out black); prints what it removed
  mse IMG REF [REFVAR]       mean over pixels and RGB of (IMG - REF)^2, raw and minus REFVAR
  avg A B OUT.exr            OUT = (A + B) / 2; prints var = mean (A - B)^2 / 4, the noise of OUT
  refs C.exr P.exr CVAR PVAR the two references side by side: means, alignment, worst block
"""
import sys, math
import OpenImageIO as oiio
from OpenImageIO import ImageBuf, ImageBufAlgo as IBA, ROI


def load(path):
    buf = ImageBuf(path)
    if not buf.read(0, 0, True, oiio.FLOAT):
        sys.exit('cycles_images.py: cannot read %s: %s' % (path, buf.geterror()))
    if buf.spec().nchannels < 3:
        sys.exit('cycles_images.py: %s: expected RGB' % path)
    return IBA.channels(buf, (0, 1, 2))


def sqdiff_avg(a, b, roi=None):
    """Per-channel mean of (a - b)^2 over roi (default: all of it)."""
    d = IBA.sub(a, b)
    sq = IBA.mul(d, d)
    return IBA.computePixelStats(sq, roi=roi).avg if roi else IBA.computePixelStats(sq).avg


def mse(a, b, roi=None):
    return sum(sqdiff_avg(a, b, roi)) / 3.0


def dedup(src, dst):
    """Drop each face whose set of corner positions equals an earlier face's (same plane, same polygon)."""
    verts, seen, out, removed = [], {}, [], []
    for no, line in enumerate(open(src, encoding='latin-1'), 1):
        t = line.split()
        if t and t[0] == 'v':
            verts.append(tuple(float(x) for x in t[1:4]))
        elif t and t[0] == 'f':
            idx = [int(c.split('/')[0]) for c in t[1:]]
            key = tuple(sorted(verts[i - 1] if i > 0 else verts[len(verts) + i] for i in idx))
            if key in seen:
                removed.append('%s:%d repeats line %d' % (src, no, seen[key]))
                continue
            seen[key] = no
        out.append(line)
    with open(dst, 'w', encoding='latin-1') as f:
        f.writelines(out)
    print('dedup %s: %d duplicate face(s) removed%s' % (src, len(removed), ''.join('\n  ' + r for r in removed)))


def channel_means(buf, roi=None):
    return IBA.computePixelStats(buf, roi=roi).avg if roi else IBA.computePixelStats(buf).avg


def alignment(c, p):
    """MSE between the references for the image shifted by -1..1 pixels and flipped: (0, 0) must win."""
    w, h = c.spec().width, c.spec().height
    inner = ROI(1, w - 1, 1, h - 1)
    res = {}
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            ps = IBA.cut(p, ROI(1 + dx, w - 1 + dx, 1 + dy, h - 1 + dy))
            res[(dx, dy)] = mse(IBA.cut(c, inner), ps)
    flipped = mse(c, IBA.flip(p))
    best = min(res, key=res.get)
    second = min(v for k, v in res.items() if k != (0, 0))
    return best, res[(0, 0)], second, flipped


def refs(cpath, ppath, cvar, pvar):
    c, p = load(cpath), load(ppath)
    w, h = c.spec().width, c.spec().height
    mc, mp = channel_means(c), channel_means(p)
    # standard error of the mean difference: the per-pixel difference's spread over sqrt(pixels)
    d2 = sqdiff_avg(c, p)
    print('reference means (R G B): Cycles %s, pathlab %s' % (' '.join('%.5f' % x for x in mc), ' '.join('%.5f' % x for x in mp)))
    print('mean difference pathlab/Cycles - 1 (R G B): %s (one standard error %s)' % (
        ' '.join('%+.3f%%' % (100 * (b / a - 1)) for a, b in zip(mc, mp)),
        ' '.join('%.3f%%' % (100 * math.sqrt(v / (w * h)) / a) for a, v in zip(mc, d2))))
    lum = lambda m: (m[0] + m[1] + m[2]) / 3
    print('mean difference, all channels: %+.3f%%; MSE between the references %.3g (their own noise %.3g + %.3g)' % (
        100 * (lum(mp) / lum(mc) - 1), sum(d2) / 3, float(cvar), float(pvar)))
    best, at0, second, flipped = alignment(c, p)
    print('alignment: MSE between the references at offset (0, 0) %.3g; best other offset %.3g (x %.2f); '
          'pathlab flipped vertically %.3g: %s' % (at0, second, second / at0, flipped,
                                                   'aligned' if best == (0, 0) and flipped > at0 else 'NOT ALIGNED, best offset %s' % (best,)))
    worst_blocks(c, p, w, h, float(cvar) + float(pvar))


def worst_blocks(c, p, w, h, var):
    """20x20 blocks: the largest |relative difference| of the block means, with its z score."""
    b, rows = 20, []
    for y in range(0, h - b + 1, b):
        for x in range(0, w - b + 1, b):
            roi = ROI(x, x + b, y, y + b)
            a, q = lum3(channel_means(c, roi)), lum3(channel_means(p, roi))
            if a <= 0:
                continue
            se = math.sqrt(mse(c, p, roi) / (b * b))  # spread of the block's mean difference
            rows.append((abs(q / a - 1), x, y, q / a - 1, (q - a) / se if se > 0 else 0.0))
    rows.sort(reverse=True)
    for _, x, y, rel, z in rows[:3]:
        print('  block %dx%d at (%d, %d) from the top left: pathlab/Cycles - 1 = %+.2f%%, z = %+.1f' % (b, b, x, y, 100 * rel, z))
    nz = sum(1 for r in rows if abs(r[4]) > 3.29)
    print('  %d of %d blocks differ by more than 3.29 standard errors (two-sided alpha 0.001 each)' % (nz, len(rows)))


def lum3(m):
    return (m[0] + m[1] + m[2]) / 3


def main(argv):
    cmd = argv[1] if len(argv) > 1 else ''
    if cmd == 'dedup' and len(argv) == 4:
        dedup(argv[2], argv[3])
    elif cmd == 'mse' and len(argv) in (4, 5):
        m = mse(load(argv[2]), load(argv[3]))
        print('%.6g %.6g' % (m, m - (float(argv[4]) if len(argv) == 5 else 0.0)))
    elif cmd == 'avg' and len(argv) == 5:
        a, b = load(argv[2]), load(argv[3])
        out = IBA.mul(IBA.add(a, b), 0.5)
        if not out.write(argv[4], 'float'):
            sys.exit('cycles_images.py: cannot write %s: %s' % (argv[4], out.geterror()))
        print('%.6g' % (mse(a, b) / 4))
    elif cmd == 'refs' and len(argv) == 6:
        refs(*argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == '__main__':
    main(sys.argv)
