/* sampling.h — warps from uniform numbers u in [0,1)^2 to directions and points, each beside its
 * pdf. Directions are in the local frame where the normal is +z, so cos(theta) = z.
 * Solid-angle pdfs are per steradian; area pdfs are per unit area. */
#ifndef PATHLAB_SAMPLING_H
#define PATHLAB_SAMPLING_H
#include "math/vec.h"

/* Uniform over the hemisphere z > 0; pdf = 1/(2 pi) per steradian. */
vec3 sample_uniform_hemisphere(float u1, float u2);
float pdf_uniform_hemisphere(vec3 w);

/* Cosine-weighted hemisphere; pdf = cos(theta)/pi per steradian. */
vec3 sample_cosine_hemisphere(float u1, float u2);
float pdf_cosine_hemisphere(vec3 w);

/* Direction about +z with density (m+1)/(2 pi) cos^m(theta) per steradian, by
 * cos(theta) = u^(1/(m+1)) (the slides' GI Compendium eq. 36). Used for the Blinn half vector. */
vec3 sample_cos_power(float u1, float u2, float m);
float pdf_cos_power(vec3 w, float m);

/* Uniform point on triangle (a, b, c) as barycentrics (b1, b2) of b and c; pdf = 1/area. */
void sample_uniform_triangle(float u1, float u2, float *b1, float *b2);

/* Power heuristic with beta = 2 and balance heuristic: MIS weight of the strategy with density pf
 * against one with density pg (both in the same measure, one sample each). */
static inline float power_heuristic(float pf, float pg)
{
    float r = pg / pf;   /* as a ratio, so that pf^2 cannot overflow; pf = 0 gives weight 0 */
    return pf > 0.0f ? 1.0f / (1.0f + r * r) : 0.0f;
}
static inline float balance_heuristic(float pf, float pg) { return pf > 0.0f ? 1.0f / (1.0f + pg / pf) : 0.0f; }
#endif
