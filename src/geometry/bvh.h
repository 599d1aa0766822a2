/* bvh.h — bounding volume hierarchy over triangles: build with binned SAH, trace rays.
 * bvh_intersect finds the closest hit, bvh_occluded stops at the first hit (shadow rays).
 * The ray-triangle test is watertight (Woop, Benthin, Wald 2013): a ray through a shared edge or
 * vertex of a closed mesh hits at least one of the triangles. */
#ifndef PATHLAB_BVH_H
#define PATHLAB_BVH_H
#include "geometry/ray.h"

typedef struct bvh bvh;

/* Builds over ntris triangles with corners P[tri[3i+k]], using up to `threads` threads.
 * Returns NULL on allocation failure. The bvh keeps its own copy of what it needs. */
bvh *bvh_build(const vec3 *P, const int *tri, int ntris, int threads);
void bvh_free(bvh *b);
/* Closest hit with t in (0, r->tmax); returns 1 and fills h on a hit, else 0 (h->tri = -1). */
int bvh_intersect(const bvh *b, const ray *r, hit *h);
/* 1 if any triangle is hit with t in (0, r->tmax). */
int bvh_occluded(const bvh *b, const ray *r);
/* The bvh's ray-triangle test on one triangle (a, b, c), for reference and tests: returns 1 and
 * fills h->t, h->u, h->v (not h->tri) when the ray hits it with t in (0, r->tmax). */
int bvh_triangle_hit(vec3 a, vec3 b, vec3 c, const ray *r, hit *h);
/* Node and leaf counts and depth, for the tests (test_bvh). */
void bvh_stats(const bvh *b, int *nodes, int *leaves, int *depth);
#endif
