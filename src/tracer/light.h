/* light.h — choosing a point s on the emitters (the course's pdf1(s)).
 * Emitters are the triangles whose material has Ke != 0; they emit Le = Ke on their front face only.
 * Strategies (--light): area = uniform over the total emitting area (pdf = 1/A); triangle = a
 * triangle chosen uniformly, then a uniform point on it; power = a triangle chosen in proportion to
 * area x luminance(Ke), then a uniform point on it; solid-angle = a triangle chosen as for power,
 * then a direction uniform over the spherical triangle it subtends from the shading point p
 * (Arvo 1995), so that its pdf is 1/Omega per steradian; tree = a triangle chosen by descending a
 * tree of the emitters, each node weighed by what it can send toward p (light_tree.h), then a
 * uniform point on it: the emitters that do not matter at p are seldom or never chosen.
 * Measures: pdf1 is returned per unit area (pdf_area) whatever the strategy. Seen from p at
 * distance d, with theta_s the angle at s between its normal and the direction to p, the density
 * per steradian is pdf_sa = pdf_area d^2 / cos(theta_s) (pdf_area_to_solid_angle), and back,
 * pdf_area = pdf_sa cos(theta_s) / d^2 (pdf_solid_angle_to_area). */
#ifndef PATHLAB_LIGHT_H
#define PATHLAB_LIGHT_H
#include "scene/mesh.h"
#include "tracer/light_tree.h"

/* solid-angle uses Arvo's map only for spherical triangles of Omega in (MIN, MAX) steradians, where
 * its trigonometry is accurate; outside, that triangle is sampled uniformly by area. */
#define LIGHT_SOLID_ANGLE_MIN 3e-4
#define LIGHT_SOLID_ANGLE_MAX 6.0

typedef enum { LIGHT_AREA, LIGHT_TRIANGLE, LIGHT_POWER, LIGHT_SOLID_ANGLE, LIGHT_TREE, LIGHT_NSTRATEGIES } light_strategy;
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
    light_tree tree;                 /* tree's (built when there are emitters) */
} light_set;

typedef struct {
    vec3 pos, n, Le;    /* s, the point on the emitter, its front normal, emitted radiance toward n's side */
    float pdf_area;     /* pdf1(s) per unit area */
    int emitter;
} light_sample;

/* Collects the emitters of m (with unit normals Ng and areas of its triangles); 0 on success. */
int light_build(light_set *ls, const mesh *m, const vec3 *Ng, const float *area);
void light_free(light_set *ls);
/* Samples s seen from the shading point p of normal n (the side it is lit from; (0, 0, 0): none,
 * which only --light tree reads, to skip the emitters under p's surface): u0 (53 random bits, see
 * pcg32_double53) chooses the emitter, u1, u2 the point on it (the form the checks of check/
 * sample and test). */
void light_sample_point(const light_set *ls, light_strategy strategy, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out);
/* The same from two numbers: u0 chooses the emitter and where it fell in the emitter's share of
 * [0, 1) is the point's first coordinate, u2 its second. Conditional on the choice that remainder
 * is uniform and independent of u2, so it samples the same density; but a stratified (u0, u2) set
 * stays stratified over all the emitters together, where an emitter chosen by a number of its own
 * would receive a random subset of the points. What the integrator uses, whatever the sampler. */
void light_sample_point_joint(const light_set *ls, light_strategy strategy, vec3 p, vec3 n, double u0, float u2, light_sample *out);
/* pdf1(s) per unit area of the point s on emitter i, chosen from p of normal n under that strategy. */
float light_pdf_area(const light_set *ls, light_strategy strategy, int i, vec3 p, vec3 n, vec3 s);
/* A density per unit area at a point seen at squared distance dist2 under cosine cos_s, made one
 * per steradian (0 when the point is seen edge-on or from behind). */
static inline float pdf_area_to_solid_angle(float pdf_area, float dist2, float cos_s)
{
    return cos_s > 0.0f ? pdf_area * dist2 / cos_s : 0.0f;
}
/* The converse: a density per steradian made one per unit area at that point. */
static inline float pdf_solid_angle_to_area(float pdf_sa, float dist2, float cos_s) { return pdf_sa * cos_s / dist2; }
#endif
