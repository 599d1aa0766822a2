/* bvh_layout.h — what the BVH's build (bvh.c) and its traversal (bvh_traverse.c) share: the node
 * and triangle-block layout, the tuning constants both read, the bounds' widening, and the entry
 * points of each compiled copy of the traversal (bvh_traverse.c is compiled once per instruction
 * set on x86-64; bvh.c picks one when it builds a tree). Private to geometry/. */
#ifndef PATHLAB_BVH_LAYOUT_H
#define PATHLAB_BVH_LAYOUT_H
#include "geometry/ray.h"
#include <stddef.h>

/* A copy compiled with AVX-512 (bvh_traverse_avx512.o, or a -march=native build on such a CPU) tests
 * nodes with intrinsics (see node_hits_v); -DBVH_NO_AVX512 keeps the portable loops there too. */
#if defined(__AVX512F__) && defined(__AVX512VL__) && !defined(BVH_NO_AVX512)
#define BVH_AVX512 1
#include <immintrin.h>
#endif

/* Every product and sum must be rounded on its own: an edge function computed as a fused multiply-
 * add would differ between the two triangles sharing that edge, and rays could slip through.
 * GCC in ISO C mode (-std=c99) contracts nothing; clang needs telling (GCC warns on the pragma). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* Tuning constants. */
#define BVH_BINS 16            /* SAH bins per axis (fewer for nodes of fewer triangles) */
#define BVH_WIDTH 8            /* children per node: one 256-bit vector of floats per slab row */
#define BVH_LEAF_MAX 8         /* triangles per leaf: one block, a 256-bit vector per row (4 works too) */
#define BVH_BINARY_LEAF 8      /* the binary tree splits nodes of more triangles than this */
#define BVH_COST_NODE 1.0f     /* SAH cost of visiting a node ... */
#define BVH_COST_BLOCK 1.0f    /* ... and of testing one block (as measured: alike) */
#define BVH_SAH_DEPTH 48       /* deeper than this, split in halves: bounds the depth for the stack */
#define BVH_PARALLEL_MIN 4096  /* a node this big may have its two subtrees built on two threads */
#define BVH_HALVES_MIN (1 << 20) /* a node this big is binned in halves on two threads, if one is free */
#define BVH_MAX_DEPTH 80       /* binary depth <= 48 + 30 (indices < 2^30), wide depth no more */
#define BVH_STACK (BVH_WIDTH * BVH_MAX_DEPTH) /* traversal stack: < W entries per level */

/* gamma(3) = 3 eps / (1 - 3 eps) with eps = 2^-24: the relative error of (plane - o) * (1/d)
 * (pbrt 3rd ed. 3.9). Exit distances are widened by 1 + 2 gamma(3): computed as (plane - o) *
 * ((1/d) * widen), with as many roundings as pbrt's ((plane - o) * (1/d)) * widen, a multiply less
 * per node. A far plane behind the origin only gets farther behind: its box stays unentered. */
#define BVH_BOX_WIDEN (1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f))
/* The t of a triangle is a weighted mean of its corners' depths computed with ~10 roundings, so a
 * box entered a few ulps beyond the current closest t may still hold a triangle whose computed t is
 * smaller: boxes are culled against t widened by this much (2^-16, far more than needed). */
#define BVH_T_WIDEN (1.0f + 0x1p-16f)

/* ---- Layout ------------------------------------------------------------------------------------
 * Node, 256 bytes (four cache lines), 64-byte aligned:
 *   bytes   0..191  float box[6][8]: rows lo.x lo.y lo.z hi.x hi.y hi.z, one column per child, so the
 *                   8 children's slabs on one axis are one 32-byte vector. An empty child slot has
 *                   lo = +inf, hi = -inf, which no ray enters.
 *   bytes 192..223  int child[8]: >= 0 index of a node; < 0 a leaf, ~child = its block index.
 *   bytes 224..255  padding to the cache line.
 * Triangle block, 320 bytes, 32-byte aligned: float v[3][3][8] = corner, axis, lane (288 bytes),
 *   then int id[8], the caller's triangle indices. A leaf of fewer than 8 triangles repeats its last
 *   triangle: the copy hits at the same t and loses the tie, so it costs nothing but a lane. */
typedef struct { float box[6][BVH_WIDTH]; int child[BVH_WIDTH]; int pad[BVH_WIDTH]; } wnode;
typedef struct { float v[3][3][BVH_LEAF_MAX]; int id[BVH_LEAF_MAX]; } tri_block;

/* One compiled copy of the traversal: its name and entry points (bvh_intersect, bvh_occluded_except). */
typedef struct {
    const char *name;
    int (*intersect)(const struct bvh *b, const ray *r, hit *h);
    int (*occluded)(const struct bvh *b, const ray *r, int except_tri);
} bvh_traversal;
extern const bvh_traversal bvh_traversal_base;      /* the build's own flags: SSE2 on x86-64 */
#ifdef BVH_DISPATCH
extern const bvh_traversal bvh_traversal_avx2;      /* -mavx2 -mfma */
extern const bvh_traversal bvh_traversal_avx512;    /* -mavx512f -mavx512vl -mavx512bw -mavx512dq */
#endif

struct bvh {
    wnode *nodes;      /* nodes[0] is the root */
    tri_block *blocks;
    int root;          /* 0, or ~0 when the whole tree is one leaf (or empty: no blocks at all) */
    int nnodes, nblocks, depth;
    const bvh_traversal *trav;   /* the copy of the traversal chosen at build time (bvh_isa) */
};

#endif
