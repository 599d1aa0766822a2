/* ray.c — ray origins off the surface they leave.
 *
 * The hit point p = a + u (b - a) + v (c - a) is off the triangle's plane by a few ulps of the
 * triangle's coordinates, and the next ray-triangle test decides on which side of that plane the
 * origin is with an error of a few ulps of them too (its products mix every coordinate): so p moves
 * along n by OFFSET_ULPS ulps of the triangle's largest |coordinate|, `scale`. Not by ulps of each
 * coordinate of p (Waechter and Binder, Ray Tracing Gems ch. 6): on the wall x = 0 of a box 1e3
 * wide that gives p.x + 1.5e-5 where the test errs by ulps of 1e3 (make stress: -5.6% of the
 * furnace's light); nor by ulps of |p|: a point near the origin on a plane 20 wide would get less
 * than the plane's own rounding. 16 ulps (make stress): 1 and 4 still lose light (sliver wall,
 * grazing light), 64 and 256 (Waechter and Binder's) move contact shadows 1e6 from the origin,
 * where one ulp is 1/16. */
#include "geometry/ray.h"
#include <float.h>

#define OFFSET_ULPS 16.0f

vec3 offset_ray_origin(vec3 p, vec3 n, float scale)
{
    /* >= 16/sqrt(3) ulps of the coordinate along n's largest component: the addition keeps the move */
    float d = OFFSET_ULPS * ldexpf(1.0f, ilogbf(fmaxf(scale, FLT_MIN)) - 23);
    return v3_madd(p, n, d);
}

float triangle_scale(vec3 a, vec3 b, vec3 c)
{
    vec3 m = v3_max(v3_max(v3(fabsf(a.x), fabsf(a.y), fabsf(a.z)), v3(fabsf(b.x), fabsf(b.y), fabsf(b.z))),
                    v3(fabsf(c.x), fabsf(c.y), fabsf(c.z)));
    return v3_max_comp(m);
}
