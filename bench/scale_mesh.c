/* bench/scale_mesh.c — the big meshes of `make bench-scale` (bench/scale.sh), built as
 * build/bench-scale-mesh:
 *
 *   bench-scale-mesh MESH.obj NTRIS OUT.obj [subdivide]
 *
 * writes a field of copies of MESH (its `v` and `f` lines; polygons fan-triangulated, negative
 * indices allowed), as many as it takes to reach NTRIS triangles, on a square grid of the xz plane.
 * Each copy is turned about y, scaled by 0.8-1.2 and raised by up to a third of its height, by
 * hashes of its number, so no two copies are alike and no two overlap; the same arguments give the
 * same file. With `subdivide`, MESH itself instead, each triangle cut into 4 at its edges' midpoints
 * (shared between neighbours) as many times as it takes: the same surface, seen the same way by
 * bench-rays' camera, with 4^k times the triangles. OUT.obj is written to OUT.obj.tmp and renamed.
 * Exit 0, or 2 with a message. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { float *v; long nv, capv; long *f; long nf, capf; } mesh_in;

static int grow(void **p, long *cap, long need, size_t size)
{
    void *q;
    long c = *cap ? *cap : 1024;
    if (need <= *cap) return 0;
    while (c < need) c *= 2;
    q = realloc(*p, (size_t)c * size);
    if (!q) return -1;
    *p = q; *cap = c;
    return 0;
}

/* One `f` line's corners, fan-triangulated into m->f; -1 on a bad index. */
static int read_face(mesh_in *m, char *s)
{
    long idx[3], n = 0, k;
    char *end;
    for (;;) {
        while (*s == ' ' || *s == '\t') s++;
        if (*s == '\0' || *s == '\n' || *s == '\r') break;
        k = strtol(s, &end, 10);
        if (end == s) return -1;
        k = k < 0 ? m->nv + k : k - 1;
        if (k < 0 || k >= m->nv) return -1;
        while (*end && *end != ' ' && *end != '\t' && *end != '\n') end++;   /* skip /vt/vn */
        s = end;
        if (n < 2) idx[n] = k; else idx[2] = k;
        if (++n >= 3) {
            if (grow((void **)&m->f, &m->capf, 3 * (m->nf + 1), sizeof(long))) return -1;
            memcpy(&m->f[3 * m->nf++], idx, sizeof idx);
            idx[1] = idx[2];
        }
    }
    return 0;
}

static int read_mesh(const char *path, mesh_in *m)
{
    char line[4096], *end;
    long ln = 0;
    int a;
    FILE *fp = fopen(path, "r");
    if (!fp) { fprintf(stderr, "bench-scale-mesh: %s: %s\n", path, strerror(errno)); return -1; }
    while (fgets(line, sizeof line, fp)) {
        ln++;
        if (line[0] == 'v' && line[1] == ' ') {
            char *s = line + 2;
            if (grow((void **)&m->v, &m->capv, 3 * (m->nv + 1), sizeof(float))) break;
            for (a = 0; a < 3; a++, s = end) {
                m->v[3 * m->nv + a] = strtof(s, &end);
                if (end == s) { fprintf(stderr, "bench-scale-mesh: %s:%ld: bad vertex\n", path, ln); fclose(fp); return -1; }
            }
            m->nv++;
        } else if (line[0] == 'f' && line[1] == ' ' && read_face(m, line + 2)) {
            fprintf(stderr, "bench-scale-mesh: %s:%ld: bad face\n", path, ln);
            fclose(fp);
            return -1;
        }
    }
    fclose(fp);
    if (m->nf == 0) { fprintf(stderr, "bench-scale-mesh: %s: no triangles\n", path); return -1; }
    return 0;
}

static uint32_t lowbias32(uint32_t x)
{
    x ^= x >> 16; x *= 0x7feb352dU; x ^= x >> 15; x *= 0x846ca68bU; x ^= x >> 16;
    return x;
}
static double u01(uint32_t h) { return (double)(h >> 8) / 16777216.0; }

/* Copy c of `copies` on a grid of g x g cells of `cell` units: its vertices, then its faces. */
static int write_copy(FILE *out, const mesh_in *m, long c, long g, const double lo[3], const double hi[3])
{
    double ctr[3], ext[3], cell, ang, sc, lift, x, y, z;
    long i, base = c * m->nv + 1;
    int a;
    for (a = 0; a < 3; a++) { ctr[a] = 0.5 * (lo[a] + hi[a]); ext[a] = hi[a] - lo[a]; }
    cell = 1.3 * sqrt(ext[0] * ext[0] + ext[2] * ext[2]);   /* any turn of a copy fits its cell */
    ang = 6.283185307179586 * u01(lowbias32(3u * (uint32_t)c));
    sc = 0.8 + 0.4 * u01(lowbias32(3u * (uint32_t)c + 1u));
    lift = ext[1] / 3.0 * u01(lowbias32(3u * (uint32_t)c + 2u));
    for (i = 0; i < m->nv; i++) {
        x = m->v[3 * i] - ctr[0]; y = m->v[3 * i + 1] - lo[1]; z = m->v[3 * i + 2] - ctr[2];
        if (fprintf(out, "v %.7g %.7g %.7g\n", sc * (cos(ang) * x + sin(ang) * z) + cell * (double)(c % g),
                    sc * y + lift, sc * (-sin(ang) * x + cos(ang) * z) + cell * (double)(c / g)) < 0) return -1;
    }
    for (i = 0; i < m->nf; i++)
        if (fprintf(out, "f %ld %ld %ld\n", base + m->f[3 * i], base + m->f[3 * i + 1], base + m->f[3 * i + 2]) < 0) return -1;
    return 0;
}

/* The midpoint of edge (a, b), made once: an open-addressing table of the level's edges. */
typedef struct { long *key, *mid; long cap; } edge_table;

static long midpoint(mesh_in *m, edge_table *E, long a, long b)
{
    long lo = a < b ? a : b, hi = a < b ? b : a, k = lo * 2654435761L + hi, i;
    int c;
    for (i = (k & 0x7fffffffffffL) % E->cap;; i = (i + 1) % E->cap) {
        if (E->key[2 * i] == lo && E->key[2 * i + 1] == hi) return E->mid[i];
        if (E->key[2 * i] < 0) break;
    }
    E->key[2 * i] = lo; E->key[2 * i + 1] = hi; E->mid[i] = m->nv;
    for (c = 0; c < 3; c++) m->v[3 * m->nv + c] = 0.5f * (m->v[3 * a + c] + m->v[3 * b + c]);
    return m->nv++;
}

/* One level: every triangle into 4; -1 when out of memory. */
static int subdivide(mesh_in *m)
{
    edge_table E;
    long nf = m->nf, f, i, *nfaces;
    E.cap = 3 * nf + 1;
    E.key = malloc((size_t)E.cap * 2 * sizeof(long)); E.mid = malloc((size_t)E.cap * sizeof(long));
    nfaces = malloc((size_t)nf * 12 * sizeof(long));
    if (!E.key || !E.mid || !nfaces || grow((void **)&m->v, &m->capv, 3 * (m->nv + 3 * nf), sizeof(float))) {
        free(E.key); free(E.mid); free(nfaces);
        return -1;
    }
    for (i = 0; i < 2 * E.cap; i++) E.key[i] = -1;
    for (f = 0; f < nf; f++) {
        long a = m->f[3 * f], b = m->f[3 * f + 1], c = m->f[3 * f + 2];
        long ab = midpoint(m, &E, a, b), bc = midpoint(m, &E, b, c), ca = midpoint(m, &E, c, a);
        long t[12] = {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca};
        memcpy(&nfaces[12 * f], t, sizeof t);
    }
    free(m->f); free(E.key); free(E.mid);
    m->f = nfaces; m->nf = 4 * nf; m->capf = 12 * nf;
    return 0;
}

static int write_field(const char *path, const mesh_in *m, long ntris)
{
    char tmp[4096];
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    long copies = (ntris + m->nf - 1) / m->nf, g = (long)ceil(sqrt((double)copies)), c, i;
    int a, bad = 0;
    FILE *out;
    for (i = 0; i < m->nv; i++)
        for (a = 0; a < 3; a++) { lo[a] = fmin(lo[a], m->v[3 * i + a]); hi[a] = fmax(hi[a], m->v[3 * i + a]); }
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.tmp", path) >= sizeof tmp || !(out = fopen(tmp, "w"))) {
        fprintf(stderr, "bench-scale-mesh: cannot write %s.tmp\n", path);
        return -1;
    }
    setvbuf(out, NULL, _IOFBF, 1 << 20);
    fprintf(out, "# %ld copies of a mesh of %ld triangles: %ld triangles (bench/scale_mesh.c)\n", copies, m->nf, copies * m->nf);
    for (c = 0; c < copies && !bad; c++) bad = write_copy(out, m, c, g, lo, hi);
    if (fclose(out) || bad || rename(tmp, path)) {
        fprintf(stderr, "bench-scale-mesh: writing %s failed\n", path);
        remove(tmp);
        return -1;
    }
    printf("%s: %ld copies, %ld triangles, %ld vertices\n", path, copies, copies * m->nf, copies * m->nv);
    return 0;
}

int main(int argc, char **argv)
{
    mesh_in m = {NULL, 0, 0, NULL, 0, 0};
    char *end;
    long ntris;
    int rc;
    if (argc < 4 || argc > 5 || (argc == 5 && strcmp(argv[4], "subdivide"))) {
        fprintf(stderr, "usage: bench-scale-mesh MESH.obj NTRIS OUT.obj [subdivide]\n");
        return 2;
    }
    ntris = strtol(argv[2], &end, 10);
    if (*end || ntris < 1 || ntris > 1000000000L) { fprintf(stderr, "bench-scale-mesh: bad NTRIS %s\n", argv[2]); return 2; }
    rc = read_mesh(argv[1], &m) ? 2 : 0;
    while (!rc && argc == 5 && m.nf < ntris)
        if (subdivide(&m)) { fprintf(stderr, "bench-scale-mesh: out of memory\n"); rc = 2; }
    if (!rc && write_field(argv[3], &m, argc == 5 ? m.nf : ntris)) rc = 2;
    free(m.v); free(m.f);
    return rc;
}
