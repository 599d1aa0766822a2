/* bvh.c — an 8-wide bounding volume hierarchy over triangles: binned SAH build, watertight traversal.
 *
 * How to use:
 *     bvh *b = bvh_build(P, tri, ntris, threads);   // keeps its own copy of the triangles
 *     ray r = {origin, direction, INFINITY};  hit h;
 *     if (bvh_intersect(b, &r, &h)) ... h.t, h.tri, h.u, h.v ...   // closest hit
 *     if (bvh_occluded(b, &r)) ...                                // any hit, for shadow rays
 *     bvh_free(b);
 *
 * How it is built:
 *  1. Every triangle gets a primref (its bounds and index). A binary tree is built top down: each
 *     node bins its triangles' centroids into BVH_BINS bins on each axis, picks the plane of least
 *     surface area heuristic (SAH) cost and partitions its primrefs in place, down to leaves of at
 *     most BVH_BINARY_LEAF triangles. On the way back up, each node gets the least SAH cost of its
 *     subtree as 1, 2, ... 8 children of a wide node (subtree_cost). The two subtrees of a big
 *     node are built by two threads (a parallel_for of 2 iterations) while the build may start one
 *     more, and the root of a big mesh bins its halves on two threads (bin_node); the tree is the
 *     same for any number of threads. Nothing is sorted, nothing allocated per node.
 *  2. The binary tree is collapsed into an 8-wide one by those costs: a subtree becomes a leaf (a
 *     block of up to 8 triangles) or a wide node over the cheapest cover of its subtree by at most
 *     8 children (collapse, cover), laid out depth first. A node tests its 8 boxes with the few
 *     instructions of one loop the compiler vectorizes, and a block its 8 triangles likewise: that
 *     is what makes single rays fast without intrinsics, and the wide nodes make the tree shallow,
 *     which matters most for incoherent rays in big meshes.
 *     With AVX-512 and AVX2 the same tests are written with intrinsics, whose masks, compress and
 *     sorting network the compiler does not find (node_hits_v, block_hits_v, node_step_sorted in
 *     bvh_traverse.c).
 *
 * The traversal lives in bvh_traverse.c, compiled once per instruction set on x86-64 (SSE2, AVX2 +
 * FMA, AVX-512): each tree gets the best copy the CPU runs (bvh_isa), and every copy finds the
 * same hits, so the one binary of `make` is fast on any x86-64 and its images never depend on it.
 *
 * How it is traversed: one loop with an explicit stack. At a node, the children the ray enters are
 * sorted by entry distance: the nearest is visited next, the others pushed farthest first. Popped
 * nodes entered beyond the closest hit so far are skipped. Shadow rays skip the sorting. The hit
 * kept is the nearest, and of two at the same t the smaller triangle index, so it does not depend
 * on the order in which children entered at equal distances are visited.
 *
 * Robustness: the triangle test is watertight (Woop, Benthin, Wald 2013) and the box test is
 * conservative (pbrt's 1 + 2 gamma(3) on exit distances, folded into the 1/d they use), so no ray slips between two triangles
 * sharing an edge or a vertex, and a box never hides a triangle the triangle test would report. */
#include "geometry/bvh.h"
#include "geometry/bvh_layout.h"
#include "sys/big_array.h"
#include "sys/parallel.h"
#include <assert.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- Build, step 1: the binary tree ------------------------------------------------------------
 * Boxes have 4 lanes, the 4th unused, so that growing one is a vector min and a vector max. */
typedef struct { float lo[4], hi[4]; } aabb;
/* primref, 32 bytes: a triangle's box; lo[3] holds the bits of its index (a float below 2, never a
 * NaN, since indices are < 2^30), hi[3] is 0. Partitions move these around. */
typedef aabb primref;
/* Binary node, 32 bytes: float lo[3]; int first (inner: the left child, the right one follows it;
 * leaf: the first primref); float hi[3]; int count (0 for inner nodes). Only the build sees these. */
typedef struct { float lo[3]; int first; float hi[3]; int count; } node2;
typedef struct { int axis, bin, nbins, nleft; float cost; aabb left, right; } split;
/* What the collapse (step 2) needs of a binary node's subtree: its primrefs [first, first + count),
 * and cost[i - 1], the least SAH cost of the subtree as at most i children of a wide node. */
typedef struct { float cost[BVH_WIDTH]; int first, count; } subtree;

typedef struct {
    primref *refs;
    node2 *nodes;
    subtree *sub;      /* per node, filled children first (subtree_cost) */
    int nslots;        /* the length of nodes */
    int idle;          /* threads the build may still start, under lock */
    pthread_mutex_t lock;
} builder;

static aabb aabb_empty(void)
{
    aabb b = {{FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX, -FLT_MAX, -FLT_MAX}};
    return b;
}
/* Lane by lane, b->lo = p->lo where p->lo < b->lo, and b->hi = p->hi where p->hi > b->hi, as SSE's
 * minps and maxps do. GCC leaves the loop scalar in the partition, whose boxes are locals, and keeps
 * them in memory (a store and a reload per primref): SSE2, which every x86-64 has, writes it out, and
 * other processors get the loop, the same arithmetic. */
static inline void aabb_grow(aabb *restrict b, const aabb *restrict p)
{
#if defined(__SSE2__)
    _mm_storeu_ps(b->lo, _mm_min_ps(_mm_loadu_ps(p->lo), _mm_loadu_ps(b->lo)));
    _mm_storeu_ps(b->hi, _mm_max_ps(_mm_loadu_ps(p->hi), _mm_loadu_ps(b->hi)));
#else
    int i;
    for (i = 0; i < 4; i++) {
        b->lo[i] = p->lo[i] < b->lo[i] ? p->lo[i] : b->lo[i];
        b->hi[i] = p->hi[i] > b->hi[i] ? p->hi[i] : b->hi[i];
    }
#endif
}
/* Centroids are kept doubled (lo + hi): one add instead of an add and a multiply. */
static inline void aabb_grow_centroid(aabb *restrict b, const primref *restrict p)
{
#if defined(__SSE2__)
    __m128 c = _mm_add_ps(_mm_loadu_ps(p->lo), _mm_loadu_ps(p->hi));
    _mm_storeu_ps(b->lo, _mm_min_ps(c, _mm_loadu_ps(b->lo)));
    _mm_storeu_ps(b->hi, _mm_max_ps(c, _mm_loadu_ps(b->hi)));
#else
    aabb c;
    int i;
    for (i = 0; i < 4; i++) c.lo[i] = c.hi[i] = p->lo[i] + p->hi[i];
    aabb_grow(b, &c);
#endif
}
/* Half the surface area; the SAH only compares ratios. */
static float aabb_area(const aabb *b)
{
    float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return dx * dy + dy * dz + dz * dx;
}
static int ref_id(const primref *p) { int id; memcpy(&id, &p->lo[3], sizeof id); return id; }
/* SAH weight of n triangles: the blocks they fill. */
static float blocks_of(int n) { return (float)((n + BVH_LEAF_MAX - 1) / BVH_LEAF_MAX); }

/* Bin of a primref on one axis: cb is the doubled-centroid bounds, scale = nbins / extent. */
static inline int bin_of(const primref *p, int a, const aabb *cb, float scale, int nbins)
{
    int k = (int)((p->lo[a] + p->hi[a] - cb->lo[a]) * scale);
    return k < nbins - 1 ? k : nbins - 1;
}
/* Small nodes get fewer bins: as good a split, and the bins are the main cost there. */
static int bins_for(int count) { return count < BVH_BINS ? (count < 4 ? 4 : count) : BVH_BINS; }

typedef struct { aabb box[3][BVH_BINS]; int n[3][BVH_BINS]; } bins;

static void bins_clear(bins *B, int nbins)
{
    int a, k;
    for (a = 0; a < 3; a++)
        for (k = 0; k < nbins; k++) { B->box[a][k] = aabb_empty(); B->n[a][k] = 0; }
}
static inline void bin_one(const primref *p, const aabb *cb, const float scale[3], int nbins, bins *B)
{
    int a, k;
    for (a = 0; a < 3; a++) {
        k = bin_of(p, a, cb, scale[a], nbins);
        aabb_grow(&B->box[a][k], p);
        B->n[a][k]++;
    }
}
/* Neighbouring primrefs often fall in the same bin, and growing a bin waits for the previous store
 * to it: with two sets of bins, even and odd primrefs, two such chains run side by side. */
static void bin_refs(const primref *r, int n, const aabb *cb, const float scale[3], int nbins, bins *B)
{
    bins odd;
    int a, i, k;
    bins_clear(B, nbins);
    if (n < 64) {   /* a small node: clearing and merging a second set would cost more than it saves */
        for (i = 0; i < n; i++) bin_one(&r[i], cb, scale, nbins, B);
        return;
    }
    bins_clear(&odd, nbins);
    for (i = 0; i + 1 < n; i += 2) {
        bin_one(&r[i], cb, scale, nbins, B);
        bin_one(&r[i + 1], cb, scale, nbins, &odd);
    }
    if (i < n) bin_one(&r[i], cb, scale, nbins, B);
    for (a = 0; a < 3; a++)
        for (k = 0; k < nbins; k++) { aabb_grow(&B->box[a][k], &odd.box[a][k]); B->n[a][k] += odd.n[a][k]; }
}

/* Sweeps the bins of one axis from both ends and keeps the cheapest plane in *best. */
static void sweep_axis(const aabb *box, const int *count, int nbins, int axis, split *best)
{
    float right_area[BVH_BINS], cost;
    int right_n[BVH_BINS];
    aabb right_box[BVH_BINS], acc = aabb_empty();
    int n = 0, k;
    for (k = nbins - 1; k > 0; k--) {
        aabb_grow(&acc, &box[k]);
        n += count[k];
        right_box[k] = acc; right_n[k] = n; right_area[k] = aabb_area(&acc);
    }
    acc = aabb_empty(); n = 0;
    for (k = 1; k < nbins; k++) {    /* plane k: bins [0, k) go left */
        aabb_grow(&acc, &box[k - 1]);
        n += count[k - 1];
        if (n == 0 || right_n[k] == 0) continue;
        cost = aabb_area(&acc) * blocks_of(n) + right_area[k] * blocks_of(right_n[k]);
        if (cost < best->cost) {
            best->axis = axis; best->bin = k; best->nleft = n; best->cost = cost;
            best->left = acc; best->right = right_box[k];
        }
    }
}

/* ---- The biggest nodes (the root's): binned on two threads ---------------------------------------
 * The root's binning, alone, kept one of two threads idle (0.09 s of a 16M build). A node of at least
 * BVH_HALVES_MIN refs, when the build may start one more thread, bins each half of its refs on its
 * own thread and merges the bins: boxes by min and max and counts by sums, exact in any order, so
 * the bins, the split and the tree are those of one pass. The partition stays one pass: in halves
 * it must then trade the halves' misplaced refs, as much work again. */
static int claim_thread(builder *B, int delta);
typedef struct {
    const primref *r;
    int n, half;            /* the halves: [0, half) and [half, n) */
    const aabb *cb;
    const float *scale;
    int nbins;
    bins bin[2];
} halves;

/* parallel_body: bins halves [begin, end). */
static void bin_halves(void *ctx, int thread, int begin, int end)
{
    halves *h = ctx;
    int i;
    (void)thread;
    for (i = begin; i < end; i++)
        bin_refs(h->r + (i ? h->half : 0), i ? h->n - h->half : h->half, h->cb, h->scale, h->nbins, &h->bin[i]);
}

/* The bins of refs [0, n): one pass, or two halves on two threads for a big node. */
static void bin_node(builder *B, const primref *r, int n, const aabb *cb, const float scale[3], int nbins, bins *out)
{
    halves h;
    int a, k;
    if (n < BVH_HALVES_MIN || !claim_thread(B, -1)) { bin_refs(r, n, cb, scale, nbins, out); return; }
    h.r = r; h.n = n; h.half = n / 2; h.cb = cb; h.scale = scale; h.nbins = nbins;
    parallel_for(2, 1, 2, bin_halves, &h);
    claim_thread(B, +1);
    *out = h.bin[0];
    for (a = 0; a < 3; a++)
        for (k = 0; k < nbins; k++) { aabb_grow(&out->box[a][k], &h.bin[1].box[a][k]); out->n[a][k] += h.bin[1].n[a][k]; }
}

/* Cheapest binned SAH split of refs [0, n); 0 when every centroid is the same point. */
static int find_split(builder *B, const primref *r, int n, const aabb *cb, split *s, float scale[3])
{
    bins bn;
    int nbins = bins_for(n), a;
    for (a = 0; a < 3; a++) {
        float extent = cb->hi[a] - cb->lo[a];
        scale[a] = extent > 0 ? (float)nbins / extent : 0.0f;
        if (!(scale[a] < FLT_MAX)) scale[a] = 0.0f;   /* a denormal extent: treat the axis as flat */
    }
    bin_node(B, r, n, cb, scale, nbins, &bn);
    s->cost = INFINITY;
    s->nbins = nbins;
    for (a = 0; a < 3; a++)
        if (scale[a] > 0) sweep_axis(bn.box[a], bn.n[a], nbins, a, s);
    return s->cost < INFINITY;
}

static void swap_refs(primref *a, primref *b) { primref t = *a; *a = *b; *b = t; }

/* Moves the refs of bins < s->bin to the front; fills the children's centroid bounds. */
static int partition(primref *r, int n, const split *s, const aabb *cb, float scale, aabb *lcb, aabb *rcb)
{
    int i = 0, j = n - 1;
    aabb l = aabb_empty(), rt = aabb_empty();   /* locals, not *lcb: kept in registers */
    for (;;) {
        while (i <= j && bin_of(&r[i], s->axis, cb, scale, s->nbins) < s->bin) aabb_grow_centroid(&l, &r[i++]);
        while (i <= j && bin_of(&r[j], s->axis, cb, scale, s->nbins) >= s->bin) aabb_grow_centroid(&rt, &r[j--]);
        if (i >= j) break;
        swap_refs(&r[i], &r[j]);    /* both now on their side; the loops above grow their bounds */
    }
    *lcb = l; *rcb = rt;
    return i;
}

/* Fallback split for identical centroids and for too deep trees: halves by position. */
static void split_halves(const primref *r, int n, split *s, aabb *lcb, aabb *rcb)
{
    int i;
    s->nleft = n / 2;
    s->left = s->right = *lcb = *rcb = aabb_empty();
    for (i = 0; i < n; i++) {
        aabb_grow(i < s->nleft ? &s->left : &s->right, &r[i]);
        aabb_grow_centroid(i < s->nleft ? lcb : rcb, &r[i]);
    }
}

static void set_node(node2 *nd, const aabb *b)
{
    memcpy(nd->lo, b->lo, sizeof nd->lo);
    memcpy(nd->hi, b->hi, sizeof nd->hi);
    nd->first = 0; nd->count = 0;
}
static aabb node_box(const node2 *nd)
{
    aabb b = aabb_empty();
    memcpy(b.lo, nd->lo, sizeof nd->lo);
    memcpy(b.hi, nd->hi, sizeof nd->hi);
    return b;
}

/* Decides how to split refs [first, first+count); 0 makes their node a leaf. */
static int choose_split(builder *B, int first, int count, const aabb *cb, int depth,
                        split *s, aabb *lcb, aabb *rcb)
{
    primref *r = B->refs + first;
    float scale[3];
    if (count <= BVH_BINARY_LEAF) return 0;
    if (depth < BVH_SAH_DEPTH && find_split(B, r, count, cb, s, scale)) {
        partition(r, count, s, cb, scale[s->axis], lcb, rcb);
        return 1;
    }
    if (count <= BVH_LEAF_MAX) return 0;
    split_halves(r, count, s, lcb, rcb);
    return 1;
}

/* ---- Build, step 1b: where the wide tree's nodes and leaves will be -----------------------------
 * The binary tree goes down to BVH_BINARY_LEAF triangles; which of its subtrees become the wide
 * tree's nodes and leaves is chosen by dynamic programming on the SAH (Ylitie, Karras, Laine 2017,
 * "Efficient incoherent ray traversal on GPUs through compressed wide BVHs", section 4.1): cost[i-1]
 * of a subtree is its least cost as at most i children of a wide node, filled children first, so a
 * node of 24 triangles need not become a wide node of three leaves when its parent can adopt them. */
static float leaf_cost(const node2 *nd, int count)
{
    aabb b = node_box(nd);
    return count <= BVH_LEAF_MAX ? BVH_COST_BLOCK * aabb_area(&b) : INFINITY;
}
/* Least cost of at most i >= 2 roots shared between the subtrees l and r; *k gets l's share. */
static float share_cost(const subtree *l, const subtree *r, int i, int *k)
{
    float best = l->cost[0] + r->cost[i - 2], c;
    int j;
    *k = 1;
    for (j = 2; j < i; j++) {
        c = l->cost[j - 1] + r->cost[i - j - 1];
        if (c < best) { best = c; *k = j; }
    }
    return best;
}
/* cost[] of node ni: one root is a leaf or a wide node over at most BVH_WIDTH roots below it. */
static float root_cost(const builder *B, int ni, int *leaf)
{
    const node2 *nd = &B->nodes[ni];
    const subtree *sub = &B->sub[ni];
    float as_leaf = leaf_cost(nd, sub->count), as_node;
    aabb b = node_box(nd);
    int k;
    *leaf = 1;
    assert(!nd->count || sub->count <= BVH_LEAF_MAX);   /* a binary leaf fits one block */
    if (nd->count) return as_leaf;
    as_node = BVH_COST_NODE * aabb_area(&b) + share_cost(&B->sub[nd->first], &B->sub[nd->first + 1], BVH_WIDTH, &k);
    *leaf = sub->count <= BVH_LEAF_MAX && as_leaf <= as_node;
    return *leaf ? as_leaf : as_node;
}
/* Fills B->sub[ni], its children's being filled (build_rec calls it on the way back up). */
static void subtree_cost(builder *B, int ni, int first, int count)
{
    subtree *sub = &B->sub[ni];
    const node2 *nd = &B->nodes[ni];
    int i, k, leaf;
    sub->first = first; sub->count = count;
    sub->cost[0] = root_cost(B, ni, &leaf);
    for (i = 2; i <= BVH_WIDTH; i++) {
        float c = nd->count ? INFINITY : share_cost(&B->sub[nd->first], &B->sub[nd->first + 1], i, &k);
        sub->cost[i - 1] = c < sub->cost[i - 2] ? c : sub->cost[i - 2];
    }
}

/* Takes (delta -1) or returns (+1) one of the threads the build may start; 1 if it could. */
static int claim_thread(builder *B, int delta)
{
    int ok;
    pthread_mutex_lock(&B->lock);
    ok = delta > 0 || B->idle > 0;
    if (ok) B->idle += delta;
    pthread_mutex_unlock(&B->lock);
    return ok;
}

/* The two children of a split node, [0] the left one and [1] the right one, for build_pair_body.
 * next[i]: the first slot child i's descendants may take; on return, the slot after the last. */
typedef struct {
    builder *B;
    int node[2], first[2], count[2], next[2], leaves[2], depth;
    aabb cb[2];
} child_pair;

static int build_rec(builder *B, int ni, int first, int count, aabb cb, int depth, int *next);

/* parallel_body: builds the subtrees of children [begin, end) of the pair. */
static void build_pair_body(void *ctx, int thread, int begin, int end)
{
    child_pair *c = ctx;
    int i;
    (void)thread;
    for (i = begin; i < end; i++)
        c->leaves[i] = build_rec(c->B, c->node[i], c->first[i], c->count[i], c->cb[i], c->depth, &c->next[i]);
}

/* Builds the subtrees of the children of a split node, at slots `left` and left + 1; returns their
 * leaves. Their descendants take the slots from *next = left + 2 on, and *next ends after the last.
 * On one thread the right child's descendants follow the left's: the nodes stay close in memory. A
 * big node's children are built on two threads if the build may start one more; the right child's
 * descendants then start where a full left subtree (2 nleft - 2 nodes) would end, and the gap is
 * never read. The slots differ, the tree does not: collapse follows the links, depth first. */
static int build_pair(builder *B, int left, int first, int count, const split *s, aabb lcb, aabb rcb,
                      int depth, int *next)
{
    child_pair c;
    c.B = B; c.depth = depth;
    c.node[0] = left; c.first[0] = first; c.count[0] = s->nleft; c.cb[0] = lcb; c.next[0] = *next;
    c.node[1] = left + 1; c.first[1] = first + s->nleft; c.count[1] = count - s->nleft; c.cb[1] = rcb;
    if (count >= BVH_PARALLEL_MIN && claim_thread(B, -1)) {
        c.next[1] = left + 2 * s->nleft;
        parallel_for(2, 1, 2, build_pair_body, &c);
        claim_thread(B, +1);
    } else {
        build_pair_body(&c, 0, 0, 1);
        c.next[1] = c.next[0];
        build_pair_body(&c, 0, 1, 2);
    }
    *next = c.next[1];
    return c.leaves[0] + c.leaves[1];
}

/* Builds the subtree of node ni, whose bounds are set, and returns its number of leaves. Its
 * descendants take the slots from *next on, at most 2 count - 2 of them (count leaves at most), and
 * *next ends after the last. */
static int build_rec(builder *B, int ni, int first, int count, aabb cb, int depth, int *next)
{
    split s;
    aabb lcb, rcb;
    node2 *nd = &B->nodes[ni];
    int left = *next, leaves;
    assert(ni >= 0 && ni < B->nslots && count > 0);
    if (!choose_split(B, first, count, &cb, depth, &s, &lcb, &rcb)) {
        nd->first = first; nd->count = count;
        subtree_cost(B, ni, first, count);
        return 1;
    }
    assert(s.nleft > 0 && s.nleft < count && left + 2 * count - 2 <= B->nslots);
    *next += 2;
    set_node(&B->nodes[left], &s.left);
    set_node(&B->nodes[left + 1], &s.right);
    nd->first = left; nd->count = 0;
    leaves = build_pair(B, left, first, count, &s, lcb, rcb, depth + 1, next);
    assert(*next <= left + 2 * count - 2);   /* within the range the caller set aside */
    subtree_cost(B, ni, first, count);
    return leaves;
}

/* ---- Build, step 2: the wide tree ------------------------------------------------------------- */
/* The primrefs [first, first + count) of one block. collapse writes these 8 bytes, not the 320 of
 * the block: the first write to a page costs the kernel's zeroing of it, and the blocks' pages are
 * then first written by fill_blocks, on every thread (at 16M triangles, collapse took 0.6-1.4 s
 * of a 3.7 s build on 2 threads, nearly all of it zeroing pages; 0.08-0.37 s so). */
typedef struct { int first, count; } leaf_span;
typedef struct {
    const builder *builder;
    const node2 *bin;
    const subtree *sub;
    const primref *refs;
    const vec3 *P;
    const int *tri;
    bvh *b;
    int max_nodes, max_blocks;   /* the lengths of b->nodes and b->blocks */
    leaf_span *span;             /* per block: its primrefs, which fill_blocks turns into triangles */
} collapser;

/* Appends to kids the roots of the cheapest cover of subtree ni by at most i of them (i >= 1). */
static void cover(const collapser *C, int ni, int i, int kids[BVH_WIDTH], int *k);

/* The roots of subtree ni shared between its two children, at most i >= 2 of them. */
static void cover_children(const collapser *C, int ni, int i, int kids[BVH_WIDTH], int *k)
{
    int l = C->bin[ni].first, j;
    share_cost(&C->sub[l], &C->sub[l + 1], i, &j);
    cover(C, l, j, kids, k);
    cover(C, l + 1, i - j, kids, k);
}
static void cover(const collapser *C, int ni, int i, int kids[BVH_WIDTH], int *k)
{
    const float *cost = C->sub[ni].cost;
    while (i > 1 && !(cost[i - 1] < cost[i - 2])) i--;   /* as subtree_cost chose */
    if (i == 1) kids[(*k)++] = ni;
    else cover_children(C, ni, i, kids, k);
}

/* A leaf's block: its primrefs, for fill_blocks. */
static int collapse_leaf(collapser *C, const subtree *sub)
{
    bvh *b = C->b;
    assert(b->nblocks < C->max_blocks && sub->count <= BVH_LEAF_MAX);
    C->span[b->nblocks].first = sub->first;
    C->span[b->nblocks].count = sub->count;
    return ~b->nblocks++;
}

/* Emits binary node ni as a leaf or a wide node, and its subtree, depth first; returns its reference. */
static int collapse(collapser *C, int ni, int depth)
{
    bvh *b = C->b;
    int kids[BVH_WIDTH], k = 0, wi, i, a, leaf;
    wnode *w;
    if (depth > b->depth) b->depth = depth;
    root_cost(C->builder, ni, &leaf);
    if (leaf) return collapse_leaf(C, &C->sub[ni]);
    cover_children(C, ni, BVH_WIDTH, kids, &k);
    assert(b->nnodes < C->max_nodes && k >= 2);
    wi = b->nnodes++;
    w = &b->nodes[wi];
    for (i = 0; i < BVH_WIDTH; i++) {
        for (a = 0; a < 3; a++) {
            w->box[a][i] = i < k ? C->bin[kids[i]].lo[a] : INFINITY;
            w->box[3 + a][i] = i < k ? C->bin[kids[i]].hi[a] : -INFINITY;
        }
        w->child[i] = ~0;
    }
    memset(w->pad, 0, sizeof w->pad);
    for (i = 0; i < k; i++) w->child[i] = collapse(C, kids[i], depth + 1);
    return wi;
}

/* parallel_body: the triangles of blocks [begin, end), from the spans collapse left; a block of
 * fewer than BVH_LEAF_MAX triangles repeats its last one. */
static void fill_blocks(void *ctx, int thread, int begin, int end)
{
    const collapser *C = ctx;
    int i, lane, k, id;
    (void)thread;
    for (i = begin; i < end; i++) {
        tri_block *blk = &C->b->blocks[i];
        const leaf_span *sp = &C->span[i];
        for (lane = 0; lane < BVH_LEAF_MAX; lane++) {
            id = ref_id(&C->refs[sp->first + (lane < sp->count ? lane : sp->count - 1)]);
            blk->id[lane] = id;
            for (k = 0; k < 3; k++) {
                vec3 p = C->P[C->tri[3 * id + k]];
                blk->v[k][0][lane] = p.x; blk->v[k][1][lane] = p.y; blk->v[k][2][lane] = p.z;
            }
        }
    }
}

#ifndef NDEBUG   /* only asserts call it */
/* Every child reference in range: a node after its parent (depth first), a block, or an empty slot. */
static int wide_tree_valid(const bvh *b)
{
    int n, i, ref;
    for (n = 0; n < b->nnodes; n++)
        for (i = 0; i < BVH_WIDTH; i++) {
            ref = b->nodes[n].child[i];
            if (ref >= 0 ? (ref <= n || ref >= b->nnodes) : (~ref >= b->nblocks && ref != ~0)) return 0;
        }
    return b->depth <= BVH_MAX_DEPTH && (b->root == 0 ? b->nnodes > 0 : b->root == ~0);
}
#endif

/* ---- Build: driver ------------------------------------------------------------------------------
 * The two linear passes (primrefs from triangles, blocks from leaves) give each thread one equal
 * share; make_refs keeps the bounds each thread saw, merged afterwards (min and max: exact in any
 * order). */
typedef struct {
    const vec3 *P;
    const int *tri;
    primref *refs;
    aabb box[PARALLEL_MAX_THREADS], cb[PARALLEL_MAX_THREADS];   /* per thread: triangles, centroids */
} ref_maker;

/* parallel_body: the primrefs of triangles [begin, end), their bounds grown into this thread's. */
static void make_refs(void *ctx, int thread, int begin, int end)
{
    ref_maker *M = ctx;
    aabb box = aabb_empty(), cb = aabb_empty();
    int i, k;
    for (i = begin; i < end; i++) {
        aabb t = aabb_empty();
        for (k = 0; k < 3; k++) {
            vec3 p = M->P[M->tri[3 * i + k]];
            aabb q = {{p.x, p.y, p.z, 0}, {p.x, p.y, p.z, 0}};
            aabb_grow(&t, &q);
        }
        memcpy(&t.lo[3], &i, sizeof i);
        t.hi[3] = 0;
        M->refs[i] = t;
        aabb_grow(&box, &t);
        aabb_grow_centroid(&cb, &t);
    }
    aabb_grow(&M->box[thread], &box);
    aabb_grow(&M->cb[thread], &cb);
}

/* ---- Build, step 0 (BVH_BUILD_SPLIT only): triangles cut into several primrefs ----------------
 * A long thin or tilted triangle fills little of its box, and that box overlaps its neighbours':
 * rays enter it for nothing. Before the build, such triangles get more than one primref, each
 * bounding the part of the triangle on one side of a plane that halves the box on its longest axis,
 * recursively (early split clipping: Ernst and Greiner 2007; Karras and Aila 2013, section 4.2, pick
 * the triangles alike). The extra primrefs, BVH_SPLIT_BUDGET times the triangles, are shared out in
 * proportion to each triangle's waste, the half area of its box less twice its own area (0 for a
 * right triangle in an axis plane), rounded up or down by a hash of its index so that the total
 * comes out right. A leaf then lists a triangle once per primref it holds: the same hit. */
#define BVH_SPLIT_BUDGET 0.25   /* extra primrefs per triangle, on average */
#define BVH_SPLIT_MAX 15        /* extra primrefs of one triangle, at most */

typedef struct {
    const vec3 *P;
    const int *tri;
    float *waste;       /* per triangle */
    int *first;         /* its first primref; first[ntris] = all of them */
    primref *refs;
    double sum[PARALLEL_MAX_THREADS];
    aabb box[PARALLEL_MAX_THREADS], cb[PARALLEL_MAX_THREADS];
} splitter;

static void corners(const vec3 *P, const int *tri, int i, float v[3][4])
{
    int k;
    for (k = 0; k < 3; k++) {
        vec3 p = P[tri[3 * i + k]];
        v[k][0] = p.x; v[k][1] = p.y; v[k][2] = p.z; v[k][3] = 0;
    }
}
static aabb corner_box(float v[3][4])
{
    aabb b = aabb_empty();
    int k;
    for (k = 0; k < 3; k++) { aabb q; memcpy(q.lo, v[k], sizeof q.lo); memcpy(q.hi, v[k], sizeof q.hi); aabb_grow(&b, &q); }
    return b;
}

/* parallel_body: the waste of triangles [begin, end), and their sum per thread. */
static void split_waste(void *ctx, int thread, int begin, int end)
{
    splitter *S = ctx;
    float v[3][4];
    double sum = 0;
    int i;
    for (i = begin; i < end; i++) {
        aabb b;
        vec3 e1, e2, n;
        corners(S->P, S->tri, i, v);
        b = corner_box(v);
        e1 = v3(v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]);
        e2 = v3(v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]);
        n = v3_cross(e1, e2);                       /* |n| = twice the triangle's area */
        S->waste[i] = fmaxf(0.0f, aabb_area(&b) - sqrtf(v3_dot(n, n)));
        sum += S->waste[i];
    }
    S->sum[thread] += sum;
}

/* Grows l and r by the point x, widened by `slack` on every axis. */
static void grow_both(aabb *l, aabb *r, const float x[4], float slack)
{
    aabb q;
    int a;
    for (a = 0; a < 4; a++) { q.lo[a] = x[a] - slack; q.hi[a] = x[a] + slack; }
    aabb_grow(l, &q);
    aabb_grow(r, &q);
}

/* The bounds of the part of triangle v inside `box` on each side of the plane x[axis] = c: its
 * corners on that side and the points where its edges cross the plane, those widened by a few ulps
 * of the corners (the crossing is rounded), then clipped to the side and to the box. */
static void clip_split(float v[3][4], const aabb *box, int axis, float c, aabb *l, aabb *r)
{
    float x[4];
    int e, a;
    *l = *r = aabb_empty();
    for (e = 0; e < 3; e++) {
        const float *p = v[e], *q = v[(e + 1) % 3];
        aabb pt;
        memcpy(pt.lo, p, sizeof pt.lo); memcpy(pt.hi, p, sizeof pt.hi);
        if (p[axis] <= c) aabb_grow(l, &pt);
        if (p[axis] >= c) aabb_grow(r, &pt);
        if ((p[axis] < c && q[axis] > c) || (p[axis] > c && q[axis] < c)) {
            float t = (c - p[axis]) / (q[axis] - p[axis]), slack = 0;
            for (a = 0; a < 3; a++) {
                x[a] = p[a] + t * (q[a] - p[a]);
                slack = fmaxf(slack, (fabsf(p[a]) + fabsf(q[a])) * 0x1p-20f);
            }
            x[3] = 0;
            grow_both(l, r, x, slack);
        }
    }
    l->hi[axis] = fminf(l->hi[axis], c);
    r->lo[axis] = fmaxf(r->lo[axis], c);
    for (a = 0; a < 3; a++) {
        l->lo[a] = fmaxf(l->lo[a], box->lo[a]); l->hi[a] = fminf(l->hi[a], box->hi[a]);
        r->lo[a] = fmaxf(r->lo[a], box->lo[a]); r->hi[a] = fminf(r->hi[a], box->hi[a]);
    }
    l->lo[3] = l->hi[3] = r->lo[3] = r->hi[3] = 0;
}

/* Writes extra + 1 primrefs of triangle id covering its part inside box; returns the next slot. */
static primref *split_tri(float v[3][4], aabb box, int extra, int id, primref *out)
{
    aabb l, r;
    float ex = box.hi[0] - box.lo[0], ey = box.hi[1] - box.lo[1], ez = box.hi[2] - box.lo[2];
    int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2, nl;
    if (extra > 0 && box.hi[axis] > box.lo[axis]) {
        clip_split(v, &box, axis, 0.5f * (box.lo[axis] + box.hi[axis]), &l, &r);
        if (l.lo[axis] <= l.hi[axis] && r.lo[axis] <= r.hi[axis]) {
            nl = (extra - 1 + (aabb_area(&l) >= aabb_area(&r))) / 2;   /* the bigger part gets the odd one */
            out = split_tri(v, l, nl, id, out);
            return split_tri(v, r, extra - 1 - nl, id, out);
        }
    }
    for (; extra >= 0; extra--, out++) {           /* a point, or a piece too thin to cut: copies */
        *out = box;
        memcpy(&out->lo[3], &id, sizeof id);
        out->hi[3] = 0;
    }
    return out;
}

/* parallel_body: the primrefs of triangles [begin, end), at first[i], and their bounds per thread. */
static void split_refs(void *ctx, int thread, int begin, int end)
{
    splitter *S = ctx;
    float v[3][4];
    aabb box = aabb_empty(), cb = aabb_empty();
    int i, j;
    for (i = begin; i < end; i++) {
        corners(S->P, S->tri, i, v);
        split_tri(v, corner_box(v), S->first[i + 1] - S->first[i] - 1, i, S->refs + S->first[i]);
        for (j = S->first[i]; j < S->first[i + 1]; j++) { aabb_grow(&box, &S->refs[j]); aabb_grow_centroid(&cb, &S->refs[j]); }
    }
    aabb_grow(&S->box[thread], &box);
    aabb_grow(&S->cb[thread], &cb);
}

/* Each triangle's share of the extra primrefs: first[] as splitter says; the total, or -1 if it
 * would not fit an int (then no triangle is split). */
static int split_counts(splitter *S, int ntris, int threads)
{
    double total = 0, scale;
    long n = 0;
    int i, t;
    for (t = 0; t < threads; t++) S->sum[t] = 0;
    parallel_for(ntris, parallel_even_grain(ntris, threads), threads, split_waste, S);
    for (t = 0; t < threads; t++) total += S->sum[t];
    scale = total > 0 ? BVH_SPLIT_BUDGET * ntris / total : 0;
    S->first[0] = 0;
    for (i = 0; i < ntris; i++) {
        uint32_t h = (uint32_t)i * 0x9e3779b9u;    /* a hash of i, for the rounding */
        double share = scale * S->waste[i] + (double)((h ^ h >> 15) >> 8) * (1.0 / 16777216.0);
        int extra = share < BVH_SPLIT_MAX ? (int)share : BVH_SPLIT_MAX;
        n += 1 + extra;
        if (n > INT_MAX / 2) return -1;
        S->first[i + 1] = (int)n;
    }
    return (int)n;
}

/* Step 0: B->refs, the triangles split; returns their number (0: out of memory, or -1: too many). */
static int build_split_refs(builder *B, const vec3 *P, const int *tri, int ntris, int threads, aabb *cb)
{
    splitter S;
    int nrefs = 0, t;
    S.P = P; S.tri = tri;
    S.waste = big_array((size_t)ntris, sizeof(float), 64);
    S.first = big_array((size_t)ntris + 1, sizeof(int), 64);
    if (S.waste && S.first) nrefs = split_counts(&S, ntris, threads);
    if (nrefs > 0 && (B->refs = big_array((size_t)nrefs, sizeof(primref), 64)) != NULL) {
        S.refs = B->refs;
        for (t = 0; t < threads; t++) S.box[t] = S.cb[t] = aabb_empty();
        parallel_for(ntris, parallel_even_grain(ntris, threads), threads, split_refs, &S);
        for (t = 1; t < threads; t++) { aabb_grow(&S.box[0], &S.box[t]); aabb_grow(&S.cb[0], &S.cb[t]); }
        cb[0] = S.box[0]; cb[1] = S.cb[0];
    } else if (nrefs > 0) nrefs = 0;
    free(S.waste);
    free(S.first);
    return nrefs;
}

/* Step 0 without splits: one primref per triangle; its bounds in cb[0], its centroids' in cb[1]. */
static int build_refs(builder *B, const vec3 *P, const int *tri, int ntris, int threads, aabb *cb)
{
    ref_maker M;
    int t;
    B->refs = big_array((size_t)ntris, sizeof(primref), 64);
    if (!B->refs) return 0;
    M.P = P; M.tri = tri; M.refs = B->refs;
    for (t = 0; t < threads; t++) M.box[t] = M.cb[t] = aabb_empty();
    parallel_for(ntris, parallel_even_grain(ntris, threads), threads, make_refs, &M);
    for (t = 1; t < threads; t++) { aabb_grow(&M.box[0], &M.box[t]); aabb_grow(&M.cb[0], &M.cb[t]); }
    cb[0] = M.box[0]; cb[1] = M.cb[0];
    return ntris;
}

/* Step 1; returns the number of leaves, 0 when out of memory. */
static int build_binary(builder *B, const vec3 *P, const int *tri, int ntris, int threads, int quality)
{
    aabb cb[2];
    int leaves, next = 1, nrefs = -1;
    if (quality == BVH_BUILD_SPLIT) nrefs = build_split_refs(B, P, tri, ntris, threads, cb);
    if (nrefs < 0) nrefs = build_refs(B, P, tri, ntris, threads, cb);   /* too many to split: as usual */
    if (nrefs == 0) return 0;
    B->nslots = 2 * nrefs;
    B->nodes = big_array((size_t)B->nslots, sizeof(node2), 64);
    B->sub = big_array((size_t)B->nslots, sizeof(subtree), 64);
    if (!B->nodes || !B->sub) return 0;
    set_node(&B->nodes[0], &cb[0]);
    B->idle = threads - 1;
    pthread_mutex_init(&B->lock, NULL);
    leaves = build_rec(B, 0, 0, nrefs, cb[1], 0, &next);
    pthread_mutex_destroy(&B->lock);
    return leaves;
}

/* Step 2: a wide tree with at most leaves - 1 nodes (each has 2 children at least). */
static int build_wide(bvh *b, const builder *B, const vec3 *P, const int *tri, int leaves, int threads)
{
    collapser C;
    C.builder = B; C.bin = B->nodes; C.sub = B->sub; C.refs = B->refs; C.P = P; C.tri = tri; C.b = b;
    C.max_nodes = leaves > 1 ? leaves - 1 : 1;
    C.max_blocks = leaves;
    b->nodes = big_array((size_t)C.max_nodes, sizeof(wnode), 64);
    b->blocks = big_array((size_t)C.max_blocks, sizeof(tri_block), 64);
    C.span = big_array((size_t)C.max_blocks, sizeof(leaf_span), 64);
    if (!b->nodes || !b->blocks || !C.span) { free(C.span); return 0; }
    b->root = collapse(&C, 0, 1);
    assert(b->nblocks <= leaves && wide_tree_valid(b));
    parallel_for(b->nblocks, parallel_even_grain(b->nblocks, threads), threads, fill_blocks, &C);
    free(C.span);
    return 1;
}

/* ---- Which copy of the traversal --------------------------------------------------------------
 * bvh_traverse.c is compiled for SSE2 (the base, any x86-64), AVX2 + FMA and AVX-512 when the
 * Makefile defines BVH_DISPATCH (x86-64); the best one the CPU runs is chosen, or the one forced
 * by bvh_isa_force (--isa). All give the same hits (bvh_traverse.c). */
static const bvh_traversal *forced;   /* set before any tree is built (single-threaded start) */

static const bvh_traversal *const *traversals(void)
{
    static const bvh_traversal *const all[] = {
#ifdef BVH_DISPATCH
        &bvh_traversal_avx512, &bvh_traversal_avx2,
#endif
        &bvh_traversal_base, NULL};
    return all;
}

static int cpu_runs(const bvh_traversal *t)
{
#ifdef BVH_DISPATCH
    if (t == &bvh_traversal_avx512)
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
               __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
    if (t == &bvh_traversal_avx2) return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#endif
    (void)t;
    return 1;
}

static const bvh_traversal *bvh_isa_traversal(void)
{
    const bvh_traversal *const *t = traversals();
    if (forced) return forced;
    while (!cpu_runs(*t)) t++;   /* the base runs everywhere: the list ends with it */
    return *t;
}

const char *bvh_isa(void) { return bvh_isa_traversal()->name; }

void bvh_isa_names(char *dst, size_t cap)
{
    const bvh_traversal *const *t;
    size_t n = 0;
    if (cap) dst[0] = '\0';
    for (t = traversals(); *t && n < cap; t++)
        n += (size_t)snprintf(dst + n, cap - n, "%s%s%s", n ? ", " : "", (*t)->name, cpu_runs(*t) ? "" : " (not on this CPU)");
}

int bvh_isa_force(const char *name)
{
    const bvh_traversal *const *t;
    if (!name) { forced = NULL; return 0; }
    for (t = traversals(); *t; t++)
        if (!strcmp((*t)->name, name)) {
            if (!cpu_runs(*t)) return -2;
            forced = *t;
            return 0;
        }
    return -1;
}

int bvh_intersect(const bvh *b, const ray *r, hit *h) { return b->trav->intersect(b, r, h); }
int bvh_occluded(const bvh *b, const ray *r) { return b->trav->occluded(b, r, -1); }
int bvh_occluded_except(const bvh *b, const ray *r, int tri) { return b->trav->occluded(b, r, tri); }

bvh *bvh_build(const vec3 *P, const int *tri, int ntris, int threads)
{
    return bvh_build_quality(P, tri, ntris, threads, BVH_BUILD_DEFAULT);
}

bvh *bvh_build_quality(const vec3 *P, const int *tri, int ntris, int threads, int quality)
{
    builder B;
    bvh *b = calloc(1, sizeof *b);
    int ok, leaves;
    B.refs = NULL; B.nodes = NULL; B.sub = NULL;   /* build_binary sets up the rest */
    if (!b) return NULL;
    b->trav = bvh_isa_traversal();
    if (ntris == 0) return b;                   /* an empty bvh: every ray misses */
    if (ntris < 0 || ntris > INT_MAX / 2) { free(b); return NULL; }
    /* a small mesh builds faster than a thread starts (a loaded machine took 5-33 ms to start the
     * two parallel passes' threads for the Cornell box's 38 triangles, against 0 ms on one thread) */
    threads = ntris < BVH_PARALLEL_MIN ? 1 : parallel_threads(threads);
    leaves = build_binary(&B, P, tri, ntris, threads, quality);
    ok = leaves > 0 && build_wide(b, &B, P, tri, leaves, threads);
    free(B.refs);
    free(B.nodes);
    free(B.sub);
    if (!ok) { bvh_free(b); return NULL; }
    return b;
}

void bvh_free(bvh *b)
{
    if (!b) return;
    free(b->nodes);
    free(b->blocks);
    free(b);
}

void bvh_stats(const bvh *b, int *nodes, int *leaves, int *depth)
{
    if (nodes) *nodes = b->nnodes;
    if (leaves) *leaves = b->nblocks;
    if (depth) *depth = b->depth;
}

/* 1 if lane i of blk (a triangle) has a box that meets [lo, hi]. */
static int lane_box_meets(const tri_block *blk, int i, vec3 lo, vec3 hi)
{
    float l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    int a;
    for (a = 0; a < 3; a++) {
        float x = blk->v[0][a][i], y = blk->v[1][a][i], z = blk->v[2][a][i];
        float mn = x < y ? (x < z ? x : z) : (y < z ? y : z), mx = x > y ? (x > z ? x : z) : (y > z ? y : z);
        if (mn > h[a] || mx < l[a]) return 0;
    }
    return 1;
}

int bvh_any_in_box(const bvh *b, vec3 lo, vec3 hi, int (*test)(void *ctx, int tri), void *ctx)
{
    int stack[BVH_STACK], sp = 0, ref = b->root, i;
    if (!b->nblocks) return 0;
    for (;;) {
        if (ref >= 0) {
            const wnode *n = &b->nodes[ref];
            for (i = 0; i < BVH_WIDTH; i++)   /* an empty slot (lo +inf, hi -inf) meets nothing */
                if (n->box[0][i] <= hi.x && n->box[3][i] >= lo.x && n->box[1][i] <= hi.y && n->box[4][i] >= lo.y &&
                    n->box[2][i] <= hi.z && n->box[5][i] >= lo.z)
                    stack[sp++] = n->child[i];
        } else {
            const tri_block *blk = &b->blocks[~ref];
            for (i = 0; i < BVH_LEAF_MAX; i++)
                if ((i == 0 || blk->id[i] != blk->id[i - 1]) && lane_box_meets(blk, i, lo, hi) && test(ctx, blk->id[i])) return 1;
        }
        if (sp == 0) return 0;
        ref = stack[--sp];
    }
}
