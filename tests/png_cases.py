#!/usr/bin/env python3
"""png_cases.py DIR — writes the PNG files of tests/test_png.c into DIR, with Python's zlib (an
independent deflate): every colour type at every bit depth PNG allows, plain and Adam7-interlaced,
every row filter (the filter of a row cycles through 0..4), zlib levels 0 (stored blocks), 1 and 9
(fixed and dynamic Huffman blocks). Beside each NAME.png, NAME.txt: "W H MAXVAL" then, row by row
from the top, each pixel's R G B integers (grey repeated; a palette's entries looked up, MAXVAL 255).
Then hostile files: hostile_WHAT.png. Deterministic (a fixed seed)."""
import random
import struct
import sys
import zlib

ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}
DEPTHS = {0: (1, 2, 4, 8, 16), 2: (8, 16), 3: (1, 2, 4, 8), 4: (8, 16), 6: (8, 16)}


def chunk(kind, data, bad_crc=False):
    crc = zlib.crc32(kind + data) ^ (1 if bad_crc else 0)
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)


def pack_row(samples, depth):
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    if depth == 8:
        return bytes(samples)
    out, acc, nbits = bytearray(), 0, 0
    for s in samples:
        acc, nbits = acc << depth | s, nbits + depth
        if nbits == 8:
            out.append(acc)
            acc, nbits = 0, 0
    if nbits:
        out.append(acc << (8 - nbits))
    return bytes(out)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def filter_row(row, prev, bpp, f):
    out = bytearray([f])
    for i, x in enumerate(row):
        a = row[i - bpp] if i >= bpp else 0
        b = prev[i] if prev else 0
        c = prev[i - bpp] if prev and i >= bpp else 0
        pred = [0, a, b, (a + b) >> 1, paeth(a, b, c)][f]
        out.append((x - pred) & 255)
    return bytes(out)


def raw_data(pix, w, h, depth, ch, interlace, seed):
    """The filtered rows of pix[y][x] (a list of ch samples each)."""
    bpp = max(1, ch * depth // 8)
    passes = ADAM7 if interlace else [(0, 0, 1, 1)]
    out, n = bytearray(), seed
    for x0, y0, dx, dy in passes:
        xs, ys = list(range(x0, w, dx)), list(range(y0, h, dy))
        if not xs or not ys:
            continue
        prev = None
        for y in ys:
            row = pack_row([s for x in xs for s in pix[y][x]], depth)
            out += filter_row(row, prev, bpp, n % 5)
            n += 1
            prev = row
    return bytes(out)


def png(w, h, depth, ctype, interlace, idat, plte=None, trns=None, extra=b""):
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))
    out += chunk(b"tEXt", b"Comment\0made by png_cases.py") + extra
    if plte:
        out += chunk(b"PLTE", plte)
    if trns:
        out += chunk(b"tRNS", trns)
    for i in range(0, len(idat), 50):   # several IDAT chunks
        out += chunk(b"IDAT", idat[i:i + 50])
    return out + chunk(b"IEND", b"")


def case(d, rnd, name, w, h, depth, ctype, interlace, level):
    ch, top = CHANNELS[ctype], (1 << depth) - 1
    plte = None
    if ctype == 3:
        n = min(1 << depth, 200)
        plte = [tuple(rnd.randrange(256) for _ in range(3)) for _ in range(n)]
        top = n - 1
    pix = [[[rnd.randrange(top + 1) if rnd.random() < 0.7 or x == 0 else 0 for _ in range(ch)] for x in range(w)]
           for y in range(h)]
    idat = zlib.compress(raw_data(pix, w, h, depth, ch, interlace, w + h), level)
    trns = b"\0\1" if ctype == 0 and depth == 16 else b"\0" if ctype == 3 else None
    with open(f"{d}/{name}.png", "wb") as f:
        f.write(png(w, h, depth, ctype, interlace, idat, bytes(c for e in plte for c in e) if plte else None, trns))
    with open(f"{d}/{name}.txt", "w") as f:
        f.write(f"{w} {h} {255 if ctype == 3 else (1 << depth) - 1}\n")
        for row in pix:
            f.write(" ".join(" ".join(map(str, plte[p[0]] if ctype == 3 else (p[0],) * 3 if ch < 3 else p[:3]))
                             for p in row) + "\n")


def far_distance():
    """A fixed-Huffman block whose first symbol copies 3 bytes from 1 back: before the start."""
    bits = [1, 1, 0]                          # BFINAL, BTYPE 01 (least significant bit first)
    bits += [0, 0, 0, 0, 0, 0, 1]             # length symbol 257 (7-bit code 0000001, most significant first)
    bits += [0, 0, 0, 0, 0]                   # distance code 0: distance 1
    bits += [0] * 7                           # end of block (256)
    out = bytearray((len(bits) + 7) // 8)
    for i, b in enumerate(bits):
        out[i // 8] |= b << (i % 8)
    return bytes(out)


def hostile(d):
    good = zlib.compress(b"\0" + b"\x10\x20\x30" * 2, 9)
    cases = {
        "bad_crc": png(2, 1, 8, 2, 0, good).replace(b"IEND\xaeB`\x82", b"IEND\xaeB`\x83"),
        "bomb": png(16000, 16000, 8, 2, 0, zlib.compress(b"\0" * 1000, 9)),
        "huge": png(30000, 30000, 8, 2, 0, good),
        "filter_5": png(2, 1, 8, 2, 0, zlib.compress(b"\5" + b"\x10\x20\x30" * 2)),
        "short_data": png(2, 2, 8, 2, 0, good),
        "long_data": png(2, 1, 8, 2, 0, zlib.compress(b"\0" + b"\x10\x20\x30" * 3)),
        "adler": png(2, 1, 8, 2, 0, good[:-1] + bytes([good[-1] ^ 1])),
        "truncated_idat": png(2, 1, 8, 2, 0, good[:-6]),
        "no_plte": png(2, 1, 8, 3, 0, zlib.compress(b"\0\0\0")),
        "index_past_plte": png(2, 1, 8, 3, 0, zlib.compress(b"\0\0\3"), plte=b"\1\2\3" * 2),
        "depth_3": png(2, 1, 3, 0, 0, good),
        "rgb_4bit": png(2, 1, 4, 2, 0, good),
        "critical": png(2, 1, 8, 2, 0, good, extra=chunk(b"ABCD", b"x")),
        "cut": png(2, 1, 8, 2, 0, good)[:-20],
        "reserved_block": png(2, 1, 8, 2, 0, b"\x78\x9c\x07\0\0\0\0\0"),
        "far_distance": png(2, 1, 8, 2, 0, b"\x78\x9c" + far_distance() + b"\0\0\0\0"),
    }
    for name, data in cases.items():
        with open(f"{d}/hostile_{name}.png", "wb") as f:
            f.write(data)


def main():
    d = sys.argv[1]
    rnd = random.Random(20261205)
    k = 0
    for ctype, depths in DEPTHS.items():
        for depth in depths:
            for interlace in (0, 1):
                for w, h in ((13, 11), (1, 1), (33, 3)):
                    name = f"c{ctype}_d{depth}_i{interlace}_{w}x{h}"
                    case(d, rnd, name, w, h, depth, ctype, interlace, (0, 1, 9)[k % 3])
                    k += 1
    hostile(d)


main()
