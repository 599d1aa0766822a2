/* visibility.c — the pairs of visibility.h, by separating planes.
 *
 * A segment from a point p of A to a point s of E lies in the convex hull H of their six corners.
 * A triangle T can cross it only where T meets H, and cannot when a plane separates them:
 *  - T's own, with H on one closed side: the open segment stays off that plane, or runs in it, where
 *    the watertight test finds no hit (det = 0);
 *  - A's, with E on one closed side and T on the other: a shadow ray leaves A toward s, cos(theta_p)
 *    > 0, so it runs strictly on E's side (two walls meeting in a ridge);
 *  - E's, with A and T on either side: the ray comes to s from E's front, cos(theta_s) > 0.
 * And a T in the plane of A or of E cannot either: the ray leaves the one and stops before the
 * other. A pair is clear when every T is such: with each side of each plane a bit per triangle
 * (class_of), a pair takes a few ANDs and ORs per 64 triangles.
 *
 * "On the plane" means within ERROR_BOUND of the terms of the signed distance computed (side_of):
 * the corners are floats, the distances are computed in doubles, and their rounding error is a few
 * units of 2^-53 of those terms, bounded here 256 times over. So a T that only touches H (two walls
 * meeting at an edge, at a shared corner) leaves H on one side, and a T that goes in any further,
 * by more than ~2^-45 of the lengths involved, blocks the pair. The bound follows the terms, not the
 * largest coordinate: a light 5e-6 under a ground 1e4 wide is under it (with a tolerance of 2^-30 of
 * the coordinates, as first written, it was in the ground's plane, and lit what the ground hides;
 * tests/test_visibility.c, "mixed scales").
 * The test is on the triangles themselves: a shadow ray's ends are moved off them by
 * offset_ray_origin (16 ulps), and p is rounded. So within ~16 ulps of an edge where A
 * meets a tilted wall, a traced ray could start just behind that wall and find it at t ~ 1e-7; the
 * pair says lit, which is the answer without the move (on McGuire's boxes the images are the same
 * bit for bit: tests/test_visibility_render.sh). */
#include "geometry/visibility.h"
#include "math/dvec.h"
#include "geometry/ray.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* 2^8 times the few units of 2^-53 that bound the rounding of side_of (its comment) */
#define ERROR_BOUND 0x1p-45
/* hull_apart is 65 axes, ~1 us: at most this many per scene (a quarter of a second) */
#define HULL_TESTS_MAX 250000L

/* u x v, and in *terms the magnitudes of its products (|u.y v.z| + |u.z v.y|, ...), which bound
 * its rounding error. */
static dvec cross_terms(dvec u, dvec v, dvec *terms)
{
    terms->x = fabs(u.y * v.z) + fabs(u.z * v.y);
    terms->y = fabs(u.z * v.x) + fabs(u.x * v.z);
    terms->z = fabs(u.x * v.y) + fabs(u.y * v.x);
    return dv_cross(u, v);
}

/* N . (p - o), N = u x v from cross_terms (terms M) with u, v differences of float corners, and in
 * *err a bound on its rounding error: u, v, p - o are each rounded once (relative 2^-53), N's
 * components then carry at most ~4 units of M, and the dot product adds ~3 of |N_i (p - o)_i|: in
 * all less than 5 x 2^-53 x sum (|N_i| + M_i) |p_i - o_i|, bounded by ERROR_BOUND of that sum. */
static double side_of(dvec N, dvec M, dvec o, dvec p, double *err)
{
    dvec d = dv_lin(p, 1.0, o, -1.0);
    *err = ERROR_BOUND * ((fabs(N.x) + M.x) * fabs(d.x) + (fabs(N.y) + M.y) * fabs(d.y) + (fabs(N.z) + M.z) * fabs(d.z));
    return dv_dot(N, d);
}

/* A triangle in doubles: its corners, its plane's normal N (not unit) and the terms M of N. */
typedef struct { dvec c[3], N, M; } dtri;

static void dtri_make(dtri *t, const vec3 *P, const int *corner)
{
    int k;
    for (k = 0; k < 3; k++) t->c[k] = dv_of(P[corner[k]]);
    t->N = cross_terms(dv_lin(t->c[1], 1.0, t->c[0], -1.0), dv_lin(t->c[2], 1.0, t->c[0], -1.0), &t->M);
}

enum { ABOVE = 1, BELOW = 2 };

/* Where X lies against T's plane: ABOVE if its corners are on N's side or on the plane, BELOW if
 * on the other side or on it; both if on it. A T whose plane is not a number (no normal: never in
 * practice, the parser drops zero areas) gets 0: it blocks. */
static int class_of(const dtri *T, const dtri *X)
{
    int k, above = 1, below = 1;
    if (!(dv_dot(T->N, T->N) > 0.0)) return 0;
    for (k = 0; k < 3; k++) {
        double err, s = side_of(T->N, T->M, T->c[0], X->c[k], &err);
        if (!(err < INFINITY)) return 0;
        above &= s >= -err;
        below &= s <= err;
    }
    return (above ? ABOVE : 0) | (below ? BELOW : 0);
}

/* Separating-axis test of T against the hull H of A's and E's corners, for a pair that the planes of
 * T, A and E could not clear (folded walls: two triangles of a quad that is not flat). A separating
 * plane of two convex sets is parallel to a face of one of them or to an edge of each: the faces of
 * H are among the planes through 3 of its 6 points, T's face was tried, and the edge pairs give 15 x
 * 3 axes. Touching counts as separated, as above; a segment that could then meet T lies in the plane
 * through that contact, a set of segments of measure zero. */
/* The projections on the axis N (terms M), from o, are compared with their error bounds (side_of):
 * apart when H's highest point may be no higher than T's lowest, or the other way round, which a
 * contact gives whatever the rounding. */
static int apart_on_axis(dvec N, dvec M, dvec o, const dvec *h, const dvec *t)
{
    double hlo = INFINITY, hhi = -INFINITY, tlo = INFINITY, thi = -INFINITY, s, err;
    int k;
    if (!(dv_dot(N, N) > 0.0)) return 0;
    for (k = 0; k < 6; k++) {
        s = side_of(N, M, o, h[k], &err);
        hlo = s + err < hlo ? s + err : hlo, hhi = s - err > hhi ? s - err : hhi;
    }
    for (k = 0; k < 3; k++) {
        s = side_of(N, M, o, t[k], &err);
        tlo = s + err < tlo ? s + err : tlo, thi = s - err > thi ? s - err : thi;
    }
    return hhi <= tlo || thi <= hlo;   /* false for a NaN */
}

static int hull_apart(const dtri *A, const dtri *E, const dtri *T)
{
    dvec h[6], N, M;
    int i, j, k;
    for (k = 0; k < 3; k++) h[k] = A->c[k], h[3 + k] = E->c[k];
    for (i = 0; i < 6; i++)
        for (j = i + 1; j < 6; j++) {
            for (k = j + 1; k < 6; k++) {   /* planes through three points of H */
                N = cross_terms(dv_lin(h[j], 1.0, h[i], -1.0), dv_lin(h[k], 1.0, h[i], -1.0), &M);
                if (apart_on_axis(N, M, h[i], h, T->c)) return 1;
            }
            for (k = 0; k < 3; k++) {       /* an edge of H and an edge of T */
                N = cross_terms(dv_lin(h[j], 1.0, h[i], -1.0), dv_lin(T->c[(k + 1) % 3], 1.0, T->c[k], -1.0), &M);
                if (apart_on_axis(N, M, h[i], h, T->c)) return 1;
            }
        }
    return 0;
}

/* The sides of every plane, as bit tables of one row of `words` words per triangle: row X of
 * above and below has bit T set when X is so against T's plane (class_of; both: X lies in it); row
 * T of above_of and below_of has bit X set when X is above or below T's plane (the same, transposed). */
typedef struct {
    size_t words;
    uint64_t *above, *below, *above_of, *below_of;
} sides;

static const uint64_t *row(const uint64_t *table, const sides *s, int i) { return table + (size_t)i * s->words; }
static int bit(const uint64_t *table, const sides *s, int i, int j) { return (int)(row(table, s, i)[j >> 6] >> (j & 63) & 1); }

/* 1 if no triangle can block a segment from triangle a to triangle e: every T has a separating plane,
 * its own (a and e on one side of it), a's (T and e on either side) or e's (T and a on either side),
 * or else hull_apart finds one, while *budget lasts (then T blocks). */
static int pair_clear(const sides *s, const dtri *d, int a, int e, int ntris, long *budget)
{
    /* e below a's plane (bit a of e's row): then every T above it is kept off, and so on */
    uint64_t e_below_a = 0 - (uint64_t)bit(s->below, s, e, a), e_above_a = 0 - (uint64_t)bit(s->above, s, e, a);
    uint64_t a_below_e = 0 - (uint64_t)bit(s->below, s, a, e), a_above_e = 0 - (uint64_t)bit(s->above, s, a, e);
    size_t w;
    for (w = 0; w < s->words; w++) {
        uint64_t all = w + 1 < s->words || ntris % 64 == 0 ? ~(uint64_t)0 : ((uint64_t)1 << (ntris % 64)) - 1;
        uint64_t above_a = row(s->above, s, a)[w], below_a = row(s->below, s, a)[w];
        uint64_t above_e = row(s->above, s, e)[w], below_e = row(s->below, s, e)[w];
        /* T's plane holds a or e, or has both on one side */
        uint64_t own = (above_a & below_a) | (above_e & below_e) | (above_a & above_e) | (below_a & below_e);
        uint64_t by_a = (e_below_a & row(s->above_of, s, a)[w]) | (e_above_a & row(s->below_of, s, a)[w]);
        uint64_t by_e = (a_below_e & row(s->above_of, s, e)[w]) | (a_above_e & row(s->below_of, s, e)[w]);
        uint64_t left = ~(own | by_a | by_e) & all;
        int k;
        for (k = 0; k < 64; k++) {
            if (!(left >> k & 1)) continue;
            if (*budget <= 0) return 0;
            --*budget;
            if (!hull_apart(&d[a], &d[e], &d[w * 64 + (size_t)k])) return 0;
        }
    }
    return 1;
}

int pair_visibility_build(pair_visibility *pv, const vec3 *P, const int *tri, int ntris, const int *emitter_tri, int nemitters)
{
    sides s;
    uint64_t *tables;
    dtri *d;
    size_t nbits = (size_t)ntris * (size_t)(nemitters > 0 ? nemitters : 0), table, i;
    long budget = HULL_TESTS_MAX;
    int t, x, e;
    memset(pv, 0, sizeof *pv);
    pv->nemitters = nemitters;
    if (ntris <= 0 || ntris > VISIBILITY_MAX_TRIS || nemitters <= 0) return 0;
    s.words = ((size_t)ntris + 63) / 64;
    table = s.words * (size_t)ntris;
    d = malloc(sizeof *d * (size_t)ntris);
    tables = calloc(4 * table, sizeof *tables);
    pv->bits = calloc((nbits + 7) / 8, 1);
    if (!d || !tables || !pv->bits) {
        free(d); free(tables); pair_visibility_free(pv);
        return 1;
    }
    s.above = tables, s.below = tables + table, s.above_of = tables + 2 * table, s.below_of = tables + 3 * table;
    for (t = 0; t < ntris; t++) dtri_make(&d[t], P, tri + 3 * t);
    for (t = 0; t < ntris; t++)
        for (x = 0; x < ntris; x++) {
            int cls = class_of(&d[t], &d[x]);
            uint64_t bit_t = (uint64_t)1 << (t & 63), bit_x = (uint64_t)1 << (x & 63);
            size_t wx = (size_t)x * s.words + (size_t)(t >> 6), wt = (size_t)t * s.words + (size_t)(x >> 6);
            if (cls & ABOVE) s.above[wx] |= bit_t, s.above_of[wt] |= bit_x;
            if (cls & BELOW) s.below[wx] |= bit_t, s.below_of[wt] |= bit_x;
        }
    for (t = 0; t < ntris; t++)
        for (e = 0; e < nemitters; e++)
            if (emitter_tri[e] != t && pair_clear(&s, d, t, emitter_tri[e], ntris, &budget)) {   /* an emitter does not light itself */
                i = (size_t)t * (size_t)nemitters + (size_t)e;
                pv->bits[i >> 3] |= (unsigned char)(1u << (i & 7));
                pv->npairs++;
            }
    free(d);
    free(tables);
    return 0;
}

void pair_visibility_free(pair_visibility *pv)
{
    free(pv->bits);
    pv->bits = NULL;
    pv->npairs = 0;
}

/* ---- near_blockers_find ---- */
typedef struct { const vec3 *P; const int *tri; int self; vec3 a, n; double size; } slab_query;

/* 1 if triangle t has a corner in front of q's emitter's plane beyond the rounding of points in it. */
static int in_front(void *ctx, int t)
{
    const slab_query *q = ctx;
    double most = -1.0;
    int k;
    if (t == q->self) return 0;
    for (k = 0; k < 3; k++) {
        double h = dv_dot(dv_of(q->n), dv_of(v3_sub(q->P[q->tri[3 * t + k]], q->a)));
        most = h > most ? h : most;
    }
    return most > q->size * 0x1p-20;
}

void near_blockers_find(unsigned char *near, const bvh *b, const vec3 *P, const int *tri, const int *emitter_tri, int nemitters)
{
    int e;
    for (e = 0; e < nemitters; e++) {
        const int *c = tri + 3 * emitter_tri[e];
        vec3 A = P[c[0]], B = P[c[1]], C = P[c[2]];
        float d = 2.0f * v3_length(v3_sub(offset_ray_origin(A, v3(1, 0, 0), triangle_scale(A, B, C)), A));
        vec3 lo = v3(fminf(A.x, fminf(B.x, C.x)) - d, fminf(A.y, fminf(B.y, C.y)) - d, fminf(A.z, fminf(B.z, C.z)) - d);
        vec3 hi = v3(fmaxf(A.x, fmaxf(B.x, C.x)) + d, fmaxf(A.y, fmaxf(B.y, C.y)) + d, fmaxf(A.z, fmaxf(B.z, C.z)) + d);
        slab_query q;
        q.P = P, q.tri = tri, q.self = emitter_tri[e], q.a = A;
        q.n = v3_normalize(v3_cross(v3_sub(B, A), v3_sub(C, A)));
        q.size = v3_length(v3_sub(B, A)) + v3_length(v3_sub(C, A));
        near[e] = (unsigned char)bvh_any_in_box(b, lo, hi, in_front, &q);
    }
}
