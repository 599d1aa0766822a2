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
#include <stdint.h>
#include <string.h>

#define OFFSET_ULPS 16.0f

/* The power of two 2^floor(log2 s) for s >= FLT_MIN: s with its mantissa bits cleared. The same
 * value as ldexpf(1, ilogbf(s)), without two calls into libm per ray (profile: 6 % of a render). */
static float exponent_of(float s)
{
    uint32_t u;
    memcpy(&u, &s, sizeof u);
    u &= 0x7f800000u;
    memcpy(&s, &u, sizeof s);
    return s;
}

vec3 offset_ray_origin(vec3 p, vec3 n, float scale)
{
    /* >= 16/sqrt(3) ulps of the coordinate along n's largest component: the addition keeps the move.
     * A NaN scale fails the comparison and gets FLT_MIN, as fmaxf would give it. */
    float s = scale > FLT_MIN ? scale : FLT_MIN;
    float d = OFFSET_ULPS * (exponent_of(s) * 0x1p-23f);   /* 2^-23 of a power of two: exact */
    return v3_madd(p, n, d);
}

/* ?: rather than fmaxf, which GCC calls in libm (it must honour NaN without -ffinite-math-only). */
static float max_abs3(vec3 a, float m)
{
    float x = fabsf(a.x), y = fabsf(a.y), z = fabsf(a.z);
    m = x > m ? x : m;
    m = y > m ? y : m;
    return z > m ? z : m;
}

float triangle_scale(vec3 a, vec3 b, vec3 c)
{
    return max_abs3(c, max_abs3(b, max_abs3(a, 0.0f)));
}
