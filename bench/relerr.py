#!/usr/bin/env python3
"""bench/relerr.py IMAGE.pfm VARIANCE.pfm — the relative error per pixel of a render, on average.

For every pixel-channel with a mean above 0: sqrt(variance of the mean) / mean, where the variance is
the one pathlab writes with --variance (the variance of the pixel's mean, not of one sample). Prints
one line: 'relerr R pixels N skipped K' with R the mean of those ratios over the N pixel-channels
(K pixel-channels with mean 0, e.g. black background, are skipped). The error of a Monte Carlo mean
falls as 1/sqrt(spp), so a render at S spp with relerr R reaches a target T at S * (R / T)^2 spp.
Exit 0, or 2 on bad input."""
import math
import struct
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = []
    pos = 0
    for _ in range(3):              # "PF", "W H", "scale", each ended by one newline
        end = data.index(b"\n", pos)
        parts.append(data[pos:end].decode("ascii"))
        pos = end + 1
    if parts[0] not in ("PF", "Pf"):
        raise ValueError(f"{path}: not a PFM file")
    ch = 3 if parts[0] == "PF" else 1
    w, h = (int(v) for v in parts[1].split())
    order = "<" if float(parts[2]) < 0 else ">"
    n = w * h * ch
    if len(data) - pos != 4 * n:
        raise ValueError(f"{path}: {len(data) - pos} bytes of pixels, expected {4 * n}")
    return w, h, ch, struct.unpack(f"{order}{n}f", data[pos:])


def main():
    if len(sys.argv) != 3:
        print("usage: bench/relerr.py IMAGE.pfm VARIANCE.pfm", file=sys.stderr)
        return 2
    try:
        a = read_pfm(sys.argv[1])
        v = read_pfm(sys.argv[2])
    except (OSError, ValueError) as e:
        print(f"relerr: {e}", file=sys.stderr)
        return 2
    if a[:3] != v[:3]:
        print("relerr: the image and its variance differ in size or channels", file=sys.stderr)
        return 2
    total, n, skipped = 0.0, 0, 0
    for m, var in zip(a[3], v[3]):
        if m > 0.0:
            total += math.sqrt(max(var, 0.0)) / m
            n += 1
        else:
            skipped += 1
    if n == 0:
        print("relerr: every pixel is 0", file=sys.stderr)
        return 2
    print(f"relerr {total / n:.6g} pixels {n} skipped {skipped}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
