/* case.h — what a case of `pathlab check-sampling` is, and what running it finds.
 * A case draws N samples from one sampling routine of pathlab and checks that
 *   1. the counts in cells match N times the pdf integrated over each cell (chi-square);
 *   2. the pdf integrates to 1 (or to the chance of a sample above the surface);
 *   3. the pdf a sampler returns is the pdf function's value there, and the pdf function is the
 *      course's formula (in double); samples are where they should be (unit, above, on the triangle).
 * The routines under test are function pointers, so that a test can swap in a broken one. A case's
 * samples come from the streams of one seed (case_stream): the result does not depend on threads. */
#ifndef PATHLAB_CHECK_CASE_H
#define PATHLAB_CHECK_CASE_H
#include <stdint.h>
#include "check/light_scene.h"
#include "math/rng.h"
#include "stats/chi2.h"
#include "tracer/brdf.h"
#include "tracer/light.h"
#include "tracer/sky.h"

typedef enum { CASE_WARP, CASE_TRIANGLE, CASE_BRDF, CASE_LIGHT_CHOICE, CASE_LIGHT_POINT, CASE_SKY } sampling_case_kind;

typedef struct {                 /* a warp of sampling.c: a direction about +z */
    vec3 (*sample)(float u1, float u2, float m);
    float (*pdf)(vec3 w, float m);
    double (*formula)(double cos_theta, double m);   /* the course's pdf per steradian, in double */
    float m;                                         /* the exponent of cos_power */
} warp_routine;

typedef struct { void (*sample)(float u1, float u2, float *b1, float *b2); } triangle_routine;

typedef struct {                 /* brdf_sample and its pdf, for one material and one wo */
    vec3 (*sample)(const material *m, vec3 wo, float u_lobe, float u1, float u2, float *pdf);
    float (*pdf)(const material *m, vec3 wo, vec3 wi);
    material mat;
    float theta_deg, phi_o;      /* wo = (sin cos phi_o, sin sin phi_o, cos) of theta_deg */
    int wi_integral;             /* also integrate the pdf in the wi domain itself (slower) */
} brdf_routine;

typedef struct {                 /* light_sample_point and light_pdf_area in a test scene, from p of normal n */
    void (*sample)(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out);
    float (*pdf)(const light_set *ls, light_strategy st, int i, vec3 p, vec3 n, vec3 s);
    light_strategy st;
    light_scene_id scene;
    vec3 p, n;                   /* n = (0, 0, 0): a bare point, lit from every side */
    int grid;                    /* CASE_LIGHT_POINT: grid^2 cells per emitter */
} light_routine;

typedef struct {                 /* sky_sample and sky_pdf_sa on the test sky of w x h pixels (sky_check.h) */
    vec3 (*sample)(const sky *s, double u1, float u2, float *pdf_sa, vec3 *L);
    float (*pdf)(const sky *s, vec3 w);
    int w, h;                    /* 1 x 1: the constant sky */
} sky_routine;

typedef struct {                 /* the routine of `kind` is the one used */
    sampling_case_kind kind;
    char name[80];
    double share;                /* of N drawn by this case (the BRDF cases: 1/2) */
    warp_routine warp;
    triangle_routine triangle;
    brdf_routine brdf;
    light_routine light;
    sky_routine sky;
} sampling_case;

typedef struct {
    char routine[80];
    char cells[96];                   /* how the samples were binned */
    long n;                           /* samples in the chi-square test */
    chi2_result chi2;
    double discarded;                 /* of them, with no direction (below the surface) */
    int nintegrals;                   /* 0 to 3 integrals of the pdf, and what they should be */
    double integral[3], integral_want[3];
    const char *integral_what[3];
    long pdf_checked, pdf_mismatch;   /* samples whose returned pdf is not the pdf function's */
    int has_formula;                  /* the pdf function against the course's formula in double: */
    double formula_gap, formula_tol;  /* worst relative gap, and the rounding allowed */
    int has_geom;                     /* samples where they should be: */
    double geom_gap, geom_tol;        /* worst | |w| - 1 | or distance out of the triangle */
    long outside;                     /* samples out of their domain (below, off the triangle) */
} sampling_result;

/* Stream k of a case's seed: 0 the chi-square samples, 1 the pilot sample, 2 the spot checks. */
static inline pcg32 case_stream(uint64_t seed, int k)
{
    pcg32 r;
    pcg32_init(&r, seed + SPLITMIX64_GAMMA * (uint64_t)k, (uint64_t)k);
    return r;
}
#endif
