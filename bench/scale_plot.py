#!/usr/bin/env python3
"""bench/scale_plot.py CSV OUT.svg — the table, slopes and log-log plot of bench/scale.sh's CSV.

Per tool and thread count, the median over rounds at each size of: build time, bytes per triangle
(BVH and triangles; peak resident memory too) and Mrays/s of each ray kind. Prints Markdown tables
(figures, pathlab/embree ratios, the load average of each run) and the least-squares slopes of
log value against log triangles, next to what the algorithms predict over the measured range:
a build of O(N log N) grows with slope 1 + 1/ln N (about 1.07 between 1M and 16M); a traversal
of O(log N) steps per ray loses speed with slope -1/ln N (about -0.07). Writes OUT.svg (six
log-log panels) through a temporary file."""
import collections, math, os, statistics, sys

KINDS = ('primary', 'diffuse', 'shadow')
COLOURS = ('#0072B2', '#D55E00', '#009E73', '#CC79A7')


def read(path):
    rows = collections.defaultdict(list)
    for line in open(path):
        f = line.strip().split(',')
        if not f[0] or f[0] == 'tool':
            continue
        rows[(f[0], int(f[1]), int(f[2]))].append(f)
    med = {}
    for key, rs in rows.items():
        col = lambda i: statistics.median(float(r[i]) for r in rs if r[i])
        n = key[2]
        med[key] = {'build': col(4) / 1e3, 'bpt': col(5), 'rss': col(6) * 1048576 / n,
                    'primary': col(7), 'diffuse': col(8), 'shadow': col(9),
                    'load': '-'.join(sorted({r[11] for r in rs}))}
    return med


def slope(pts):
    xs = [math.log(x) for x, _ in pts]
    ys = [math.log(y) for _, y in pts]
    if len(xs) < 2:
        return float('nan')
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def series(med):
    out = collections.defaultdict(dict)
    for (tool, t, n), v in med.items():
        out[(tool, t)][n] = v
    return out


def tables(med):
    S = series(med)
    tools = sorted({k[0] for k in S if k[0] != 'embree'})
    for t in sorted({k[1] for k in S}):
        E = S.get(('embree', t), {})
        for tool in tools:
            P = S.get((tool, t), {})
            print(f"\n{tool} against Embree 3, {t} thread(s) (each cell: {tool} / embree = ratio)\n")
            print("| triangles | build s | BVH bytes/tri | peak RSS bytes/tri | primary Mrays/s | diffuse | shadow | load |")
            print("|---|---|---|---|---|---|---|---|")
            for n in sorted(P):
                p, e = P[n], E.get(n)
                cell = lambda k, f: (f % p[k]) + ((" / " + f % e[k] + " = %.2f" % (p[k] / e[k])) if e else "")
                print(f"| {n / 1e6:.2f}M | {cell('build', '%.2f')} | {cell('bpt', '%.1f')} | {cell('rss', '%.0f')} | "
                      f"{cell('primary', '%.2f')} | {cell('diffuse', '%.2f')} | {cell('shadow', '%.2f')} | {p['load']}{(' / ' + e['load']) if e else ''} |")
    ns = sorted({k[2] for k in med})
    if len(ns) >= 2:
        mid = math.sqrt(ns[0] * ns[-1])
        print(f"\nslopes of log value against log triangles, {ns[0] / 1e6:.2f}M to {ns[-1] / 1e6:.2f}M "
              f"(expected: build {1 + 1 / math.log(mid):.2f} for N log N, rays/s {-1 / math.log(mid):.2f} for log N)\n")
        print("| tool | threads | build | primary | diffuse | shadow |")
        print("|---|---|---|---|---|---|")
        for (tool, t), P in sorted(S.items()):
            sl = [slope([(n, P[n][k]) for n in sorted(P)]) for k in ('build',) + KINDS]
            print(f"| {tool} | {t} | " + " | ".join("%.2f" % s for s in sl) + " |")


def ticks(lo, hi):
    out = []
    for e in range(math.floor(math.log10(lo)) - 1, math.ceil(math.log10(hi)) + 1):
        for m in (1, 2, 5):
            v = m * 10 ** e
            if lo <= v <= hi:
                out.append(v)
    return out


def panel(o, x0, y0, title, curves, w=300, h=220):
    """curves: [(name, colour, dash, [(n, y)])]; log-log axes over the points' range."""
    L, T, W, H = x0 + 50, y0 + 24, w - 64, h - 64
    xs = [p[0] for c in curves for p in c[3]]
    ys = [p[1] for c in curves for p in c[3]]
    if not xs:
        return
    xl, xh = min(xs) / 1.15, max(xs) * 1.15
    yl, yh = min(ys) / 1.25, max(ys) * 1.25
    if yh / yl < 3:
        g = math.sqrt(3 / (yh / yl)); yl, yh = yl / g, yh * g
    X = lambda x: L + W * (math.log(x) - math.log(xl)) / (math.log(xh) - math.log(xl))
    Y = lambda y: T + H - H * (math.log(y) - math.log(yl)) / (math.log(yh) - math.log(yl))
    o.write(f'<text x="{L + W / 2:.1f}" y="{y0 + 14}" text-anchor="middle" font-size="12" font-weight="bold">{title}</text>\n')
    o.write(f'<rect x="{L}" y="{T}" width="{W}" height="{H}" fill="none" stroke="#000"/>\n')
    for v in ticks(xl, xh):
        o.write(f'<line x1="{X(v):.1f}" y1="{T + H}" x2="{X(v):.1f}" y2="{T + H + 4}" stroke="#000"/>'
                f'<text x="{X(v):.1f}" y="{T + H + 15}" text-anchor="middle" font-size="10">{v / 1e6:g}M</text>\n')
    for v in ticks(yl, yh):
        o.write(f'<line x1="{L - 4}" y1="{Y(v):.1f}" x2="{L + W}" y2="{Y(v):.1f}" stroke="#ddd"/>'
                f'<text x="{L - 6}" y="{Y(v) + 3:.1f}" text-anchor="end" font-size="10">{v:g}</text>\n')
    o.write(f'<text x="{L + W / 2:.1f}" y="{T + H + 30}" text-anchor="middle" font-size="10">triangles</text>\n')
    for name, col, dash, pts in curves:
        d = ' '.join(f'{X(x):.1f},{Y(y):.1f}' for x, y in pts)
        o.write(f'<polyline points="{d}" fill="none" stroke="{col}" stroke-width="1.5"{dash}/>\n')
        for x, y in pts:
            o.write(f'<circle cx="{X(x):.1f}" cy="{Y(y):.1f}" r="2.5" fill="{col}"/>\n')


def guide(pts, exponent_of):
    """The expected growth through the first point: y0 * g(N) / g(N0)."""
    n0, y0 = pts[0]
    return [(n, y0 * exponent_of(n) / exponent_of(n0)) for n, _ in pts]


def svg(med, path):
    S = series(med)
    keys = sorted(S, key=lambda k: (k[0] != 'embree', k[0], k[1]))
    style = {k: (COLOURS[i % len(COLOURS)], '' if k[1] == 1 else ' stroke-dasharray="5,3"') for i, k in enumerate(keys)}
    tools = sorted({k[0] for k in keys})
    for i, k in enumerate(keys):
        style[k] = (COLOURS[tools.index(k[0]) % len(COLOURS)], '' if k[1] == 1 else ' stroke-dasharray="5,3"')
    cur = lambda m: [(f"{k[0]} {k[1]}t", style[k][0], style[k][1], [(n, S[k][n][m]) for n in sorted(S[k])]) for k in keys]
    grey = '#888'
    tmp = path + '.tmp'
    with open(tmp, 'w') as o:
        W, H = 960, 560
        o.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif">\n'
                f'<rect width="{W}" height="{H}" fill="#fff"/>\n')
        first = cur('build')[0][3] if keys else []
        c = cur('build') + ([("N log N", grey, ' stroke-dasharray="2,3"', guide(first, lambda n: n * math.log(n)))] if first else [])
        panel(o, 10, 10, 'build time (s)', c)
        mem = cur('bpt') + [(n + ' RSS', col, ' stroke-dasharray="1,2"', pts) for n, col, _, pts in cur('rss')]
        panel(o, 330, 10, 'bytes per triangle: BVH (solid), peak RSS (dotted)', mem)
        for i, kind in enumerate(KINDS):
            c = cur(kind)
            first = c[0][3] if c else []
            c += [("1 / log N", grey, ' stroke-dasharray="2,3"', guide(first, lambda n: 1 / math.log(n)))] if first else []
            panel(o, 650 if i == 0 else 10 + 320 * (i - 1), 10 if i == 0 else 270, f'{kind} rays, Mrays/s', c)
        y = 290
        for i, k in enumerate(keys):
            col, dash = style[k]
            o.write(f'<line x1="670" y1="{y + 18 * i}" x2="700" y2="{y + 18 * i}" stroke="{col}" stroke-width="1.5"{dash}/>'
                    f'<text x="706" y="{y + 18 * i + 4}" font-size="11">{k[0]}, {k[1]} thread(s)</text>\n')
        y += 18 * len(keys)
        o.write(f'<line x1="670" y1="{y}" x2="700" y2="{y}" stroke="{grey}" stroke-dasharray="2,3"/>'
                f'<text x="706" y="{y + 4}" font-size="11">expected growth (N log N; 1 / log N)</text>\n'
                f'<text x="670" y="{y + 24}" font-size="10">fields of bunny copies (bench/scale.sh)</text>\n</svg>\n')
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 3:
        print("usage: scale_plot.py SCALE.csv OUT.svg", file=sys.stderr)
        return 2
    med = read(sys.argv[1])
    tables(med)
    svg(med, sys.argv[2])
    return 0


if __name__ == '__main__':
    sys.exit(main())
