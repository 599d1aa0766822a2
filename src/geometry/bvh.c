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
 *     more; the tree is the same for any number of threads. Nothing is sorted, nothing allocated
 *     per node.
 *  2. The binary tree is collapsed into an 8-wide one by those costs: a subtree becomes a leaf (a
 *     block of up to 8 triangles) or a wide node over the cheapest cover of its subtree by at most
 *     8 children (collapse, cover), laid out depth first. A node tests its 8 boxes with the few
 *     instructions of one loop the compiler vectorizes, and a block its 8 triangles likewise: that
 *     is what makes single rays fast without intrinsics, and the wide nodes make the tree shallow,
 *     which matters most for incoherent rays in big meshes.
 *     With AVX-512 (a -march=native build) the same tests are written with intrinsics, whose masks
 *     and compress instructions the compiler does not find (node_hits_v, block_hits_v).
 *
 * How it is traversed: one loop with an explicit stack. At a node, the children the ray enters are
 * sorted by entry distance: the nearest is visited next, the others pushed farthest first. Popped
 * nodes entered beyond the closest hit so far are skipped. Shadow rays skip the sorting.
 *
 * Robustness: the triangle test is watertight (Woop, Benthin, Wald 2013) and the box test is
 * conservative (pbrt's 1 + 2 gamma(3) on exit distances, folded into the 1/d they use), so no ray slips between two triangles
 * sharing an edge or a vertex, and a box never hides a triangle the triangle test would report. */
#include "geometry/bvh.h"
#include "sys/big_array.h"
#include "sys/parallel.h"
#include <assert.h>
#include <float.h>
#include <limits.h>
#include <stddef.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
/* A -march=native build on a CPU with AVX-512 tests nodes with intrinsics (see node_hits_v);
 * -DBVH_NO_AVX512 keeps the portable loops there too, to compare them. */
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

struct bvh {
    wnode *nodes;      /* nodes[0] is the root */
    tri_block *blocks;
    int root;          /* 0, or ~0 when the whole tree is one leaf (or empty: no blocks at all) */
    int nnodes, nblocks, depth;
};

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
static inline void aabb_grow(aabb *restrict b, const aabb *restrict p)
{
    int i;
    for (i = 0; i < 4; i++) {
        b->lo[i] = p->lo[i] < b->lo[i] ? p->lo[i] : b->lo[i];
        b->hi[i] = p->hi[i] > b->hi[i] ? p->hi[i] : b->hi[i];
    }
}
/* Centroids are kept doubled (lo + hi): one add instead of an add and a multiply. */
static inline void aabb_grow_centroid(aabb *restrict b, const primref *restrict p)
{
    aabb c;
    int i;
    for (i = 0; i < 4; i++) c.lo[i] = c.hi[i] = p->lo[i] + p->hi[i];
    aabb_grow(b, &c);
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

static void bin_refs(const primref *r, int n, const aabb *cb, const float scale[3], int nbins, bins *B)
{
    int a, i, k;
    for (a = 0; a < 3; a++)
        for (k = 0; k < nbins; k++) { B->box[a][k] = aabb_empty(); B->n[a][k] = 0; }
    for (i = 0; i < n; i++)
        for (a = 0; a < 3; a++) {
            k = bin_of(&r[i], a, cb, scale[a], nbins);
            aabb_grow(&B->box[a][k], &r[i]);
            B->n[a][k]++;
        }
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

/* Cheapest binned SAH split of refs [0, n); 0 when every centroid is the same point. */
static int find_split(const primref *r, int n, const aabb *cb, split *s, float scale[3])
{
    bins B;
    int nbins = bins_for(n), a;
    for (a = 0; a < 3; a++) {
        float extent = cb->hi[a] - cb->lo[a];
        scale[a] = extent > 0 ? (float)nbins / extent : 0.0f;
        if (!(scale[a] < FLT_MAX)) scale[a] = 0.0f;   /* a denormal extent: treat the axis as flat */
    }
    bin_refs(r, n, cb, scale, nbins, &B);
    s->cost = INFINITY;
    s->nbins = nbins;
    for (a = 0; a < 3; a++)
        if (scale[a] > 0) sweep_axis(B.box[a], B.n[a], nbins, a, s);
    return s->cost < INFINITY;
}

static void swap_refs(primref *a, primref *b) { primref t = *a; *a = *b; *b = t; }

/* Moves the refs of bins < s->bin to the front; fills the children's centroid bounds. */
static int partition(primref *r, int n, const split *s, const aabb *cb, float scale, aabb *lcb, aabb *rcb)
{
    int i = 0, j = n - 1;
    *lcb = aabb_empty(); *rcb = aabb_empty();
    for (;;) {
        while (i <= j && bin_of(&r[i], s->axis, cb, scale, s->nbins) < s->bin) aabb_grow_centroid(lcb, &r[i++]);
        while (i <= j && bin_of(&r[j], s->axis, cb, scale, s->nbins) >= s->bin) aabb_grow_centroid(rcb, &r[j--]);
        if (i >= j) break;
        swap_refs(&r[i], &r[j]);    /* both now on their side; the loops above grow their bounds */
    }
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
    if (depth < BVH_SAH_DEPTH && find_split(r, count, cb, s, scale)) {
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
typedef struct {
    const builder *builder;
    const node2 *bin;
    const subtree *sub;
    const primref *refs;
    const vec3 *P;
    const int *tri;
    bvh *b;
    int max_nodes, max_blocks;   /* the lengths of b->nodes and b->blocks */
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

/* A leaf's block: the primref index of each lane in id[] (fill_blocks turns them into triangles). */
static int collapse_leaf(collapser *C, const subtree *sub)
{
    bvh *b = C->b;
    tri_block *blk = &b->blocks[b->nblocks];
    int lane;
    assert(b->nblocks < C->max_blocks && sub->count <= BVH_LEAF_MAX);
    for (lane = 0; lane < BVH_LEAF_MAX; lane++) blk->id[lane] = sub->first + (lane < sub->count ? lane : sub->count - 1);
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

/* parallel_body: the triangles of blocks [begin, end), from the primref indices collapse left. */
static void fill_blocks(void *ctx, int thread, int begin, int end)
{
    const collapser *C = ctx;
    int i, lane, k, id;
    (void)thread;
    for (i = begin; i < end; i++) {
        tri_block *blk = &C->b->blocks[i];
        for (lane = 0; lane < BVH_LEAF_MAX; lane++) {
            id = ref_id(&C->refs[blk->id[lane]]);
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

/* parallel_body: the primrefs of triangles [begin, end). */
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

/* Step 1; returns the number of leaves, 0 when out of memory. */
static int build_binary(builder *B, const vec3 *P, const int *tri, int ntris, int threads)
{
    ref_maker M;
    int t, leaves, next = 1;
    B->nslots = 2 * ntris;
    B->refs = big_array((size_t)ntris, sizeof(primref), 64);
    B->nodes = big_array((size_t)B->nslots, sizeof(node2), 64);
    B->sub = big_array((size_t)B->nslots, sizeof(subtree), 64);
    if (!B->refs || !B->nodes || !B->sub) return 0;
    M.P = P; M.tri = tri; M.refs = B->refs;
    for (t = 0; t < threads; t++) M.box[t] = M.cb[t] = aabb_empty();
    parallel_for(ntris, parallel_even_grain(ntris, threads), threads, make_refs, &M);
    for (t = 1; t < threads; t++) { aabb_grow(&M.box[0], &M.box[t]); aabb_grow(&M.cb[0], &M.cb[t]); }
    set_node(&B->nodes[0], &M.box[0]);
    B->idle = threads - 1;
    pthread_mutex_init(&B->lock, NULL);
    leaves = build_rec(B, 0, 0, ntris, M.cb[0], 0, &next);
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
    if (!b->nodes || !b->blocks) return 0;
    b->root = collapse(&C, 0, 1);
    assert(b->nblocks <= leaves && wide_tree_valid(b));
    parallel_for(b->nblocks, parallel_even_grain(b->nblocks, threads), threads, fill_blocks, &C);
    return 1;
}

bvh *bvh_build(const vec3 *P, const int *tri, int ntris, int threads)
{
    builder B;
    bvh *b = calloc(1, sizeof *b);
    int ok, leaves;
    B.refs = NULL; B.nodes = NULL; B.sub = NULL;   /* build_binary sets up the rest */
    if (!b || ntris == 0) return b;             /* an empty bvh: every ray misses */
    if (ntris < 0 || ntris > INT_MAX / 2) { free(b); return NULL; }
    /* a small mesh builds faster than a thread starts (a loaded machine took 5-33 ms to start the
     * two parallel passes' threads for the Cornell box's 38 triangles, against 0 ms on one thread) */
    threads = ntris < BVH_PARALLEL_MIN ? 1 : parallel_threads(threads);
    leaves = build_binary(&B, P, tri, ntris, threads);
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
#ifdef BVH_AVX512   /* a block's lanes are one vector: L_(op) names the intrinsic of its width */
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
#ifdef BVH_AVX512
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
#ifdef BVH_AVX512
    p->bo[0] = L_(set1_ps)(o[kx]); p->bo[1] = L_(set1_ps)(o[ky]); p->bo[2] = L_(set1_ps)(o[kz]);
    p->bS[0] = L_(set1_ps)(p->Sx); p->bS[1] = L_(set1_ps)(p->Sy); p->bS[2] = L_(set1_ps)(p->Sz);
#endif
}

static inline const float *row(const wnode *n, ptrdiff_t offset) { return (const float *)((const char *)n + offset); }

#ifndef BVH_AVX512   /* the portable tests; with AVX-512, node_hits_v and block_hits_v */
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

#ifndef BVH_AVX512
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

#ifdef BVH_AVX512
/* block_hits_float with intrinsics: the same operations in the same order (see node_hits_v), on
 * one vector of BVH_LEAF_MAX lanes (lanes, L_). */
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
    unsigned neg = L_(cmp_ps_mask)(U, zero, _CMP_LT_OQ) | L_(cmp_ps_mask)(V, zero, _CMP_LT_OQ) | L_(cmp_ps_mask)(W, zero, _CMP_LT_OQ);
    unsigned pos = L_(cmp_ps_mask)(U, zero, _CMP_GT_OQ) | L_(cmp_ps_mask)(V, zero, _CMP_GT_OQ) | L_(cmp_ps_mask)(W, zero, _CMP_GT_OQ);
    unsigned inside = ~(neg & pos) & ((1u << BVH_LEAF_MAX) - 1), mask;
    *edge = inside & (L_(cmp_ps_mask)(U, zero, _CMP_EQ_OQ) | L_(cmp_ps_mask)(V, zero, _CMP_EQ_OQ) |
                      L_(cmp_ps_mask)(W, zero, _CMP_EQ_OQ));
    if (!inside) return 0;
    det = L_(add_ps)(L_(add_ps)(U, V), W);
    T = L_(add_ps)(L_(add_ps)(L_(mul_ps)(U, L_(mul_ps)(Sz, az)), L_(mul_ps)(V, L_(mul_ps)(Sz, bz))),
                   L_(mul_ps)(W, L_(mul_ps)(Sz, cz)));
    rcp = L_(div_ps)(L_(set1_ps)(1.0f), det);
    t = L_(mul_ps)(T, rcp);
    L_(storeu_ps)(h->t, t); L_(storeu_ps)(h->u, L_(mul_ps)(V, rcp)); L_(storeu_ps)(h->v, L_(mul_ps)(W, rcp));
    mask = L_(cmp_ps_mask)(det, zero, _CMP_NEQ_UQ) & L_(cmp_ps_mask)(t, zero, _CMP_GT_OQ) &
           L_(cmp_ps_mask)(t, L_(set1_ps)(tmax), _CMP_LT_OQ);
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

/* Of the children in mask (not empty), returns the nearest and pushes the others farthest first, so
 * that they come off the stack nearest first. Usually one or two children are hit.
 * Measured: a test per lane (predictable branches, and the next node stays in a register) runs
 * faster than looping over the set bits, although it executes more instructions. */
typedef struct { int ref; float t; } entry;

#ifndef BVH_AVX512
static inline int push_near_first(const wnode *n, unsigned mask, const float dist[BVH_WIDTH], entry *stack, int *sp)
{
    entry e[BVH_WIDTH], x;
    int k = 0, i, j;
    for (i = 0; i < BVH_WIDTH; i++)
        if (mask >> i & 1) { e[k].ref = n->child[i]; e[k].t = dist[i]; k++; }
    if (k == 1) return e[0].ref;
    assert(*sp + k - 1 <= BVH_STACK);   /* the tree's depth bounds it (wide_tree_valid) */
    if (k == 2) {
        int near = e[1].t < e[0].t;
        stack[(*sp)++] = e[1 - near];
        return e[near].ref;
    }
    for (i = 1; i < k; i++) {         /* insertion sort, farthest first */
        x = e[i];
        for (j = i; j > 0 && e[j - 1].t < x.t; j--) e[j] = e[j - 1];
        e[j] = x;
    }
    for (j = 0; j < k - 1; j++) stack[(*sp)++] = e[j];
    return e[k - 1].ref;
}
#endif

#ifdef BVH_AVX512
/* With AVX-512, nodes (and blocks, block_hits_v) are tested with intrinsics: the same operations
 * in the same order as node_hits (so the same children are entered at the same distances and every
 * hit is the same), but the hit mask comes out of one compare into a mask register instead of eight
 * bits ORed together, and closest-hit rays pack the children hit with one compress instead of a
 * branch per lane, which mispredicts on incoherent rays. Measured (docs/performance.md, issue 12
 * item 4): dragon diffuse rays 1.2x faster, shadow 1.1x. Shadow rays keep the branch per lane:
 * with the compress they were 0.91x. */
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
static inline int push_near_first_v(const wnode *n, unsigned mask, __m256 dist, entry *stack, int *sp)
{
    float t[BVH_WIDTH];
    int r[BVH_WIDTH], k, i, j;
    unsigned rest = mask & (mask - 1);
    if (!rest) return n->child[__builtin_ctz(mask)];
    if (!(rest & (rest - 1))) {       /* two children: no compress */
        int a = __builtin_ctz(mask), c = __builtin_ctz(rest), near;
        _mm256_storeu_ps(t, dist);
        near = t[c] < t[a];
        assert(*sp + 1 <= BVH_STACK);
        stack[*sp].ref = n->child[near ? a : c]; stack[*sp].t = t[near ? a : c]; (*sp)++;
        return n->child[near ? c : a];
    }
    _mm256_storeu_ps(t, _mm256_maskz_compress_ps((__mmask8)mask, dist));
    _mm256_storeu_si256((__m256i *)r, _mm256_maskz_compress_epi32((__mmask8)mask,
                                                                  _mm256_load_si256((const __m256i *)n->child)));
    k = __builtin_popcount(mask);
    assert(*sp + k - 1 <= BVH_STACK);
    if (k == 2) {
        int near = t[1] < t[0];
        stack[*sp].ref = r[1 - near]; stack[*sp].t = t[1 - near]; (*sp)++;
        return r[near];
    }
    for (i = 1; i < k; i++) {
        float xt = t[i];
        int xr = r[i];
        for (j = i; j > 0 && t[j - 1] < xt; j--) { t[j] = t[j - 1]; r[j] = r[j - 1]; }
        t[j] = xt; r[j] = xr;
    }
    for (j = 0; j < k - 1; j++) { stack[*sp].ref = r[j]; stack[*sp].t = t[j]; (*sp)++; }
    return r[k - 1];
}
#endif

static int ray_is_valid(const ray *r)
{
    float s = r->o.x + r->o.y + r->o.z + r->d.x + r->d.y + r->d.z;
    return s - s == 0.0f && !v3_is_zero(r->d) && r->tmax > 0.0f;   /* no inf, no NaN */
}

int bvh_intersect(const bvh *b, const ray *r, hit *h)
{
    entry stack[BVH_STACK];
    int sp = 0, ref = b->root, best_lane = -1;
    float tmax = r->tmax, tcull = tmax * BVH_T_WIDEN, bu = 0, bv = 0;
    const tri_block *best = NULL;
    ray_pre p;
#ifdef BVH_AVX512
    ray_vec v;
#endif
    h->tri = -1;
    if (!b->nblocks || !ray_is_valid(r)) return 0;
    ray_prepare(r, &p);
#ifdef BVH_AVX512
    v = ray_vectors(&p);
#endif
    for (;;) {
        if (ref >= 0) {            /* node: go on with the nearest child entered, stack the others */
#ifdef BVH_AVX512
            __m256 dist;
            unsigned mask = node_hits_v(&b->nodes[ref], &p, &v, tcull, &dist);
            if (mask) { ref = push_near_first_v(&b->nodes[ref], mask, dist, stack, &sp); continue; }
#else
            float dist[BVH_WIDTH];
            unsigned mask = node_hits(&b->nodes[ref], &p, tcull, dist);
            if (mask) { ref = push_near_first(&b->nodes[ref], mask, dist, stack, &sp); continue; }
#endif
        } else {                   /* leaf: keep the nearest of its triangles closer than tmax */
            const tri_block *blk = &b->blocks[~ref];
            lane_hits lh;
            unsigned mask = block_hits(blk, &p, tmax, &lh);
            for (; mask; mask &= mask - 1) {
                int i = lowest_bit(mask);
                if (lh.t[i] < tmax) { tmax = lh.t[i]; bu = lh.u[i]; bv = lh.v[i]; best = blk; best_lane = i; }
            }
            tcull = tmax * BVH_T_WIDEN;
        }
        do {                       /* next stacked node that may still hold a closer hit */
            if (sp == 0) goto done;
            --sp;
        } while (stack[sp].t > tcull);
        ref = stack[sp].ref;
    }
done:
    if (!best) return 0;
    h->t = tmax; h->u = bu; h->v = bv; h->tri = best->id[best_lane];
    return 1;
}

int bvh_occluded(const bvh *b, const ray *r)
{
    int stack[BVH_STACK], sp = 0, ref = b->root, i;
    float tmax = r->tmax, tcull = tmax * BVH_T_WIDEN;
    ray_pre p;
#ifdef BVH_AVX512
    ray_vec v;
#endif
    if (!b->nblocks || !ray_is_valid(r)) return 0;
    ray_prepare(r, &p);
#ifdef BVH_AVX512
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
#else
            float dist[BVH_WIDTH];
            unsigned mask = node_hits(n, &p, tcull, dist);
            assert(sp + BVH_WIDTH <= BVH_STACK);
            for (i = 0; i < BVH_WIDTH; i++)
                if (mask >> i & 1) stack[sp++] = n->child[i];
#endif
        } else {
            lane_hits lh;
            if (block_hits(&b->blocks[~ref], &p, tmax, &lh)) return 1;
        }
        if (sp == 0) return 0;
        ref = stack[--sp];
    }
}

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
