/* test_bvh.c — the BVH against brute force, watertightness, and self-intersection.
 *  1. Triangle soups of several sizes and distributions (uniform, clustered, long and thin, big and
 *     small, coplanar on axis planes, duplicated, exponentially spaced): for random rays the bvh's
 *     closest hit has exactly the t of a loop over every triangle with the same triangle test, and
 *     bvh_occluded agrees. Axis-parallel rays (zero direction components) and finite tmax included.
 *  2. Closed meshes (an icosphere, a cube of many triangles), also moved 1e4 away: rays from inside
 *     and from outside aimed exactly at shared vertices and at points of shared edges never miss.
 *  3. tmax: a hit at t is reported with tmax = next float above t, not with tmax = t.
 *  4. Builds with 1, 2, 3 and 8 threads give the same hits; past 2^20 triangles (the root binned on
 *     two threads), the tree of 2 threads is that of 1.
 *  5. offset_ray_origin: rays leaving points of triangles 1e5 from the origin never hit their own;
 *     its move is 16 ldexpf(1, ilogbf(fmaxf(scale, FLT_MIN)) - 23) (the libm formula it replaced)
 *     for every kind of scale, and triangle_scale is the largest |coordinate|.
 *  6. big_array (the BVH's arrays): aligned, writable, NULL when n * size overflows.
 *  7. 1 and 2 again with the triangles split before the build (BVH_BUILD_SPLIT): the same hits.
 * Sanitizer builds, and PATHLAB_TEST_QUICK=1, shrink the sizes. */
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "sys/big_array.h"
#include "check.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

static int quick;
static int quality = BVH_BUILD_DEFAULT;   /* of the trees built by build() */
static const char *quality_tag(void) { return quality == BVH_BUILD_SPLIT ? "_split" : ""; }
static bvh *build(const vec3 *P, const int *tri, int ntris, int threads) { return bvh_build_quality(P, tri, ntris, threads, quality); }

/* ---- Random numbers: a 64-bit LCG, its top bits -------------------------------------------- */
static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;
static float rnd(void)   /* [0, 1) */
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (float)(rng_state >> 40) * (1.0f / 16777216.0f);
}
static float rnd_range(float lo, float hi) { return lo + (hi - lo) * rnd(); }
static vec3 rnd_vec(float lo, float hi) { return v3(rnd_range(lo, hi), rnd_range(lo, hi), rnd_range(lo, hi)); }
static vec3 rnd_dir(void)
{
    for (;;) {
        vec3 d = rnd_vec(-1, 1);
        float l = v3_dot(d, d);
        if (l > 1e-4f && l <= 1) return v3_scale(d, 1.0f / sqrtf(l));
    }
}

/* ---- Meshes ------------------------------------------------------------------------------------ */
typedef struct { vec3 *P; int *tri; int nverts, ntris, cap_v, cap_t; } soup;

static int add_vert(soup *s, vec3 p)
{
    if (s->nverts == s->cap_v) { s->cap_v = s->cap_v ? 2 * s->cap_v : 64; s->P = realloc(s->P, (size_t)s->cap_v * sizeof(vec3)); }
    s->P[s->nverts] = p;
    return s->nverts++;
}
static void add_tri_idx(soup *s, int a, int b, int c)
{
    if (s->ntris == s->cap_t) { s->cap_t = s->cap_t ? 2 * s->cap_t : 64; s->tri = realloc(s->tri, 3 * (size_t)s->cap_t * sizeof(int)); }
    s->tri[3 * s->ntris] = a; s->tri[3 * s->ntris + 1] = b; s->tri[3 * s->ntris + 2] = c;
    s->ntris++;
}
static void add_tri(soup *s, vec3 a, vec3 b, vec3 c) { add_tri_idx(s, add_vert(s, a), add_vert(s, b), add_vert(s, c)); }
static void soup_free(soup *s) { free(s->P); free(s->tri); memset(s, 0, sizeof *s); }
static vec3 corner(const soup *s, int t, int k) { return s->P[s->tri[3 * t + k]]; }

enum { UNIFORM, CLUSTERED, THIN, MIXED, COPLANAR, DUPLICATES, EXPONENTIAL, NKINDS };
static const char *kind_name[NKINDS] = {"uniform", "clustered", "thin", "mixed", "coplanar", "duplicates", "exponential"};

static void make_soup(soup *s, int kind, int n)
{
    vec3 centers[8];
    int i, k;
    for (k = 0; k < 8; k++) centers[k] = rnd_vec(-1, 1);
    for (i = 0; i < n; i++) {
        vec3 c = rnd_vec(-1, 1);
        float size = 0.1f;
        if (kind == CLUSTERED) { c = v3_add(centers[i % 8], rnd_vec(-0.01f, 0.01f)); size = 0.005f; }
        if (kind == MIXED) size = (i % 10 == 0) ? 1.5f : 0.01f;
        if (kind == EXPONENTIAL) { float e = ldexpf(1.0f, -(i % 40)); c = v3(e, e * rnd(), e * rnd()); size = 0.3f * e; }
        if (kind == THIN) {
            int axis = i % 3;
            vec3 a = rnd_vec(-1, 1), b = a;
            if (axis == 0) b.x = -a.x; else if (axis == 1) b.y = -a.y; else b.z = -a.z;
            add_tri(s, a, b, v3_add(a, rnd_vec(-1e-3f, 1e-3f)));
        } else if (kind == COPLANAR) {   /* on the planes x, y or z = a multiple of 1/4 */
            int axis = i % 3;
            float plane = (float)((int)rnd_range(-4, 5)) * 0.25f;
            vec3 p[3];
            for (k = 0; k < 3; k++) {
                p[k] = v3_add(c, rnd_vec(-size, size));
                if (axis == 0) p[k].x = plane; else if (axis == 1) p[k].y = plane; else p[k].z = plane;
            }
            add_tri(s, p[0], p[1], p[2]);
        } else if (kind == DUPLICATES && i > 0 && i % 3 != 0) {
            int t = s->ntris - 1;      /* the same triangle again: shared indices, then new copies */
            if (i % 3 == 1) add_tri_idx(s, s->tri[3 * t], s->tri[3 * t + 1], s->tri[3 * t + 2]);
            else add_tri(s, corner(s, t, 0), corner(s, t, 1), corner(s, t, 2));
        } else
            add_tri(s, v3_add(c, rnd_vec(-size, size)), v3_add(c, rnd_vec(-size, size)), v3_add(c, rnd_vec(-size, size)));
    }
}

/* Icosphere of radius r around c: an icosahedron subdivided `levels` times, vertices shared. */
static int midpoint(soup *s, int a, int b, int *cache_a, int *cache_b, int *cache_m, int *ncache, vec3 c, float r)
{
    vec3 m;
    int i, k;
    for (i = 0; i < *ncache; i++)
        if ((cache_a[i] == a && cache_b[i] == b) || (cache_a[i] == b && cache_b[i] == a)) return cache_m[i];
    m = v3_scale(v3_add(v3_sub(s->P[a], c), v3_sub(s->P[b], c)), 0.5f);
    k = add_vert(s, v3_add(c, v3_scale(v3_normalize(m), r)));
    cache_a[*ncache] = a; cache_b[*ncache] = b; cache_m[*ncache] = k; ++*ncache;
    return k;
}

static void make_icosphere(soup *s, vec3 c, float r, int levels)
{
    static const int F[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5},
        {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    float g = (1.0f + sqrtf(5.0f)) / 2;
    vec3 V[12] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                  {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    int i, l;
    for (i = 0; i < 12; i++) add_vert(s, v3_add(c, v3_scale(v3_normalize(V[i]), r)));
    for (i = 0; i < 20; i++) add_tri_idx(s, F[i][0], F[i][1], F[i][2]);
    for (l = 0; l < levels; l++) {
        int n = s->ntris, *old = malloc(3 * (size_t)n * sizeof(int)), ncache = 0;
        int *ca = malloc(3 * (size_t)n * sizeof(int)), *cb = malloc(3 * (size_t)n * sizeof(int)), *cm = malloc(3 * (size_t)n * sizeof(int));
        int t;
        memcpy(old, s->tri, 3 * (size_t)n * sizeof(int));
        s->ntris = 0;
        for (t = 0; t < n; t++) {
            int a = old[3 * t], b = old[3 * t + 1], d = old[3 * t + 2];
            int ab = midpoint(s, a, b, ca, cb, cm, &ncache, c, r), bd = midpoint(s, b, d, ca, cb, cm, &ncache, c, r);
            int da = midpoint(s, d, a, ca, cb, cm, &ncache, c, r);
            add_tri_idx(s, a, ab, da); add_tri_idx(s, b, bd, ab); add_tri_idx(s, d, da, bd); add_tri_idx(s, ab, bd, da);
        }
        free(old); free(ca); free(cb); free(cm);
    }
}

/* Cube [c - h, c + h] whose faces are n x n grids of quads split in two, vertices shared. */
static void make_cube(soup *s, vec3 c, float h, int n)
{
    int base = s->nverts;
    /* every grid point of the cube surface, indexed by (i, j, k) in [0, n]^3 */
    int *id = malloc((size_t)(n + 1) * (n + 1) * (n + 1) * sizeof(int));
    int i, j, k, axis, side, u, v;
    for (i = 0; i <= n; i++)
        for (j = 0; j <= n; j++)
            for (k = 0; k <= n; k++) {
                int on = i == 0 || i == n || j == 0 || j == n || k == 0 || k == n;
                vec3 p = v3(c.x - h + 2 * h * i / n, c.y - h + 2 * h * j / n, c.z - h + 2 * h * k / n);
                id[(i * (n + 1) + j) * (n + 1) + k] = on ? add_vert(s, p) : -1;
            }
    for (axis = 0; axis < 3; axis++)
        for (side = 0; side <= n; side += n)
            for (u = 0; u < n; u++)
                for (v = 0; v < n; v++) {
                    int q[4], uv[4][2] = {{u, v}, {u + 1, v}, {u + 1, v + 1}, {u, v + 1}};
                    for (k = 0; k < 4; k++) {
                        int g[3];
                        g[axis] = side; g[(axis + 1) % 3] = uv[k][0]; g[(axis + 2) % 3] = uv[k][1];
                        q[k] = id[(g[0] * (n + 1) + g[1]) * (n + 1) + g[2]];
                    }
                    add_tri_idx(s, q[0], q[1], q[2]);
                    add_tri_idx(s, q[0], q[2], q[3]);
                }
    (void)base;
    free(id);
}

/* ---- Brute force ------------------------------------------------------------------------------- */
static int brute_intersect(const soup *s, const ray *r, hit *best)
{
    ray rr = *r;
    int t;
    best->tri = -1;
    for (t = 0; t < s->ntris; t++) {
        hit h;
        if (bvh_triangle_hit(corner(s, t, 0), corner(s, t, 1), corner(s, t, 2), &rr, &h)) {
            *best = h; best->tri = t;
            rr.tmax = h.t;     /* strictly closer from now on, like the bvh */
        }
    }
    return best->tri >= 0;
}

/* 1 if a triangle other than except is hit with t in (0, tmax): bvh_occluded_except by brute force. */
static int brute_any_except(const soup *s, const ray *r, int except)
{
    int t;
    hit h;
    for (t = 0; t < s->ntris; t++)
        if (t != except && bvh_triangle_hit(corner(s, t, 0), corner(s, t, 1), corner(s, t, 2), r, &h)) return 1;
    return 0;
}

/* 1 when the bvh's answer for r matches brute force; *why says how it does not. */
static int agrees(const bvh *b, const soup *s, const ray *r, const char **why)
{
    hit hb, hf, again;
    int ib = bvh_intersect(b, r, &hb), ifb = brute_intersect(s, r, &hf), oc = bvh_occluded(b, r);
    *why = "";
    if (ib != ifb) { *why = ib ? "bvh hit, brute force missed" : "bvh missed, brute force hit"; return 0; }
    if (oc != ifb) { *why = "occluded disagrees"; return 0; }
    if (!ib) return hb.tri == -1 || (*why = "tri not -1 on a miss", 0);
    if (hb.t != hf.t) { *why = "different t"; return 0; }
    if (!(hb.t > 0 && hb.t < r->tmax)) { *why = "t out of (0, tmax)"; return 0; }
    /* ties: of the triangles at the same t, the smallest index, as brute force keeps it (the rule
     * that makes the hit independent of the order of the visits, which differs between copies) */
    if (hb.tri != hf.tri) { *why = "not the smallest index of the triangles at that t"; return 0; }
    /* a shadow ray blind to one triangle: the one hit first, then one it may not hit */
    if (bvh_occluded_except(b, r, hb.tri) != brute_any_except(s, r, hb.tri)) { *why = "occluded_except (the hit) disagrees"; return 0; }
    if (!bvh_occluded_except(b, r, hb.tri + 1 < s->ntris ? hb.tri + 1 : -1)) { *why = "occluded_except (another) misses"; return 0; }
    if (!bvh_triangle_hit(corner(s, hb.tri, 0), corner(s, hb.tri, 1), corner(s, hb.tri, 2), r, &again) ||
        again.t != hb.t || again.u != hb.u || again.v != hb.v) { *why = "hit triangle does not give that t, u, v"; return 0; }
    return 1;
}

static ray random_ray(float extent)
{
    ray r;
    r.o = rnd_vec(-extent, extent);
    r.d = rnd_dir();
    switch ((int)(rnd() * 8)) {      /* a quarter with zero direction components */
    case 0: r.d = v3(rnd() < 0.5f ? -1.0f : 1.0f, 0, 0); break;
    case 1: r.d = v3_normalize(v3(0, r.d.y, r.d.z)); break;
    default: break;
    }
    if (rnd() < 0.1f) r.o.x = 0.25f * (float)(int)rnd_range(-4, 5);   /* origin on a coplanar plane */
    r.tmax = rnd() < 0.3f ? rnd_range(0.1f, 3.0f) : INFINITY;
    return r;
}

/* A ray through a corner of a random triangle that lies in a plane of the triangle's box: zero
 * direction components, origin on the plane, so the slab test meets 0 * inf = NaN. */
static ray ray_in_box_plane(const soup *s)
{
    int t = (int)(rnd() * (float)s->ntris), axis = (int)(rnd() * 3);
    vec3 a = corner(s, t, (int)(rnd() * 3)), off = rnd_vec(-0.5f, 0.5f);
    ray r;
    if (axis == 0) off.x = 0; else if (axis == 1) off.y = 0; else off.z = 0;
    if (rnd() < 0.3f) off = axis == 0 ? v3(0, 0, off.z) : axis == 1 ? v3(off.x, 0, 0) : v3(0, off.y, 0);
    if (v3_is_zero(off)) off = v3(0, 0, 0.5f);
    r.o = v3_add(a, off);
    r.d = v3_sub(a, r.o);   /* exact zeros where off is zero: the ray stays in those planes */
    r.tmax = INFINITY;
    return r;
}

/* Also aims a third of the rays at a random triangle's centroid so that most rays hit something,
 * and a sixth at triangle corners along planes of their boxes. */
static void test_soup(int kind, int n, int nrays)
{
    soup s = {0};
    bvh *b;
    int bad = 0, hits = 0, i;
    const char *why = "", *first_why = "";
    char name[64];
    make_soup(&s, kind, n);
    b = build(s.P, s.tri, s.ntris, 2);
    for (i = 0; i < nrays && b; i++) {
        ray r = random_ray(1.5f);
        hit h;
        if (i % 3 == 0) {
            int t = (int)(rnd() * (float)s.ntris);
            vec3 m = v3_scale(v3_add(v3_add(corner(&s, t, 0), corner(&s, t, 1)), corner(&s, t, 2)), 1.0f / 3);
            r.d = v3_normalize(v3_sub(m, r.o));
        } else if (i % 3 == 1 && i % 2 == 0)
            r = ray_in_box_plane(&s);
        hits += bvh_intersect(b, &r, &h);
        if (!agrees(b, &s, &r, &why)) { if (!bad++) first_why = why; }
    }
    snprintf(name, sizeof name, "soup_%s_%d%s", kind_name[kind], n, quality_tag());
    check(b && bad == 0, name, "%d of %d rays disagree with brute force (%s); %d hits", bad, nrays, first_why, hits);
    bvh_free(b);
    soup_free(&s);
}

/* ---- The root, binned on two threads ------------------------------------------------------------
 * A node of at least BVH_HALVES_MIN (2^20) triangles is binned in two halves on two threads when a
 * thread is free, whose bins are merged: the tree must be the one of one pass (a build on one
 * thread), node for node, and find the same hits, which agree with brute force. */
static void test_halves(void)
{
    soup s = {0};
    int n = (1 << 20) + 4096, bad = 0, brute = 0, stats[2][3], ok = 1, i, k;
    bvh *b[2];
    const char *why = "";
    for (i = 0; i < n; i++) {   /* tiny triangles: few overlap, so rays and brute force stay quick */
        vec3 c = i < n / 2 ? rnd_vec(0.5f, 1) : rnd_vec(-1, 1);   /* halves unlike: both must count */
        add_tri(&s, v3_add(c, rnd_vec(-2e-3f, 2e-3f)), v3_add(c, rnd_vec(-2e-3f, 2e-3f)), v3_add(c, rnd_vec(-2e-3f, 2e-3f)));
    }
    for (k = 0; k < 2; k++) {
        b[k] = bvh_build(s.P, s.tri, s.ntris, k + 1);
        if (b[k]) bvh_stats(b[k], &stats[k][0], &stats[k][1], &stats[k][2]);
        ok = ok && b[k];
    }
    for (i = 0; i < 2000 && ok; i++) {
        ray r = random_ray(1.5f);
        hit h[2];
        int got[2];
        if (i % 2) {   /* every other ray at a triangle */
            int t = (int)(rnd() * (float)s.ntris);
            vec3 m = v3_scale(v3_add(v3_add(corner(&s, t, 0), corner(&s, t, 1)), corner(&s, t, 2)), 1.0f / 3);
            r.d = v3_normalize(v3_sub(m, r.o));
        }
        for (k = 0; k < 2; k++) got[k] = bvh_intersect(b[k], &r, &h[k]);
        bad += got[1] != got[0] || (got[0] && (h[1].t != h[0].t || h[1].tri != h[0].tri));
        if (i < 8) brute += !agrees(b[1], &s, &r, &why);   /* 8: a loop over a million triangles is slow */
    }
    ok = ok && !memcmp(stats[0], stats[1], sizeof stats[0]);
    check(ok && bad == 0 && brute == 0, "root_binned_on_two_threads_same_tree",
          "%d triangles: %d of 2000 rays differ between 1 and 2 threads, %d of 8 from brute force (%s); nodes %d / %d, leaves %d / %d, depth %d / %d",
          n, bad, brute, why, stats[0][0], stats[1][0], stats[0][1], stats[1][1], stats[0][2], stats[1][2]);
    for (k = 0; k < 2; k++) bvh_free(b[k]);
    soup_free(&s);
}

/* ---- Watertightness ------------------------------------------------------------------------ */
/* Rays toward targets: every vertex, and points of every edge at several fractions. From inside,
 * o is fixed; from outside (outside != 0), o lies beyond the target, away from the centre, so that
 * the ray enters the (convex) solid at the target instead of grazing its silhouette. */
static int count_misses(const bvh *b, const soup *s, vec3 o, int outside, vec3 center, int *nrays)
{
    static const float frac[] = {0.5f, 0.25f, 1.0f / 3.0f, 0.1f, 0.999f, 1e-4f};
    int misses = 0, t, k, f;
    for (t = 0; t < s->ntris; t++)
        for (k = 0; k < 3; k++) {
            vec3 a = corner(s, t, k), c = corner(s, t, (k + 1) % 3);
            for (f = -1; f < (int)(sizeof frac / sizeof frac[0]); f++) {
                vec3 target = f < 0 ? a : v3_add(a, v3_scale(v3_sub(c, a), frac[f]));
                ray r;
                hit h;
                if (outside) {
                    vec3 out = v3_sub(target, center);
                    o = v3_add(target, v3_add(v3_scale(out, 2.0f), v3_scale(rnd_dir(), 0.3f * v3_length(out))));
                }
                r.o = o; r.d = v3_sub(target, o); r.tmax = INFINITY;
                if (v3_is_zero(r.d)) continue;
                ++*nrays;
                if (!bvh_intersect(b, &r, &h) || !bvh_occluded(b, &r)) misses++;
            }
        }
    return misses;
}

static void test_closed(const char *name, const soup *s, vec3 center, float radius)
{
    bvh *b = build(s->P, s->tri, s->ntris, 2);
    int miss_in = 0, miss_out = 0, nin = 0, nout = 0;
    vec3 inside[3] = {center, v3_add(center, v3_scale(v3(0.3f, -0.2f, 0.1f), radius)),
                      v3_add(center, v3_scale(v3(-0.05f, 0.4f, -0.3f), radius))};
    int i;
    for (i = 0; i < 3 && b; i++) miss_in += count_misses(b, s, inside[i], 0, center, &nin);
    if (b) miss_out = count_misses(b, s, center, 1, center, &nout);
    check(b && miss_in + miss_out == 0, name, "%d misses of %d rays from inside, %d of %d from outside, at vertices and edges",
          miss_in, nin, miss_out, nout);
    bvh_free(b);
}

/* Axis-parallel rays from inside the cube through grid points of its faces: the direction has two
 * zero components and the origin lies on box planes of the bvh. */
static void test_axis_rays(const char *name, const soup *cube, vec3 c, float h, int n)
{
    bvh *b = build(cube->P, cube->tri, cube->ntris, 1);
    int misses = 0, nrays = 0, i, j, axis, sign;
    for (i = 1; i < n && b; i++)
        for (j = 1; j < n; j++)
            for (axis = 0; axis < 3; axis++)
                for (sign = -1; sign <= 1; sign += 2) {
                    float g[3] = {c.x, c.y, c.z}, d[3] = {0, 0, 0}, u = -h + 2 * h * i / n, v = -h + 2 * h * j / n;
                    ray r;
                    hit hh;
                    g[(axis + 1) % 3] += u; g[(axis + 2) % 3] += v; d[axis] = (float)sign;
                    r.o = v3(g[0], g[1], g[2]); r.d = v3(d[0], d[1], d[2]); r.tmax = INFINITY;
                    nrays++;
                    if (!bvh_intersect(b, &r, &hh) || !bvh_occluded(b, &r)) misses++;
                }
    check(b && misses == 0, name, "%d misses of %d axis-parallel rays", misses, nrays);
    bvh_free(b);
}

static void test_watertight(void)
{
    vec3 far = v3(1e4f, -1e4f, 1e4f);
    int levels = quick ? 3 : 4, grid = quick ? 8 : 16, moved;
    for (moved = 0; moved < 2; moved++) {
        vec3 c = moved ? far : v3(0, 0, 0);
        soup sphere = {0}, cube = {0};
        char name[64];
        make_icosphere(&sphere, c, 1.0f, levels);
        make_cube(&cube, c, 1.0f, grid);
        snprintf(name, sizeof name, "watertight_icosphere%s%s", moved ? "_at_1e4" : "", quality_tag());
        test_closed(name, &sphere, c, 1.0f);
        snprintf(name, sizeof name, "watertight_cube%s%s", moved ? "_at_1e4" : "", quality_tag());
        test_closed(name, &cube, c, 1.0f);
        snprintf(name, sizeof name, "watertight_cube_axis_rays%s%s", moved ? "_at_1e4" : "", quality_tag());
        test_axis_rays(name, &cube, c, 1.0f, grid);
        soup_free(&sphere); soup_free(&cube);
    }
}

/* ---- tmax, threads, empty ------------------------------------------------------------------ */
static void test_tmax(void)
{
    soup s = {0};
    bvh *b;
    int bad = 0, tested = 0, i;
    make_soup(&s, UNIFORM, 2000);
    b = bvh_build(s.P, s.tri, s.ntris, 1);
    for (i = 0; i < 2000 && b; i++) {
        ray r = {rnd_vec(-1.5f, 1.5f), rnd_dir(), INFINITY};
        hit h, h2;
        if (!bvh_intersect(b, &r, &h)) continue;
        tested++;
        r.tmax = h.t;                        /* the hit is at t = tmax: not in (0, tmax) */
        if (bvh_intersect(b, &r, &h2) && h2.t >= h.t) bad++;
        if (bvh_occluded(b, &r) != bvh_intersect(b, &r, &h2)) bad++;
        r.tmax = nextafterf(h.t, INFINITY);  /* now it is */
        if (!bvh_intersect(b, &r, &h2) || h2.t != h.t || !bvh_occluded(b, &r)) bad++;
    }
    check(b && bad == 0 && tested > 100, "tmax_exclusive", "%d failures over %d hit rays", bad, tested);
    bvh_free(b);
    soup_free(&s);
}

#define NBUILDS 6
static void test_threads(void)
{
    /* 8 threads on 2 cores, three times: threads come free while others still build, and the build
     * hands them subtrees deep inside ones built on one thread (a race, hence the repeats) */
    static const int threads[NBUILDS] = {1, 2, 3, 8, 8, 8};
    soup s = {0};
    int n = quick ? 20000 : 100000, bad = 0, stats[NBUILDS][3] = {{0}}, ok = 1, i, k;
    bvh *b[NBUILDS];
    make_soup(&s, UNIFORM, n);   /* not MIXED: its 10% of big triangles make every ray slow */
    for (k = 0; k < NBUILDS; k++) {
        b[k] = bvh_build(s.P, s.tri, s.ntris, threads[k]);
        if (b[k]) bvh_stats(b[k], &stats[k][0], &stats[k][1], &stats[k][2]);
        ok = ok && b[k];
    }
    for (i = 0; i < 20000 && ok; i++) {
        ray r = random_ray(1.5f);
        hit h[NBUILDS];
        int got[NBUILDS];
        for (k = 0; k < NBUILDS; k++) got[k] = bvh_intersect(b[k], &r, &h[k]);
        for (k = 1; k < NBUILDS; k++)
            if (got[k] != got[0] || (got[0] && (h[k].t != h[0].t || h[k].tri != h[0].tri || h[k].u != h[0].u))) bad++;
    }
    for (k = 1; k < NBUILDS && ok; k++) ok = !memcmp(stats[0], stats[k], sizeof stats[0]);
    check(ok && bad == 0, "threads_same_hits", "1, 2, 3, 8, 8, 8 threads: %d differences; nodes %d %d %d %d, leaves %d, depth %d",
          bad, stats[0][0], stats[1][0], stats[2][0], stats[3][0], stats[0][1], stats[0][2]);
    for (k = 0; k < NBUILDS; k++) bvh_free(b[k]);
    soup_free(&s);
}

static void test_empty_and_single(void)
{
    vec3 P[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    int tri[3] = {0, 1, 2};
    bvh *e = bvh_build(P, tri, 0, 1), *one = bvh_build(P, tri, 1, 4);
    ray r = {v3(0.25f, 0.25f, 1), v3(0, 0, -1), INFINITY};
    hit h;
    int ok_e = e && !bvh_intersect(e, &r, &h) && h.tri == -1 && !bvh_occluded(e, &r);
    int ok_1 = one && bvh_intersect(one, &r, &h) && h.tri == 0 && h.t == 1.0f && h.u == 0.25f && h.v == 0.25f && bvh_occluded(one, &r);
    check(ok_e, "empty_bvh_misses", NULL);
    check(ok_1, "single_triangle", "t %g u %g v %g", (double)h.t, (double)h.u, (double)h.v);
    r.d = v3(0, 0, 1);
    check(one && !bvh_intersect(one, &r, &h) && !bvh_occluded(one, &r), "behind_origin_misses", NULL);
    bvh_free(e); bvh_free(one);
}

/* ---- offset_ray_origin --------------------------------------------------------------------- */
/* Direction about n with cos theta >= mincos. */
static vec3 rnd_hemisphere(vec3 n, float mincos)
{
    for (;;) {
        vec3 d = rnd_dir();
        if (v3_dot(d, n) >= mincos) return d;
    }
}

/* Points on triangles of an icosphere of radius 10 moved 1e5 away; rays leave outward (must miss
 * everything) and inward from the point offset along -n (must not hit their own triangle). */
static void test_offset(void)
{
    soup s = {0};
    bvh *b;
    int self = 0, self_raw = 0, rays = 0, i, side;
    make_icosphere(&s, v3(1e5f, -1e5f, 1e5f), 10.0f, 3);
    b = bvh_build(s.P, s.tri, s.ntris, 1);
    for (i = 0; i < (quick ? 5000 : 40000) && b; i++) {
        int t = (int)(rnd() * (float)s.ntris);
        vec3 a = corner(&s, t, 0), bb = corner(&s, t, 1), c = corner(&s, t, 2);
        vec3 n = v3_normalize(v3_cross(v3_sub(bb, a), v3_sub(c, a)));   /* outward */
        float u = rnd(), v = rnd();
        vec3 p;
        if (u + v > 1) { u = 1 - u; v = 1 - v; }
        p = v3_add(a, v3_add(v3_scale(v3_sub(bb, a), u), v3_scale(v3_sub(c, a), v)));
        for (side = -1; side <= 1; side += 2) {
            vec3 ns = v3_scale(n, (float)side);
            ray r = {offset_ray_origin(p, ns, triangle_scale(a, bb, c)), rnd_hemisphere(ns, 0.01f), INFINITY}, raw = r;
            hit h;
            raw.o = p;
            rays++;
            if (bvh_intersect(b, &r, &h) && h.tri == t) self++;
            if (bvh_intersect(b, &raw, &h) && h.tri == t) self_raw++;
        }
    }
    check(b && self == 0, "offset_origin_no_self_hit_at_1e5", "%d self hits of %d rays (%d without the offset)", self, rays, self_raw);
    bvh_free(b);
    soup_free(&s);
}

/* ---- offset_ray_origin's move, triangle_scale, big_array ------------------------------------ */
static void test_offset_formula(void)
{
    static const float special[] = {0.0f, FLT_MIN, FLT_MIN / 2, 0x1p-149f, 1.0f, 1.5f, 0x1.fffffep0f, 2.0f,
                                    1e-30f, 3e5f, FLT_MAX, INFINITY, NAN};
    int bad = 0, i, n = (int)(sizeof special / sizeof special[0]);
    for (i = 0; i < n + 100000; i++) {
        float s = i < n ? special[i] : ldexpf(rnd_range(1.0f, 2.0f), (int)rnd_range(-140.0f, 127.0f));
        float want = 16.0f * ldexpf(1.0f, ilogbf(fmaxf(s, FLT_MIN)) - 23);
        vec3 o = offset_ray_origin(v3(0, 0, 0), v3(1, 0, 0), s);
        if (memcmp(&o.x, &want, sizeof want) != 0) bad++;
    }
    check(bad == 0, "offset_libm_formula", "%d of %d scales moved otherwise than 16 ldexpf(1, ilogbf(fmaxf(s, FLT_MIN)) - 23)", bad, n + 100000);
    check(triangle_scale(v3(1, -7, 2), v3(3, 0.5f, -6.5f), v3(-2, 4, 0)) == 7.0f &&
          triangle_scale(v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, -0.25f)) == 0.25f,
          "triangle_scale", "the largest |coordinate| of the three corners");
}

static void test_big_array(void)
{
    size_t n = (size_t)1 << 20, i;   /* 8 MiB: the huge-page advice applies */
    double *a = big_array(n, sizeof(double), 64), sum = 0;
    for (i = 0; a && i < n; i++) a[i] = (double)i;
    for (i = 0; a && i < n; i++) sum += a[i];
    check(a && (uintptr_t)a % 64 == 0 && sum == (double)n * (double)(n - 1) / 2, "big_array",
          "8 MiB: %s", a ? "aligned to 64, every element written and read back" : "NULL");
    free(a);
    check(big_array((size_t)-1 / 16 + 1, 16, 64) == NULL, "big_array_overflow", "n * size past SIZE_MAX gives NULL");
}

/* ---- Instruction sets ------------------------------------------------------------------------
 * The traversal is compiled for SSE2, AVX2 + FMA and AVX-512 (x86-64; bvh_isa): every copy this CPU
 * runs must give the very same hits as the base copy, bit for bit (t, u, v, triangle, occlusion),
 * or images would depend on the machine. */
static void test_isa(void)
{
    static const char *const names[] = {"avx512", "avx2", "sse2", "portable"};
    const char *base = bvh_isa_force("sse2") == 0 ? "sse2" : "portable";
    char all[128];
    int k, kind;
    bvh_isa_force(NULL);
    bvh_isa_names(all, sizeof all);
    check(bvh_isa_force("no-such-isa") == -1, "isa_unknown_refused", "compiled in: %s; in use: %s", all, bvh_isa());
    for (k = 0; k < 4; k++) {
        int bad = 0, rays = 0, hits = 0;
        char name[64];
        if (!strcmp(names[k], base) || bvh_isa_force(names[k]) != 0) continue;
        for (kind = 0; kind < NKINDS; kind++) {
            soup s = {0};
            bvh *bx, *b0;
            int i;
            make_soup(&s, kind, 1000);
            bvh_isa_force(names[k]); bx = bvh_build(s.P, s.tri, s.ntris, 2);
            bvh_isa_force(base); b0 = bvh_build(s.P, s.tri, s.ntris, 2);
            for (i = 0; bx && b0 && i < (quick ? 300 : 2000); i++) {
                ray r = i % 2 ? random_ray(1.5f) : ray_in_box_plane(&s);
                hit hx, h0;
                int ix = bvh_intersect(bx, &r, &hx), i0 = bvh_intersect(b0, &r, &h0);
                rays++, hits += i0;
                bad += ix != i0 || hx.tri != h0.tri || (i0 && memcmp(&hx, &h0, sizeof hx) != 0) ||
                       bvh_occluded(bx, &r) != bvh_occluded(b0, &r) ||
                       (i0 && bvh_occluded_except(bx, &r, h0.tri) != bvh_occluded_except(b0, &r, h0.tri));
            }
            if (!bx || !b0) bad++;
            bvh_free(bx), bvh_free(b0), soup_free(&s);
        }
        snprintf(name, sizeof name, "isa_%s_same_hits_as_%s", names[k], base);
        check(bad == 0, name, "%d of %d rays differ (%d hits), %d kinds of soup", bad, rays, hits, NKINDS);
    }
    bvh_isa_force(NULL);
}

/* bvh_any_in_box against brute force: the triangles whose boxes meet a random box, found by a test
 * that accepts one chosen triangle only (found, or not, as brute force says) or every one. */
typedef struct { int want, calls; } box_probe;
static int is_wanted(void *ctx, int tri) { box_probe *q = ctx; q->calls++; return tri == q->want; }

static int box_meets(const soup *s, int t, vec3 lo, vec3 hi)
{
    vec3 a = corner(s, t, 0), b = corner(s, t, 1), c = corner(s, t, 2);
    return fminf(a.x, fminf(b.x, c.x)) <= hi.x && fmaxf(a.x, fmaxf(b.x, c.x)) >= lo.x &&
           fminf(a.y, fminf(b.y, c.y)) <= hi.y && fmaxf(a.y, fmaxf(b.y, c.y)) >= lo.y &&
           fminf(a.z, fminf(b.z, c.z)) <= hi.z && fmaxf(a.z, fmaxf(b.z, c.z)) >= lo.z;
}

static void test_box_query(void)
{
    int kind, bad = 0, found = 0, queries = 0;
    for (kind = 0; kind < NKINDS; kind++) {
        soup s = {0};
        bvh *b;
        int i;
        make_soup(&s, kind, 1000);
        b = bvh_build(s.P, s.tri, s.ntris, 2);
        for (i = 0; b && i < 400; i++) {
            vec3 c = rnd_vec(-1.2f, 1.2f), h = rnd_vec(0.0f, i % 2 ? 0.05f : 0.3f);
            vec3 lo = v3_sub(c, h), hi = v3_add(c, h);
            box_probe q;
            int t, any = 0;
            q.want = (int)(rnd() * (float)s.ntris) % s.ntris, q.calls = 0;
            for (t = 0; t < s.ntris; t++) any |= box_meets(&s, t, lo, hi);
            bad += bvh_any_in_box(b, lo, hi, is_wanted, &q) != box_meets(&s, q.want, lo, hi);
            q.want = -1;
            bad += bvh_any_in_box(b, lo, hi, is_wanted, &q) || (q.calls > 0) != any;
            found += any, queries++;
        }
        if (!b) bad++;
        bvh_free(b), soup_free(&s);
    }
    check(bad == 0, "box_query_brute_force", "%d of %d queries differ (%d meet a triangle)", bad, 2 * queries, found);
}

int main(void)
{
    static const int sizes[] = {1, 2, 5, 17, 100, 1000, 20000};
    int kind, i;
    quick = SANITIZED || getenv("PATHLAB_TEST_QUICK") != NULL;
    for (kind = 0; kind < NKINDS; kind++)
        for (i = 0; i < (int)(sizeof sizes / sizeof sizes[0]); i++) {
            int n = sizes[i], nrays = n >= 20000 ? 300 : 2000;
            if (quick && n > 1000) continue;
            test_soup(kind, n, quick ? nrays / 4 : nrays);
        }
    test_empty_and_single();
    test_tmax();
    test_threads();
    test_halves();
    test_watertight();
    test_offset();
    test_offset_formula();
    test_big_array();
    test_isa();
    test_box_query();
    quality = BVH_BUILD_SPLIT;
    for (kind = 0; kind < NKINDS; kind++)
        for (i = 0; i < (int)(sizeof sizes / sizeof sizes[0]); i++)
            if (sizes[i] <= 1000) test_soup(kind, sizes[i], quick ? 500 : 2000);
    test_watertight();
    return check_summary();
}
