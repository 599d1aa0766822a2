#!/usr/bin/env python3
"""tests/mistakes.py — makes the everyday mistakes of a student's image from honest inputs (python3,
stdlib only), for tests/test_grade_mistakes.sh and tests/grade_calibration.sh.

    python3 tests/mistakes.py KIND IN.pfm OUT.pfm [args]
    python3 tests/mistakes.py sub A.pfm B.pfm OUT.pfm          A - B (full - L0: "no L0")
    python3 tests/mistakes.py add A.pfm B.pfm [C.pfm...] OUT.pfm   the sum (L0 + L1: direct light only)

KIND, on IN (pixel coordinates X Y count from the top-left pixel, as pathlab's images do):
  flip-v flip-h rotate-180     the picture upside down, mirrored, both
  grey                         every channel replaced by the mean of the three, written as PF
  grey-pf                      the same written as a one-channel Pf file
  srgb                         the sRGB transfer curve on values clamped to [0, 1] (an sRGB image saved as PFM)
  gamma                        x^(1/2.2), no clamp (sign kept for negative values)
  clamp1                       min(x, 1)
  quant8                       round(clamp(x, 0, 1) * 255) / 255
  quant8-srgb                  sRGB-encoded, rounded to 8 bits, decoded back to linear
  scale F                      every value times F (pi, 1/pi, 2, 0.5, 1.3, ...)
  big-endian-header            little-endian data but a positive scale (big-endian) in the header
  crlf                         header lines ended with \\r\\n
  truncated                    the file without its last 100 bytes
  trailing                     the file with 12 bytes appended
  nan X Y | inf X Y            one pixel NaN or +inf (all three channels)
  negative X Y                 one pixel -0.5 (all three channels)
  region NAME B REF.pfm        power tests of tests/grade_calibration.sh: the pixels of region NAME
                               times (1 + B) (B may be negative): whole (every pixel), quarter (the
                               top-left quarter), bright (the 1% of pixels where REF's luminance is
                               largest: the emitter seen directly), sparse (one pixel in 16, every 4th
                               column of every 4th row)

Batches (python starts slowly; one process for many files):
    python3 tests/mistakes.py all IN.pfm OUTDIR X Y
        every KIND above but region into OUTDIR/KIND.pfm (scale: scale_F.pfm for F = pi, 1/pi, 2, 0.5,
        1.3; nan, inf, negative at pixel X Y)
    python3 tests/mistakes.py regions REF.pfm OUTDIR NAME1,NAME2,... B1,B2,... IN1.pfm IN2.pfm ...
        each region NAME with each bias B into OUTDIR/NAME_B_I.pfm for the I-th input (counting from 0):
        times 1 + B for even I, 1 - B for odd I

PFM: "PF\\n<w> <h>\\n<scale>\\n" then float32 rows from the bottom row to the top one; a negative scale
means little-endian. Written files are little-endian with scale -1 (as pathlab writes them).
Exit status 0, or 2 on bad arguments or an unreadable input.
"""
import math
import sys
from array import array


class Image:
    def __init__(self, w, h, px):
        self.w, self.h, self.px = w, h, px   # px: 3 floats per pixel, row 0 on top

    def at(self, x, y):
        return 3 * (y * self.w + x)


def fail(msg):
    sys.stderr.write("mistakes.py: %s\n" % msg)
    sys.exit(2)


def read_pfm(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        fail("%s: %s" % (path, e))
    pos, toks = 0, []
    while len(toks) < 4:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        if start == pos:
            fail("%s: truncated PFM header" % path)
        toks.append(data[start:pos].decode("ascii", "replace"))
    pos += 1   # the single whitespace after the scale
    if toks[0] not in ("PF", "Pf"):
        fail("%s: not a PFM file" % path)
    ch = 3 if toks[0] == "PF" else 1
    try:
        w, h, scale = int(toks[1]), int(toks[2]), float(toks[3])
    except ValueError:
        fail("%s: bad PFM header %r" % (path, toks))
    n = w * h * ch
    if len(data) - pos < 4 * n:
        fail("%s: %d bytes of pixels, %d needed" % (path, len(data) - pos, 4 * n))
    vals = array("f")
    vals.frombytes(data[pos:pos + 4 * n])
    if (scale < 0) != (sys.byteorder == "little"):
        vals.byteswap()
    px = array("f", bytes(4 * 3 * w * h))
    for y in range(h):
        src = (h - 1 - y) * w * ch      # bottom row first in the file
        for x in range(w):
            for c in range(3):
                px[3 * (y * w + x) + c] = vals[src + x * ch + (c if ch == 3 else 0)]
    return Image(w, h, px)


def pfm_bytes(img, channels=3, header=None):
    """The file's bytes: little-endian data, header "PF"/"Pf", w h, -1.0 unless header is given."""
    rows = array("f")
    for y in range(img.h - 1, -1, -1):
        row = img.px[3 * y * img.w:3 * (y + 1) * img.w]
        if channels == 3:
            rows.extend(row)
        else:
            rows.extend(row[0::3])
    if sys.byteorder != "little":
        rows.byteswap()
    if header is None:
        header = "%s\n%d %d\n-1.0\n" % ("PF" if channels == 3 else "Pf", img.w, img.h)
    return header.encode("ascii") + rows.tobytes()


def write(path, data):
    try:
        with open(path, "wb") as f:
            f.write(data)
    except OSError as e:
        fail("%s: %s" % (path, e))


def srgb_encode(v):
    v = min(max(v, 0.0), 1.0)
    return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1.0 / 2.4) - 0.055


def srgb_decode(e):
    return e / 12.92 if e <= 0.04045 else ((e + 0.055) / 1.055) ** 2.4


def finite_map(img, fn):
    """fn on every finite value (NaN and inf are left as they are)."""
    px = img.px
    for i in range(len(px)):
        v = px[i]
        if math.isfinite(v):
            px[i] = fn(v)
    return img


def gamma(v):
    return math.copysign(abs(v) ** (1.0 / 2.2), v)


def flip(img, horizontal, vertical):
    out = array("f", img.px)
    for y in range(img.h):
        for x in range(img.w):
            sx = img.w - 1 - x if horizontal else x
            sy = img.h - 1 - y if vertical else y
            out[img.at(x, y):img.at(x, y) + 3] = img.px[img.at(sx, sy):img.at(sx, sy) + 3]
    return Image(img.w, img.h, out)


def grey(img):
    px = img.px
    for i in range(0, len(px), 3):
        m = (px[i] + px[i + 1] + px[i + 2]) / 3.0
        px[i] = px[i + 1] = px[i + 2] = m
    return img


def set_pixel(img, args, value):
    if len(args) != 2:
        fail("needs X Y")
    x, y = int(args[0]), int(args[1])
    if not (0 <= x < img.w and 0 <= y < img.h):
        fail("pixel %d %d outside the %dx%d image" % (x, y, img.w, img.h))
    i = img.at(x, y)
    img.px[i:i + 3] = array("f", [value] * 3)
    return img


def region_pixels(img, name, ref):
    """Indices (of the pixel's first channel) of the region NAME."""
    w, h = img.w, img.h
    if name == "whole":
        return range(0, 3 * w * h, 3)
    if name == "quarter":
        return [img.at(x, y) for y in range(h // 2) for x in range(w // 2)]
    if name == "sparse":
        return [img.at(x, y) for y in range(0, h, 4) for x in range(0, w, 4)]
    if name == "bright":
        if ref is None or (ref.w, ref.h) != (w, h):
            fail("region bright needs REF.pfm of the image's size")
        lum = [(0.2126 * ref.px[i] + 0.7152 * ref.px[i + 1] + 0.0722 * ref.px[i + 2], i)
               for i in range(0, 3 * w * h, 3)]
        lum.sort(reverse=True)
        return [i for _, i in lum[:max(1, (w * h + 99) // 100)]]
    fail("unknown region '%s' (whole, quarter, bright, sparse)" % name)


SINGLE = ["flip-v", "flip-h", "rotate-180", "grey", "grey-pf", "srgb", "gamma", "clamp1", "quant8",
          "quant8-srgb", "scale", "big-endian-header", "crlf", "truncated", "trailing", "nan", "inf",
          "negative", "region"]
SCALES = ["3.14159265", "0.318309886", "2", "0.5", "1.3"]


def make(kind, src, args, cache):
    """The bytes of mistake KIND made from the file src. cache: path -> Image, read once."""
    if kind in ("truncated", "trailing"):   # byte-level: the honest file as it is
        try:
            with open(src, "rb") as f:
                data = f.read()
        except OSError as e:
            fail("%s: %s" % (src, e))
        return data[:-100] if kind == "truncated" else data + bytes(12)
    if src not in cache:
        cache[src] = read_pfm(src)
    img = Image(cache[src].w, cache[src].h, array("f", cache[src].px))   # a copy
    channels, header = 3, None
    if kind == "flip-v":
        img = flip(img, False, True)
    elif kind == "flip-h":
        img = flip(img, True, False)
    elif kind == "rotate-180":
        img = flip(img, True, True)
    elif kind == "grey":
        img = grey(img)
    elif kind == "grey-pf":
        img, channels = grey(img), 1
    elif kind == "srgb":
        img = finite_map(img, srgb_encode)
    elif kind == "gamma":
        img = finite_map(img, gamma)
    elif kind == "clamp1":
        img = finite_map(img, lambda v: min(v, 1.0))
    elif kind == "quant8":
        img = finite_map(img, lambda v: round(min(max(v, 0.0), 1.0) * 255.0) / 255.0)
    elif kind == "quant8-srgb":
        img = finite_map(img, lambda v: srgb_decode(round(srgb_encode(v) * 255.0) / 255.0))
    elif kind == "scale":
        if len(args) != 1:
            fail("scale needs F")
        f = float(args[0])
        img = finite_map(img, lambda v: v * f)
    elif kind == "big-endian-header":
        header = "PF\n%d %d\n1.0\n" % (img.w, img.h)
    elif kind == "crlf":
        header = "PF\r\n%d %d\r\n-1.0\r\n" % (img.w, img.h)
    elif kind == "nan":
        img = set_pixel(img, args, float("nan"))
    elif kind == "inf":
        img = set_pixel(img, args, float("inf"))
    elif kind == "negative":
        img = set_pixel(img, args, -0.5)
    elif kind == "region":
        if len(args) not in (2, 3):
            fail("region needs NAME B [REF.pfm]")
        f = 1.0 + float(args[1])
        ref = None
        if len(args) == 3:
            if args[2] not in cache:
                cache[args[2]] = read_pfm(args[2])
            ref = cache[args[2]]
        px = img.px
        for i in region_pixels(img, args[0], ref):
            px[i] *= f
            px[i + 1] *= f
            px[i + 2] *= f
    else:
        fail("unknown kind '%s'" % kind)
    return pfm_bytes(img, channels, header)


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        sys.exit(2)
    kind = argv[1]
    cache = {}
    if kind in ("sub", "add"):
        if len(argv) < 5 or (kind == "sub" and len(argv) != 5):
            fail("%s A.pfm B.pfm%s OUT.pfm" % (kind, "" if kind == "sub" else " [C.pfm...]"))
        imgs = [read_pfm(p) for p in argv[2:-1]]
        out = imgs[0]
        for other in imgs[1:]:
            if (other.w, other.h) != (out.w, out.h):
                fail("sizes differ: %dx%d and %dx%d" % (out.w, out.h, other.w, other.h))
            sign = -1.0 if kind == "sub" else 1.0
            for i in range(len(out.px)):
                out.px[i] += sign * other.px[i]
        write(argv[-1], pfm_bytes(out))
        return
    if kind == "all":   # every single-input mistake of IN into OUTDIR, one process (python starts slowly)
        if len(argv) != 6:
            fail("all IN.pfm OUTDIR X Y")
        src, outdir, xy = argv[2], argv[3], argv[4:6]
        for k in SINGLE:
            if k == "region":
                continue
            if k == "scale":
                for f in SCALES:
                    write("%s/scale_%s.pfm" % (outdir, f), make(k, src, [f], cache))
            else:
                write("%s/%s.pfm" % (outdir, k), make(k, src, xy if k in ("nan", "inf", "negative") else [], cache))
        return
    if kind == "regions":   # the power sweep of tests/grade_calibration.sh, one process
        if len(argv) < 8:
            fail("regions REF.pfm OUTDIR NAME1,... B1,B2,... IN1.pfm [IN2.pfm...]")
        ref, outdir, names, biases, ins = argv[2], argv[3], argv[4].split(","), argv[5].split(","), argv[6:]
        for name in names:
            for b in biases:
                for i, src in enumerate(ins):
                    sb = b if i % 2 == 0 else "-" + b
                    write("%s/%s_%s_%d.pfm" % (outdir, name, b, i), make("region", src, [name, sb, ref], cache))
        return
    if len(argv) < 4:
        fail("usage: mistakes.py KIND IN.pfm OUT.pfm [args] (see the head of the file)")
    write(argv[3], make(kind, argv[2], argv[4:], cache))


if __name__ == "__main__":
    main(sys.argv)
