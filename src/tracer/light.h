/* light.h — choosing a point s on the emitters (the course's pdf1(s)).
 * Emitters are the triangles whose material has Ke != 0; they emit Le = Ke on their front face only.
 * Strategies (--light): area = uniform over the total emitting area (pdf = 1/A); triangle = a
 * triangle chosen uniformly, then a uniform point on it; power = a triangle chosen in proportion to
 * area x luminance(Ke), then a uniform point on it; solid-angle = a triangle chosen as for power,
 * then a direction uniform over the spherical triangle it subtends from the shading point p
 * (Arvo 1995), so that its pdf is 1/Omega per steradian. Pdfs are returned per unit area;
 * pdf_area_to_solid_angle converts: pdf_w = pdf_A d^2 / cos(theta_s). */
#ifndef PATHLAB_LIGHT_H
#define PATHLAB_LIGHT_H
#include "scene/mesh.h"

/* solid-angle uses Arvo's map only for spherical triangles of Omega in (MIN, MAX) steradians, where
 * its trigonometry is accurate; outside, that triangle is sampled uniformly by area. */
#define LIGHT_SOLID_ANGLE_MIN 3e-4
#define LIGHT_SOLID_ANGLE_MAX 6.0

typedef enum { LIGHT_AREA, LIGHT_TRIANGLE, LIGHT_POWER, LIGHT_SOLID_ANGLE, LIGHT_NSTRATEGIES } light_strategy;
/* Their names on the command line (--light), in enum order, NULL-terminated. */
extern const char *const LIGHT_STRATEGY_NAMES[];

typedef struct { vec3 a, e1, e2, n, Le; float area; int tri; } emitter;   /* corners a, a+e1, a+e2 */

typedef struct {
    emitter *e;
    int n;
    float total_area;
    double *cdf[LIGHT_NSTRATEGIES];  /* cumulative probability of choosing emitters 0..i (double:
                                      * a float cdf would quantise the probabilities to 2^-24) */
    int *emitter_of_tri;             /* mesh triangle -> emitter index, or -1 */
} light_set;

typedef struct {
    vec3 p, n, Le;      /* point on the emitter, its front normal, emitted radiance toward n's side */
    float pdf_area;     /* pdf1(s) per unit area */
    int emitter;
} light_sample;

/* Collects the emitters of m (with unit normals Ng and areas of its triangles); 0 on success. */
int light_build(light_set *ls, const mesh *m, const vec3 *Ng, const float *area);
void light_free(light_set *ls);
/* Samples s seen from the shading point p: u0 (32 random bits, see pcg32_double) chooses the
 * emitter, u1, u2 the point on it. */
void light_sample_point(const light_set *ls, light_strategy st, vec3 p, double u0, float u1, float u2, light_sample *out);
/* pdf1(s) per unit area of the point s on emitter i, chosen from p under strategy st. */
float light_pdf_area(const light_set *ls, light_strategy st, int i, vec3 p, vec3 s);
/* The probability of choosing emitter i (before the point on it). */
float light_choice_prob(const light_set *ls, light_strategy st, int i);
/* Converts an area pdf at a point seen at distance^2 dist2 and cosine cos_s into a solid-angle pdf. */
static inline float pdf_area_to_solid_angle(float pdf_area, float dist2, float cos_s)
{
    return cos_s > 0.0f ? pdf_area * dist2 / cos_s : 0.0f;
}
#endif
