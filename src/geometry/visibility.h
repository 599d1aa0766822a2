/* visibility.h — pairs of triangles that see each other wholly: V(p, s) = 1 for every point p of a
 * triangle A and every point s of an emitter E, because a plane separates each other triangle from
 * them (its own, A's, E's, or one of a separating-axis test: visibility.c). A shadow ray between
 * such a pair cannot be blocked, so it need not be traced: in an empty box every wall sees every
 * light so. Found once per scene, quadratic in the triangles: only for scenes of at most
 * VISIBILITY_MAX_TRIS triangles (others get no table, and every shadow ray). */
#ifndef PATHLAB_VISIBILITY_H
#define PATHLAB_VISIBILITY_H
#include "geometry/bvh.h"
#include "math/vec.h"
#include <stddef.h>

#define VISIBILITY_MAX_TRIS 1024

typedef struct {
    unsigned char *bits;   /* bit t * nemitters + e: triangle t and emitter e see each other wholly;
                              NULL: no table (too many triangles, or no emitter) */
    int nemitters;
    long npairs;           /* how many such pairs */
} pair_visibility;

/* Finds the pairs between the ntris triangles (corners P[tri[3 t + k]]) and the nemitters emitters,
 * emitter e being triangle emitter_tri[e]. 0 on success (also when the scene is too big: no pairs),
 * 1 when out of memory. */
int pair_visibility_build(pair_visibility *pv, const vec3 *P, const int *tri, int ntris, const int *emitter_tri, int nemitters);
void pair_visibility_free(pair_visibility *pv);

/* near[e] = 1 for each emitter e (triangle emitter_tri[e]) that another triangle of the bvh b may
 * stand in front of within twice the offset offset_ray_origin gives its points: a shadow ray ending
 * just off such an emitter would pass between them (a plate 0.5 mm under a lamp at coordinates near
 * 1000, where the offset is 1 mm). Conservative: by the triangles' boxes, and any corner in front
 * of the emitter's plane by more than 2^-20 of its size (its neighbours in its plane do not count). */
void near_blockers_find(unsigned char *near, const bvh *b, const vec3 *P, const int *tri, const int *emitter_tri, int nemitters);

/* 1 if nothing can block a segment from triangle t to emitter e (p offset off its triangle by
 * offset_ray_origin, s on the emitter or offset off it, as shadow rays are). */
static inline int sees_wholly(const pair_visibility *pv, int t, int e)
{
    size_t i = (size_t)t * (size_t)pv->nemitters + (size_t)e;
    return pv->bits && (pv->bits[i >> 3] >> (i & 7) & 1);   /* no table: every ray is traced */
}
#endif
