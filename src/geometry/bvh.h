/* bvh.h — bounding volume hierarchy over triangles: build with binned SAH, trace rays.
 * bvh_intersect finds the closest hit, bvh_occluded stops at the first hit (shadow rays).
 * The ray-triangle test is watertight (Woop, Benthin, Wald 2013): a ray through a shared edge or
 * vertex of a closed mesh hits at least one of the triangles. */
#ifndef PATHLAB_BVH_H
#define PATHLAB_BVH_H
#include "geometry/ray.h"
#include <stddef.h>

typedef struct bvh bvh;

/* Builds over ntris triangles with corners P[tri[3i+k]], using up to `threads` threads.
 * Returns NULL on allocation failure. The bvh keeps its own copy of what it needs. */
bvh *bvh_build(const vec3 *P, const int *tri, int ntris, int threads);
/* The same with a choice of build: BVH_BUILD_DEFAULT (bvh_build's), or BVH_BUILD_SPLIT, which first
 * cuts the triangles that fill least of their boxes into several pieces, each with a tighter box
 * (about a quarter more primitives, a slower build; bench-rays --bvh-quality split measures it).
 * Both find the same hits. */
enum { BVH_BUILD_DEFAULT, BVH_BUILD_SPLIT };
bvh *bvh_build_quality(const vec3 *P, const int *tri, int ntris, int threads, int quality);
void bvh_free(bvh *b);
/* Closest hit with t in (0, r->tmax); returns 1 and fills h on a hit, else 0 (h->tri = -1). */
int bvh_intersect(const bvh *b, const ray *r, hit *h);
/* 1 if any triangle is hit with t in (0, r->tmax). */
int bvh_occluded(const bvh *b, const ray *r);
/* 1 if any triangle but tri is hit with t in (0, r->tmax): a shadow ray that ends on an emitter's
 * triangle, which its own rounding may hit or miss near t = 1 (tri < 0: bvh_occluded). */
int bvh_occluded_except(const bvh *b, const ray *r, int tri);
/* Calls test(ctx, t) for each triangle t whose box meets the box [lo, hi] (some more than once, in
 * no set order) until it returns 1; returns 1 then, else 0. For what a scene checks once at load. */
int bvh_any_in_box(const bvh *b, vec3 lo, vec3 hi, int (*test)(void *ctx, int tri), void *ctx);
/* The bvh's ray-triangle test on one triangle (a, b, c), for reference and tests: returns 1 and
 * fills h->t, h->u, h->v (not h->tri) when the ray hits it with t in (0, r->tmax). */
int bvh_triangle_hit(vec3 a, vec3 b, vec3 c, const ray *r, hit *h);
/* The instruction set of the traversal: on x86-64 it is compiled for SSE2, AVX2 + FMA and AVX-512,
 * and each tree built uses the best one this CPU runs, or the one bvh_isa_force named (call it
 * before building any tree). Every one gives the same hits. bvh_isa: the name of the one in use;
 * bvh_isa_names: every name compiled in ("avx512, avx2, sse2", with "(not on this CPU)" where it
 * applies); bvh_isa_force: 0, -1 if no such name, -2 if this CPU cannot run it (NULL: back to the best). */
const char *bvh_isa(void);
void bvh_isa_names(char *dst, size_t cap);
int bvh_isa_force(const char *name);
/* Node and leaf counts and depth, for the tests (test_bvh). */
void bvh_stats(const bvh *b, int *nodes, int *leaves, int *depth);
#endif
