/* sampling.c — the warps of sampling.h. Each sampler is checked against its pdf by the
 * chi-square tests of tests/test_sampling.c. */
#include "tracer/sampling.h"

vec3 sample_uniform_hemisphere(float u1, float u2)
{
    /* z = 1 - u1 lies in (0, 1]: z = u1 could be 0, a direction on the horizon of pdf 0 */
    float z = 1.0f - u1, r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = 2.0f * PI_F * u2;
    return v3(r * cosf(phi), r * sinf(phi), z);
}

float pdf_uniform_hemisphere(vec3 w) { return w.z > 0.0f ? 0.5f * INV_PI_F : 0.0f; }

/* Malley's method: a uniform point on the unit disk lifted to the hemisphere. */
vec3 sample_cosine_hemisphere(float u1, float u2)
{
    float r = sqrtf(u1), phi = 2.0f * PI_F * u2;
    return v3(r * cosf(phi), r * sinf(phi), sqrtf(fmaxf(0.0f, 1.0f - u1)));
}

float pdf_cosine_hemisphere(vec3 w) { return w.z > 0.0f ? w.z * INV_PI_F : 0.0f; }

vec3 sample_cos_power(float u1, float u2, float m)
{
    /* 1 - u lies in (0, 1], so cos(theta) > 0 even for huge m */
    float z = powf(1.0f - u1, 1.0f / (m + 1.0f));
    float r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = 2.0f * PI_F * u2;
    return v3(r * cosf(phi), r * sinf(phi), z);
}

float pdf_cos_power(vec3 w, float m)
{
    return w.z > 0.0f ? (m + 1.0f) * 0.5f * INV_PI_F * powf(w.z, m) : 0.0f;
}

/* sqrt(u1) spreads samples toward the far edge (b, c) as the triangle widens there, which keeps
 * the density uniform in area; the weight of corner a is 1 - b1 - b2 = 1 - sqrt(u1). */
void sample_uniform_triangle(float u1, float u2, float *b1, float *b2)
{
    float s = sqrtf(u1);
    *b1 = s * (1.0f - u2);
    *b2 = s * u2;
}
