/* bvh_traverse.c — the BVH's traversal: a ray against the 8-wide tree that bvh.c builds (see bvh.c
 * for how it is traversed and why it is robust). On x86-64 this file is compiled three times: with
 * the build's flags (SSE2), with AVX2 + FMA and with AVX-512 (the Makefile's ISA_OBJ); each copy
 * exports its entry points as bvh_traversal_ISA, and bvh_build picks the best the CPU runs (bvh_isa).
 * GCC in ISO C mode contracts no multiply-add, so every copy computes the same floats, and the
 * closest hit is the smallest (t, triangle index) whatever the order of the visits: the same hits,
 * the same images (tests/test_isa.sh). */
#include "geometry/bvh.h"
#include "geometry/bvh_layout.h"
#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#ifndef BVH_ISA
#define BVH_ISA base
#endif

/* The AVX2 copy (or a -march=native build on such a CPU) tests blocks with intrinsics and orders
 * the children a closest-hit ray enters with a sorting network (node_step_sorted); -DBVH_NO_AVX2
 * keeps the portable loops there. BVH_INTRINSICS: a copy with hand-written block tests. */
#if defined(__AVX2__) && !defined(BVH_AVX512) && !defined(BVH_NO_AVX2)
#define BVH_AVX2 1
#include <immintrin.h>
#endif
#if defined(BVH_AVX512) || defined(BVH_AVX2)
#define BVH_INTRINSICS 1
#endif

/* GCC fully unrolls a short loop nested in the traversal loop before its vectorizer sees it, and
 * then fails to vectorize the straight-line code: keep the lane loops rolled. */
#if defined(__GNUC__) && !defined(__clang__)
#define LANE_LOOP _Pragma("GCC unroll 1")
#else
#define LANE_LOOP
#endif

/* ---- Traversal ---------------------------------------------------------------------------------
 * The loops over the lanes of a node or a block are written for the vectorizer: restrict pointers,
 * per-ray values in locals, no branch inside, one mask bit per lane at the end. The per-ray values
 * live in a ray_pre whose address never leaves the traversal, so that they stay in registers. */
#ifdef BVH_INTRINSICS   /* a block's lanes are one vector: L_(op) names the intrinsic of its width */
#if BVH_LEAF_MAX == 8
typedef __m256 lanes;
#define L_(op) _mm256_##op
#else
typedef __m128 lanes;
#define L_(op) _mm_##op
#endif
#endif
typedef struct {
    float o[3], inv[3];
    float inv_far[3];      /* inv widened by BVH_BOX_WIDEN, for the exit distances */
    ptrdiff_t near[3], far[3]; /* byte offsets in a wnode of the rows with each axis' entry and exit
                                  planes (pointer-sized: no sign extension per node) */
    int kx, ky, kz;        /* watertight test: kz the dominant axis of d, kx ky the others */
    float Sx, Sy, Sz;      /* shear that maps d to (0, 0, 1) */
#ifdef BVH_INTRINSICS
    lanes bo[3], bS[3];        /* o[kx], o[ky], o[kz] and Sx, Sy, Sz broadcast once per ray for block_hits_v */
#endif
} ray_pre;

/* The watertight test's axes without a branch (a diffuse ray's direction is random, so branches
 * on it mispredict): kz the axis of the largest |d|, as "ax > ay ? (ax > az ? 0 : 2) : (ay > az ?
 * 1 : 2)", indexed by those three comparisons; kx follows kz, or precedes it when d[kz] < 0 (the
 * swap that keeps the winding), and ky is the third axis. */
static const unsigned char KZ_OF[8] = {2, 2, 2, 0, 1, 2, 1, 0}, KX_OF[6] = {1, 2, 0, 2, 0, 1};

static inline void ray_prepare(const ray *r, ray_pre *restrict p)
{
    float o[3] = {r->o.x, r->o.y, r->o.z}, d[3] = {r->d.x, r->d.y, r->d.z};
    float ax = fabsf(d[0]), ay = fabsf(d[1]), az = fabsf(d[2]);
    int a, kx, ky, kz;
    for (a = 0; a < 3; a++) {
        int lo_row = a, hi_row = 3 + a;
        p->o[a] = o[a];
        p->inv[a] = 1.0f / d[a];               /* +-inf for a zero component: the slab is NaN-safe */
        p->inv_far[a] = p->inv[a] * BVH_BOX_WIDEN;
        p->near[a] = (ptrdiff_t)(sizeof(float) * BVH_WIDTH) * (signbit(d[a]) ? hi_row : lo_row);
        p->far[a] = (ptrdiff_t)(sizeof(float) * BVH_WIDTH) * (signbit(d[a]) ? lo_row : hi_row);
    }
    kz = KZ_OF[(ax > ay) | (ax > az) << 1 | (ay > az) << 2];
    kx = KX_OF[kz + 3 * (d[kz] < 0)];
    ky = 3 - kx - kz;
    p->kx = kx; p->ky = ky; p->kz = kz;
    p->Sx = d[kx] / d[kz];
    p->Sy = d[ky] / d[kz];
    p->Sz = p->inv[kz];                        /* 1 / d[kz], computed once */
#ifdef BVH_INTRINSICS
    p->bo[0] = L_(set1_ps)(o[kx]); p->bo[1] = L_(set1_ps)(o[ky]); p->bo[2] = L_(set1_ps)(o[kz]);
    p->bS[0] = L_(set1_ps)(p->Sx); p->bS[1] = L_(set1_ps)(p->Sy); p->bS[2] = L_(set1_ps)(p->Sz);
#endif
}

static inline const float *row(const wnode *n, ptrdiff_t offset) { return (const float *)((const char *)n + offset); }

#ifndef BVH_INTRINSICS   /* the portable node test; AVX2 has node_hits_avx2, AVX-512 node_hits_v */
/* Slab test of the children: dist[i] = entry distance, returns a bit per child entered before
 * tmax. A NaN from 0 * inf (origin on a slab plane, direction parallel to it) fails the comparisons
 * "t > tnear" and "t < tfar" and so leaves the interval as it was: the ray counts as inside. */
static inline unsigned node_hits(const wnode *restrict n, const ray_pre *restrict p, float tmax, float *restrict dist)
{
    const float *nx = row(n, p->near[0]), *ny = row(n, p->near[1]), *nz = row(n, p->near[2]);
    const float *fx = row(n, p->far[0]), *fy = row(n, p->far[1]), *fz = row(n, p->far[2]);
    const float ox = p->o[0], oy = p->o[1], oz = p->o[2], ix = p->inv[0], iy = p->inv[1], iz = p->inv[2];
    const float jx = p->inv_far[0], jy = p->inv_far[1], jz = p->inv_far[2];
    unsigned mask = 0;
    int i;
    LANE_LOOP
    for (i = 0; i < BVH_WIDTH; i++) {
        float tnx = (nx[i] - ox) * ix, tny = (ny[i] - oy) * iy, tnz = (nz[i] - oz) * iz;
        float tfx = (fx[i] - ox) * jx, tfy = (fy[i] - oy) * jy, tfz = (fz[i] - oz) * jz;
        float t0 = 0.0f, t1 = INFINITY;
        t0 = tnx > t0 ? tnx : t0; t0 = tny > t0 ? tny : t0; t0 = tnz > t0 ? tnz : t0;
        t1 = tfx < t1 ? tfx : t1; t1 = tfy < t1 ? tfy : t1; t1 = tfz < t1 ? tfz : t1;
        t1 = tmax < t1 ? tmax : t1;
        dist[i] = t0;
        mask |= (unsigned)(t0 <= t1) << i;
    }
    return mask;
}
#endif

/* The watertight test (Woop, Benthin, Wald 2013) on the lanes of a block:
 *  1. shear the corners so that the ray is the +z axis and take the 2D edge functions U, V, W
 *     (twice the signed areas of the ray's foot with each edge): the ray is inside when they have
 *     one sign (either winding);
 *  2. t = T / det, a weighted mean of the corners' sheared depths, must lie in (0, tmax);
 *  3. an edge function exactly 0 in float may be a tiny value of either sign, rounded: such lanes
 *     are decided again with the products in double, where they are exact (redo_edge_lanes).
 * A nonzero float edge function already has the right sign (rounding is monotonic), so step 3 is
 * needed only for lanes that step 1 finds inside. */
typedef struct { float t[BVH_LEAF_MAX], u[BVH_LEAF_MAX], v[BVH_LEAF_MAX]; } lane_hits;

#ifndef BVH_INTRINSICS
static inline unsigned block_hits_float(const tri_block *restrict blk, const ray_pre *restrict p, float tmax,
                                        lane_hits *restrict h, unsigned *restrict edge)
{
    const float *a_x = blk->v[0][p->kx], *a_y = blk->v[0][p->ky], *a_z = blk->v[0][p->kz];
    const float *b_x = blk->v[1][p->kx], *b_y = blk->v[1][p->ky], *b_z = blk->v[1][p->kz];
    const float *c_x = blk->v[2][p->kx], *c_y = blk->v[2][p->ky], *c_z = blk->v[2][p->kz];
    const float ox = p->o[p->kx], oy = p->o[p->ky], oz = p->o[p->kz], Sx = p->Sx, Sy = p->Sy, Sz = p->Sz;
    float U[BVH_LEAF_MAX], V[BVH_LEAF_MAX], W[BVH_LEAF_MAX], az[BVH_LEAF_MAX], bz[BVH_LEAF_MAX], cz[BVH_LEAF_MAX];
    unsigned inside = 0, mask = 0, zero = 0;
    int i;
    LANE_LOOP
    for (i = 0; i < BVH_LEAF_MAX; i++) {   /* steps 1 and 3: which lanes the ray passes inside */
        float ax, ay, bx, by, cx, cy;
        int neg, pos, in;
        az[i] = a_z[i] - oz; bz[i] = b_z[i] - oz; cz[i] = c_z[i] - oz;
        ax = (a_x[i] - ox) - Sx * az[i]; ay = (a_y[i] - oy) - Sy * az[i];
        bx = (b_x[i] - ox) - Sx * bz[i]; by = (b_y[i] - oy) - Sy * bz[i];
        cx = (c_x[i] - ox) - Sx * cz[i]; cy = (c_y[i] - oy) - Sy * cz[i];
        U[i] = cx * by - cy * bx; V[i] = ax * cy - ay * cx; W[i] = bx * ay - by * ax;
        neg = (U[i] < 0.0f) | (V[i] < 0.0f) | (W[i] < 0.0f); pos = (U[i] > 0.0f) | (V[i] > 0.0f) | (W[i] > 0.0f);
        in = !(neg & pos);
        inside |= (unsigned)in << i;
        zero |= (unsigned)(in & ((U[i] == 0.0f) | (V[i] == 0.0f) | (W[i] == 0.0f))) << i;
    }
    *edge = zero;
    if (!inside) return 0;            /* the usual case: no division */
    LANE_LOOP
    for (i = 0; i < BVH_LEAF_MAX; i++) {   /* step 2 */
        float det = U[i] + V[i] + W[i], T = U[i] * (Sz * az[i]) + V[i] * (Sz * bz[i]) + W[i] * (Sz * cz[i]);
        float rcp = 1.0f / det;       /* det == 0 gives inf or NaN: t fails the tests below */
        h->t[i] = T * rcp; h->u[i] = V[i] * rcp; h->v[i] = W[i] * rcp;
        mask |= (unsigned)((det != 0.0f) & (h->t[i] > 0.0f) & (h->t[i] < tmax)) << i;
    }
    return mask & inside;
}
#endif

#ifdef BVH_INTRINSICS
/* block_hits_float with intrinsics: the same operations in the same order (see node_hits_v), on
 * one vector of BVH_LEAF_MAX lanes (lanes, L_). A comparison gives a mask register with AVX-512;
 * with AVX2 a vector, the masks combined as vectors and each taken out with one movemask (GCC's
 * vectorization of the portable loop gathers them bit by bit). */
#ifdef BVH_AVX512
#define LANES_CMP(a, b, pred) L_(cmp_ps_mask)(a, b, pred)
#define MASK_OR(a, b) ((a) | (b))
#define MASK_AND(a, b) ((a) & (b))
#define MASK_BITS(m) (m)
#else
#define LANES_CMP(a, b, pred) L_(cmp_ps)(a, b, pred)
#define MASK_OR(a, b) L_(or_ps)(a, b)
#define MASK_AND(a, b) L_(and_ps)(a, b)
#define MASK_BITS(m) ((unsigned)L_(movemask_ps)(m))
#endif
/* a bit per lane where any of U, V, W compares to 0 by pred */
#define ANY_UVW(pred) MASK_OR(MASK_OR(LANES_CMP(U, zero, pred), LANES_CMP(V, zero, pred)), LANES_CMP(W, zero, pred))

static inline lanes lane_row(const tri_block *blk, int corner, int axis) { return L_(load_ps)(blk->v[corner][axis]); }

static inline unsigned block_hits_v(const tri_block *restrict blk, const ray_pre *restrict p, float tmax,
                                    lane_hits *restrict h, unsigned *restrict edge)
{
    const lanes ox = p->bo[0], oy = p->bo[1], oz = p->bo[2];
    const lanes Sx = p->bS[0], Sy = p->bS[1], Sz = p->bS[2], zero = L_(setzero_ps)();
    lanes az = L_(sub_ps)(lane_row(blk, 0, p->kz), oz), bz = L_(sub_ps)(lane_row(blk, 1, p->kz), oz);
    lanes cz = L_(sub_ps)(lane_row(blk, 2, p->kz), oz);
    lanes ax = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 0, p->kx), ox), L_(mul_ps)(Sx, az));
    lanes ay = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 0, p->ky), oy), L_(mul_ps)(Sy, az));
    lanes bx = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 1, p->kx), ox), L_(mul_ps)(Sx, bz));
    lanes by = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 1, p->ky), oy), L_(mul_ps)(Sy, bz));
    lanes cx = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 2, p->kx), ox), L_(mul_ps)(Sx, cz));
    lanes cy = L_(sub_ps)(L_(sub_ps)(lane_row(blk, 2, p->ky), oy), L_(mul_ps)(Sy, cz));
    lanes U = L_(sub_ps)(L_(mul_ps)(cx, by), L_(mul_ps)(cy, bx));
    lanes V = L_(sub_ps)(L_(mul_ps)(ax, cy), L_(mul_ps)(ay, cx));
    lanes W = L_(sub_ps)(L_(mul_ps)(bx, ay), L_(mul_ps)(by, ax));
    lanes det, T, rcp, t;
    unsigned inside = ~MASK_BITS(MASK_AND(ANY_UVW(_CMP_LT_OQ), ANY_UVW(_CMP_GT_OQ))) & ((1u << BVH_LEAF_MAX) - 1), mask;
    *edge = inside & MASK_BITS(ANY_UVW(_CMP_EQ_OQ));
    if (!inside) return 0;
    det = L_(add_ps)(L_(add_ps)(U, V), W);
    T = L_(add_ps)(L_(add_ps)(L_(mul_ps)(U, L_(mul_ps)(Sz, az)), L_(mul_ps)(V, L_(mul_ps)(Sz, bz))),
                   L_(mul_ps)(W, L_(mul_ps)(Sz, cz)));
    rcp = L_(div_ps)(L_(set1_ps)(1.0f), det);
    t = L_(mul_ps)(T, rcp);
    L_(storeu_ps)(h->t, t); L_(storeu_ps)(h->u, L_(mul_ps)(V, rcp)); L_(storeu_ps)(h->v, L_(mul_ps)(W, rcp));
    mask = MASK_BITS(MASK_AND(MASK_AND(LANES_CMP(det, zero, _CMP_NEQ_UQ), LANES_CMP(t, zero, _CMP_GT_OQ)),
                              LANES_CMP(t, L_(set1_ps)(tmax), _CMP_LT_OQ)));
    return mask & inside;
}
#define block_hits_float block_hits_v
#endif

/* Step 3 for one lane, in scalar code: the same float shear, then U, V, W from exact products. */
static int lane_hit_exact(const tri_block *blk, ray_pre p, int i, float tmax, float *t, float *u, float *v)
{
    float az = blk->v[0][p.kz][i] - p.o[p.kz], bz = blk->v[1][p.kz][i] - p.o[p.kz], cz = blk->v[2][p.kz][i] - p.o[p.kz];
    double ax = (blk->v[0][p.kx][i] - p.o[p.kx]) - p.Sx * az, ay = (blk->v[0][p.ky][i] - p.o[p.ky]) - p.Sy * az;
    double bx = (blk->v[1][p.kx][i] - p.o[p.kx]) - p.Sx * bz, by = (blk->v[1][p.ky][i] - p.o[p.ky]) - p.Sy * bz;
    double cx = (blk->v[2][p.kx][i] - p.o[p.kx]) - p.Sx * cz, cy = (blk->v[2][p.ky][i] - p.o[p.ky]) - p.Sy * cz;
    float U = (float)(cx * by - cy * bx), V = (float)(ax * cy - ay * cx), W = (float)(bx * ay - by * ax);
    float det, T, rcp;
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return 0;
    det = U + V + W; T = U * (p.Sz * az) + V * (p.Sz * bz) + W * (p.Sz * cz);
    if (det == 0.0f) return 0;
    rcp = 1.0f / det;
    *t = T * rcp; *u = V * rcp; *v = W * rcp;
    return *t > 0.0f && *t < tmax;
}

static unsigned redo_edge_lanes(const tri_block *blk, ray_pre p, float tmax, unsigned mask, unsigned edge, lane_hits *h)
{
    int i;
    for (i = 0; i < BVH_LEAF_MAX; i++)
        if (edge >> i & 1) {
            mask &= ~(1u << i);
            mask |= (unsigned)lane_hit_exact(blk, p, i, tmax, &h->t[i], &h->u[i], &h->v[i]) << i;
        }
    return mask;
}

/* Returns a bit per lane of blk hit with t in (0, tmax), their t and barycentrics in h. */
static inline unsigned block_hits(const tri_block *blk, const ray_pre *p, float tmax, lane_hits *h)
{
    unsigned edge, mask = block_hits_float(blk, p, tmax, h, &edge);
    return edge ? redo_edge_lanes(blk, *p, tmax, mask, edge, h) : mask;
}

/* Index of the lowest set bit of m != 0 (a de Bruijn sequence; compilers turn it into one instruction). */
static inline int lowest_bit(unsigned m)
{
    static const unsigned char index[32] = {0, 1, 28, 2, 29, 14, 24, 3, 30, 22, 20, 15, 25, 17, 4, 8,
                                            31, 27, 13, 23, 21, 19, 16, 7, 26, 12, 18, 6, 11, 5, 10, 9};
    return index[((m & (0u - m)) * 0x077CB531u) >> 27];
}

/* The nodes a closest-hit ray has still to visit, the nearest on top: their indices and entry
 * distances in two arrays, so that the AVX2 copy stores 8 of each with one instruction. */
typedef struct { int ref[BVH_STACK]; float t[BVH_STACK]; int n; } node_stack;
static inline void push(node_stack *s, int ref, float t) { s->ref[s->n] = ref; s->t[s->n] = t; s->n++; }

#ifdef BVH_INTRINSICS
/* The per-ray values of the slab test broadcast once per ray, and one row's slab distances. */
typedef struct { __m256 o[3], inv[3], inv_far[3]; } ray_vec;

static inline ray_vec ray_vectors(const ray_pre *p)
{
    ray_vec v;
    int a;
    for (a = 0; a < 3; a++) {
        v.o[a] = _mm256_set1_ps(p->o[a]); v.inv[a] = _mm256_set1_ps(p->inv[a]); v.inv_far[a] = _mm256_set1_ps(p->inv_far[a]);
    }
    return v;
}

static inline __m256 slab(const wnode *n, ptrdiff_t offset, __m256 o, __m256 inv)
{
    return _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(row(n, offset)), o), inv);
}
#endif

#ifndef BVH_INTRINSICS   /* the portable copy; AVX2 has node_step_sorted, AVX-512 push_near_first_v */
/* Of the children in mask (not empty), returns the nearest and pushes the others farthest first, so
 * that they come off the stack nearest first. Usually one or two children are hit.
 * Measured: a test per lane (predictable branches, and the next node stays in a register) runs
 * faster than looping over the set bits, although it executes more instructions. */
typedef struct { int ref; float t; } entry;

static inline int push_near_first(const wnode *n, unsigned mask, const float dist[BVH_WIDTH], node_stack *s)
{
    entry e[BVH_WIDTH], x;
    int k = 0, i, j;
    for (i = 0; i < BVH_WIDTH; i++)
        if (mask >> i & 1) { e[k].ref = n->child[i]; e[k].t = dist[i]; k++; }
    if (k == 1) return e[0].ref;
    assert(s->n + k - 1 <= BVH_STACK);   /* the tree's depth bounds it (wide_tree_valid) */
    if (k == 2) {
        int near = e[1].t < e[0].t;
        push(s, e[1 - near].ref, e[1 - near].t);
        return e[near].ref;
    }
    for (i = 1; i < k; i++) {         /* insertion sort, farthest first */
        x = e[i];
        for (j = i; j > 0 && e[j - 1].t < x.t; j--) e[j] = e[j - 1];
        e[j] = x;
    }
    for (j = 0; j < k - 1; j++) push(s, e[j].ref, e[j].t);
    return e[k - 1].ref;
}
#endif


#ifdef BVH_AVX2
/* AVX2 has no compress, and a branch per lane mispredicts on incoherent rays, which enter 0, 1, 2
 * or more children in no pattern. So a closest-hit ray's node step in the AVX2 copy branches on
 * the number of children entered (0 or 1, 2, more) instead of on each lane, and orders three or
 * more with a sorting network of the 8 lanes: each lane's key is its entry distance's bits (a
 * distance >= 0 orders as its bits do) with the lane number in the low 3 bits, -1 for a child not
 * entered; a bitonic network sorts the keys in decreasing order (6 rounds of shuffle, min, max,
 * blend), the lane numbers permute the child indices alike, and all 8 entries are stored on top of
 * the stack, of which the first k count: the nearest comes off first. The stacked distance is off
 * by at most 7 units in the last place, far less than the culling margin BVH_T_WIDEN, and children
 * entered within 8 ulps of each other come in lane order: another order than the other copies',
 * which changes no hit (traverse_closest keeps the smallest triangle index at equal t).
 * Measured (bench/log.md, "Diffuse rays on AVX2: a sorting network"): diffuse rays 1.12x (bunny)
 * and 1.2x (dragon) faster, shadow rays 1.05-1.1x. */
#define SORT_ROUND(v, partner, take_max) _mm256_blend_epi32(_mm256_min_epi32(v, partner), _mm256_max_epi32(v, partner), take_max)
static inline __m256i sort8_decreasing(__m256i v)
{
    /* round (block size s, distance d): lane i meets lane i ^ d and keeps the larger key when
     * (i & d) == 0 xor (i & s) != 0 (blocks of s alternate up and down until s = 8); bit i of the
     * blend's immediate is that choice */
    v = SORT_ROUND(v, _mm256_shuffle_epi32(v, 0xB1), 0x99);          /* s 2, d 1 */
    v = SORT_ROUND(v, _mm256_shuffle_epi32(v, 0x4E), 0xC3);          /* s 4, d 2 */
    v = SORT_ROUND(v, _mm256_shuffle_epi32(v, 0xB1), 0xA5);          /* s 4, d 1 */
    v = SORT_ROUND(v, _mm256_permute2x128_si256(v, v, 1), 0x0F);    /* s 8, d 4 */
    v = SORT_ROUND(v, _mm256_shuffle_epi32(v, 0x4E), 0x33);          /* s 8, d 2 */
    v = SORT_ROUND(v, _mm256_shuffle_epi32(v, 0xB1), 0x55);          /* s 8, d 1 */
    return v;
}

/* node_hits with intrinsics, the same operations: *in has the lanes entered, *t0 the entry distances. */
static inline unsigned node_hits_avx2(const wnode *n, const ray_pre *p, const ray_vec *v, float tmax, __m256 *in, __m256 *t0)
{
    __m256 t1 = _mm256_set1_ps(INFINITY);
    *t0 = _mm256_max_ps(slab(n, p->near[0], v->o[0], v->inv[0]), _mm256_setzero_ps());
    *t0 = _mm256_max_ps(slab(n, p->near[1], v->o[1], v->inv[1]), *t0);
    *t0 = _mm256_max_ps(slab(n, p->near[2], v->o[2], v->inv[2]), *t0);
    t1 = _mm256_min_ps(slab(n, p->far[0], v->o[0], v->inv_far[0]), t1);
    t1 = _mm256_min_ps(slab(n, p->far[1], v->o[1], v->inv_far[1]), t1);
    t1 = _mm256_min_ps(slab(n, p->far[2], v->o[2], v->inv_far[2]), t1);
    t1 = _mm256_min_ps(_mm256_set1_ps(tmax), t1);
    *in = _mm256_cmp_ps(*t0, t1, _CMP_LE_OQ);
    return (unsigned)_mm256_movemask_ps(*in);
}

/* node_hits and push_near_first for a closest-hit ray: returns 1 with *next the nearest child
 * entered and the others pushed; 0 when none was entered or all were pushed, the nearest on top. */
static inline int node_step_sorted(const wnode *n, const ray_pre *p, const ray_vec *v, float tmax, node_stack *s, int *next)
{
    __m256 t0, in;
    __m256i key;
    unsigned mask = node_hits_avx2(n, p, v, tmax, &in, &t0);
    if (!(mask & (mask - 1))) {
        if (!mask) return 0;
        *next = n->child[__builtin_ctz(mask)];
        return 1;
    }
    {
        unsigned rest = mask & (mask - 1);
        if (!(rest & (rest - 1))) {   /* two: a comparison (a fifth of a diffuse ray's nodes) */
            float t[BVH_WIDTH];
            int a = __builtin_ctz(mask), c = __builtin_ctz(rest), near;
            _mm256_storeu_ps(t, t0);
            near = t[c] < t[a] ? c : a;
            push(s, n->child[a + c - near], t[a + c - near]);
            *next = n->child[near];
            return 1;
        }
    }
    key = _mm256_or_si256(_mm256_and_si256(_mm256_castps_si256(t0), _mm256_set1_epi32(~7)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    key = sort8_decreasing(_mm256_blendv_epi8(_mm256_set1_epi32(-1), key, _mm256_castps_si256(in)));
    assert(s->n + BVH_WIDTH <= BVH_STACK);
    _mm256_storeu_si256((__m256i *)(s->ref + s->n),   /* the child indices, permuted by the keys' low 3 bits */
                        _mm256_permutevar8x32_epi32(_mm256_load_si256((const __m256i *)n->child), key));
    _mm256_storeu_si256((__m256i *)(s->t + s->n), key);
    s->n += __builtin_popcount(mask);
    return 0;
}
#endif

#ifdef BVH_AVX512
/* With AVX-512, nodes (and blocks, block_hits_v) are tested with intrinsics: the same operations
 * in the same order as node_hits (so the same children are entered at the same distances and every
 * hit is the same), but the hit mask comes out of one compare into a mask register instead of eight
 * bits ORed together, and closest-hit rays pack the children hit with one compress instead of a
 * branch per lane, which mispredicts on incoherent rays. Measured (bench/log.md, "Nodes and blocks
 * tested with AVX-512 intrinsics"): dragon diffuse rays 1.2x faster, shadow 1.1x. Shadow rays keep
 * the branch per lane: with the compress they were 0.91x. */
/* node_hits, vectorized by hand: *dist gets the entry distances. */
static inline unsigned node_hits_v(const wnode *n, const ray_pre *p, const ray_vec *v, float tmax, __m256 *dist)
{
    __m256 t0 = _mm256_setzero_ps(), t1 = _mm256_set1_ps(INFINITY);
    /* the child indices sit in the node's 4th cache line, read only once the mask is known: ask for
     * that line now, alongside the box rows (dragon diffuse +1-4 % in 4 A/B runs, bunny equal) */
    _mm_prefetch((const char *)n->child, _MM_HINT_T0);
    t0 = _mm256_max_ps(slab(n, p->near[0], v->o[0], v->inv[0]), t0);   /* max(a, b) = a > b ? a : b */
    t0 = _mm256_max_ps(slab(n, p->near[1], v->o[1], v->inv[1]), t0);
    t0 = _mm256_max_ps(slab(n, p->near[2], v->o[2], v->inv[2]), t0);
    t1 = _mm256_min_ps(slab(n, p->far[0], v->o[0], v->inv_far[0]), t1);    /* min(a, b) = a < b ? a : b */
    t1 = _mm256_min_ps(slab(n, p->far[1], v->o[1], v->inv_far[1]), t1);
    t1 = _mm256_min_ps(slab(n, p->far[2], v->o[2], v->inv_far[2]), t1);
    t1 = _mm256_min_ps(_mm256_set1_ps(tmax), t1);
    *dist = t0;
    return _mm256_cmp_ps_mask(t0, t1, _CMP_LE_OQ);
}

/* push_near_first on packed lanes: the same order (lane order kept, the same insertion sort). */
static inline int push_near_first_v(const wnode *n, unsigned mask, __m256 dist, node_stack *s)
{
    float t[BVH_WIDTH];
    int r[BVH_WIDTH], k, i, j;
    unsigned rest = mask & (mask - 1);
    if (!rest) return n->child[__builtin_ctz(mask)];
    if (!(rest & (rest - 1))) {       /* two children: no compress */
        int a = __builtin_ctz(mask), c = __builtin_ctz(rest), near;
        _mm256_storeu_ps(t, dist);
        near = t[c] < t[a];
        assert(s->n + 1 <= BVH_STACK);
        push(s, n->child[near ? a : c], t[near ? a : c]);
        return n->child[near ? c : a];
    }
    _mm256_storeu_ps(t, _mm256_maskz_compress_ps((__mmask8)mask, dist));
    _mm256_storeu_si256((__m256i *)r, _mm256_maskz_compress_epi32((__mmask8)mask,
                                                                  _mm256_load_si256((const __m256i *)n->child)));
    k = __builtin_popcount(mask);
    assert(s->n + k - 1 <= BVH_STACK);
    if (k == 2) {
        int near = t[1] < t[0];
        push(s, r[1 - near], t[1 - near]);
        return r[near];
    }
    for (i = 1; i < k; i++) {
        float xt = t[i];
        int xr = r[i];
        for (j = i; j > 0 && t[j - 1] < xt; j--) { t[j] = t[j - 1]; r[j] = r[j - 1]; }
        t[j] = xt; r[j] = xr;
    }
    for (j = 0; j < k - 1; j++) push(s, r[j], t[j]);
    return r[k - 1];
}
#endif

static int ray_is_valid(const ray *r)
{
    float s = r->o.x + r->o.y + r->o.z + r->d.x + r->d.y + r->d.z;
    return s - s == 0.0f && !v3_is_zero(r->d) && r->tmax > 0.0f;   /* no inf, no NaN */
}

/* The next float above x > 0 (finite): a comparison t < next_float_up(x) is t <= x. */
static inline float next_float_up(float x)
{
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    bits++;
    memcpy(&x, &bits, sizeof x);
    return x;
}

static int traverse_closest(const bvh *b, const ray *r, hit *h)
{
    node_stack stack;
    int ref = b->root, best_lane = -1;
    float tmax = r->tmax, tcull = tmax * BVH_T_WIDEN, tkeep = tmax, bu = 0, bv = 0;
    const tri_block *best = NULL;
    ray_pre p;
#ifdef BVH_INTRINSICS
    ray_vec v;
#endif
    h->tri = -1;
    stack.n = 0;
    if (!b->nblocks || !ray_is_valid(r)) return 0;
    ray_prepare(r, &p);
#ifdef BVH_INTRINSICS
    v = ray_vectors(&p);
#endif
    for (;;) {
        if (ref >= 0) {            /* node: go on with the nearest child entered, stack the others */
#ifdef BVH_AVX512
            __m256 dist;
            unsigned mask = node_hits_v(&b->nodes[ref], &p, &v, tcull, &dist);
            if (mask) { ref = push_near_first_v(&b->nodes[ref], mask, dist, &stack); continue; }
#elif defined(BVH_AVX2)
            if (node_step_sorted(&b->nodes[ref], &p, &v, tcull, &stack, &ref)) continue;
#else
            float dist[BVH_WIDTH];
            unsigned mask = node_hits(&b->nodes[ref], &p, tcull, dist);
            if (mask) { ref = push_near_first(&b->nodes[ref], mask, dist, &stack); continue; }
#endif
        } else {                   /* leaf: keep the nearest of its triangles, and of two at equal t
                                      the smaller index (two triangles through an edge), whichever
                                      was found first: the copies need not visit in one order */
            const tri_block *blk = &b->blocks[~ref];
            lane_hits lh;
            unsigned mask = block_hits(blk, &p, tkeep, &lh);
            for (; mask; mask &= mask - 1) {
                int i = lowest_bit(mask);
                if (lh.t[i] < tmax || (best && lh.t[i] == tmax && blk->id[i] < best->id[best_lane])) {
                    tmax = lh.t[i]; bu = lh.u[i]; bv = lh.v[i]; best = blk; best_lane = i;
                }
            }
            tcull = tmax * BVH_T_WIDEN;
            if (best) tkeep = next_float_up(tmax);   /* t <= tmax from now on */
        }
        do {                       /* next stacked node that may still hold a closer hit */
            if (stack.n == 0) goto done;
            --stack.n;
        } while (stack.t[stack.n] > tcull);
        ref = stack.ref[stack.n];
    }
done:
    if (!best) return 0;
    h->t = tmax; h->u = bu; h->v = bv; h->tri = best->id[best_lane];
    return 1;
}

/* 1 if a lane of mask holds a triangle other than except (mask not 0). */
static inline int other_than(const tri_block *blk, unsigned mask, int except)
{
    for (; mask; mask &= mask - 1)
        if (blk->id[lowest_bit(mask)] != except) return 1;
    return 0;
}

static int traverse_any(const bvh *b, const ray *r, int except)
{
    int stack[BVH_STACK], sp = 0, ref = b->root, i;
    float tmax = r->tmax, tcull = tmax * BVH_T_WIDEN;
    ray_pre p;
#ifdef BVH_INTRINSICS
    ray_vec v;
#endif
    if (!b->nblocks || !ray_is_valid(r)) return 0;
    ray_prepare(r, &p);
#ifdef BVH_INTRINSICS
    v = ray_vectors(&p);
#endif
    for (;;) {
        if (ref >= 0) {            /* node: any order will do, the first hit ends the search; the
                                      last child pushed is popped at once, from a register */
            const wnode *n = &b->nodes[ref];
#ifdef BVH_AVX512
            __m256 dist;
            unsigned mask = node_hits_v(n, &p, &v, tcull, &dist);
            assert(sp + BVH_WIDTH <= BVH_STACK);
            for (i = 0; i < BVH_WIDTH; i++)
                if (mask >> i & 1) stack[sp++] = n->child[i];
#elif defined(BVH_AVX2)
            __m256 in, dist;
            unsigned mask = node_hits_avx2(n, &p, &v, tcull, &in, &dist);
            assert(sp + BVH_WIDTH <= BVH_STACK);
            for (i = 0; i < BVH_WIDTH; i++)
                if (mask >> i & 1) stack[sp++] = n->child[i];
#else
            float dist[BVH_WIDTH];
            unsigned mask = node_hits(n, &p, tcull, dist);
            assert(sp + BVH_WIDTH <= BVH_STACK);
            for (i = 0; i < BVH_WIDTH; i++)
                if (mask >> i & 1) stack[sp++] = n->child[i];
#endif
        } else {
            lane_hits lh;
            unsigned mask = block_hits(&b->blocks[~ref], &p, tmax, &lh);
            if (mask && (except < 0 || other_than(&b->blocks[~ref], mask, except))) return 1;
        }
        if (sp == 0) return 0;
        ref = stack[--sp];
    }
}

/* This copy's entry points, named after its instruction set (bvh_traversal_base, _avx2, _avx512). */
#define BVH_CAT2(a, b) a##b
#define BVH_CAT(a, b) BVH_CAT2(a, b)
const bvh_traversal BVH_CAT(bvh_traversal_, BVH_ISA) = {
#ifdef BVH_AVX512
    "avx512",
#elif defined(__AVX2__)
    "avx2",
#elif defined(__x86_64__)
    "sse2",
#else
    "portable",
#endif
    traverse_closest, traverse_any};

#ifndef BVH_ISA_COPY   /* the reference test of one triangle: in the base copy only */
int bvh_triangle_hit(vec3 a, vec3 b, vec3 c, const ray *r, hit *h)
{
    tri_block blk;
    lane_hits lh;
    vec3 corners[3] = {a, b, c};
    ray_pre p;
    int k, lane;
    if (!ray_is_valid(r)) return 0;
    for (k = 0; k < 3; k++)
        for (lane = 0; lane < BVH_LEAF_MAX; lane++) {
            blk.v[k][0][lane] = corners[k].x; blk.v[k][1][lane] = corners[k].y; blk.v[k][2][lane] = corners[k].z;
        }
    ray_prepare(r, &p);
    if (!(block_hits(&blk, &p, r->tmax, &lh) & 1)) return 0;
    h->t = lh.t[0]; h->u = lh.u[0]; h->v = lh.v[0];
    return 1;
}
#endif
