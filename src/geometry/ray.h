/* ray.h — the ray and the hit record that every ray query uses, and where a ray leaving a surface
 * starts (pbrt: ray.h; the acceleration structure is bvh.h).
 *   ray  the points o + t d for 0 < t < tmax;   hit  the closest one found: t, tri, barycentrics.
 *   offset_ray_origin moves a hit point off its triangle so that the next ray does not hit the
 *   triangle again ("acne"). The move is scaled to the triangle (triangle_scale, its largest
 *   |coordinate|), not to the point: the ray-triangle test errs by ulps of the triangle's own
 *   coordinates, so a point near the origin on a triangle far from it needs the triangle's ulps. */
#ifndef PATHLAB_RAY_H
#define PATHLAB_RAY_H
#include "math/vec.h"

typedef struct { vec3 o, d; float tmax; } ray;      /* points o + t d for 0 < t < tmax */
typedef struct { float t, u, v; int tri; } hit;     /* tri = -1: no hit; u, v barycentrics of corners 1, 2 */

/* Offsets p (a point of a triangle) along its geometric normal n by a few ulps of `scale`, the
 * triangle's largest |coordinate| (triangle_scale), so that a ray leaving p does not hit the
 * triangle again. n must point to the side the ray leaves to. */
vec3 offset_ray_origin(vec3 p, vec3 n, float scale);
/* The largest |coordinate| of the corners a, b, c: the `scale` of offset_ray_origin. */
float triangle_scale(vec3 a, vec3 b, vec3 c);
#endif
