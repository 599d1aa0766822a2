/* check_sampling.h — `pathlab check-sampling`: every sampling routine of pathlab against its pdf.
 * A case draws N samples from one routine and checks that
 *   1. the counts in cells match N times the pdf integrated over each cell (chi-square; cells
 *      expected under 5 pooled; alpha = 0.01 over all the cases, Sidak-corrected);
 *   2. the pdf integrates to 1 (or to the chance of a sample above the surface), to 1e-3;
 *   3. the pdf a sampler returns is the pdf function's value there, and the pdf function is the
 *      course's formula (in double); samples are where they should be (unit, above, on the triangle).
 * The routines under test are function pointers, pathlab's own in check_sampling_cases():
 * tests/test_chi2_power.c swaps in broken ones and requires the checks to catch them.
 * Files: check_sampling.c (the command, its table), check_sampling_cases.c (the list, threads,
 * verdicts), check_sampling_{warps,brdf,lights}.c (the cases), on chi2.h (the statistic),
 * chi2_sphere.h and chi2_triangle.h (cells and quadrature), arvo.h (spherical-triangle cells). */
#ifndef PATHLAB_CHECK_SAMPLING_H
#define PATHLAB_CHECK_SAMPLING_H
#include <stdint.h>
#include "tracer/brdf.h"
#include "stats/chi2.h"
#include "tracer/light.h"
#include "math/rng.h"

#define CHECK_ALPHA 0.01          /* family-wise level of the chi-square tests */
#define CHECK_INTEGRAL_TOL 1e-3
#define CHECK_MAX_CASES 64

typedef enum { CASE_WARP, CASE_TRIANGLE, CASE_BRDF, CASE_LIGHT_CHOICE, CASE_LIGHT_POINT } sampling_case_kind;

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

enum { LIGHT_SCENE_FIVE, LIGHT_SCENE_ONE };
typedef struct {                 /* light_sample_point and light_pdf_area in a test scene, from p */
    void (*sample)(const light_set *ls, light_strategy st, vec3 p, double u0, float u1, float u2, light_sample *out);
    float (*pdf)(const light_set *ls, light_strategy st, int i, vec3 p, vec3 s);
    light_strategy st;
    int scene;                   /* LIGHT_SCENE_FIVE: five emitters and a wall; ONE: one triangle */
    vec3 p;
    int grid;                    /* CASE_LIGHT_POINT: grid^2 cells per emitter */
} light_routine;

typedef struct {
    sampling_case_kind kind;
    char name[80];
    double share;                /* of N drawn by this case (the BRDF cases: 1/2) */
    warp_routine warp;
    triangle_routine triangle;
    brdf_routine brdf;
    light_routine light;
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

/* The cases of check-sampling, with pathlab's routines; returns how many (at most max). */
int check_sampling_cases(sampling_case *cases, int max);
/* The test materials: Kd tinted (kd, 0.8 kd, 0.6 kd) so that the lobes' mixture is not grey, Ks grey. */
material check_sampling_material(float kd, float ks, float Ns);
/* Runs one case with n samples (times its share) from the streams of seed. */
void check_sampling_run(const sampling_case *c, long n, uint64_t seed, sampling_result *r);
/* Runs them all on up to `threads` threads; case i uses a seed made of (seed, i). */
void check_sampling_run_all(const sampling_case *c, int ncases, long n, uint64_t seed, int threads, sampling_result *r);
/* The verdicts: the chi-square at level alpha_case, integral k, the pdfs (returned = function =
 * formula), the samples (where they should be), and all of them. */
int sampling_chi2_pass(const sampling_result *r, double alpha_case);
int sampling_integral_pass(const sampling_result *r, int k);
int sampling_pdf_pass(const sampling_result *r);
int sampling_samples_pass(const sampling_result *r);
int sampling_result_pass(const sampling_result *r, double alpha_case);
/* argv[0] = "check-sampling". Prints the table; 0 when every case passes, 1 if one fails, 2 on a usage error. */
int check_sampling_main(int argc, char **argv);

/* The case runners (check_sampling_warps.c, _brdf.c, _lights.c). */
void check_warp(const warp_routine *w, long n, uint64_t seed, sampling_result *r);
void check_triangle(const triangle_routine *t, long n, uint64_t seed, sampling_result *r);
void check_brdf(const brdf_routine *b, long n, uint64_t seed, sampling_result *r);
void check_light_choice(const light_routine *l, long n, uint64_t seed, sampling_result *r);
void check_light_point(const light_routine *l, long n, uint64_t seed, sampling_result *r);

/* The light test scenes: LIGHT_SCENE_FIVE, five emitters of different areas, colours and sides, and a
 * wall that does not emit; LIGHT_SCENE_ONE, the emitter (0,0,0) (1,0,0) (0.3,0.8,0). */
#define LIGHT_SCENE_MAX 6
typedef struct {
    vec3 P[3 * LIGHT_SCENE_MAX], Ng[LIGHT_SCENE_MAX];
    float area[LIGHT_SCENE_MAX];
    int tri[3 * LIGHT_SCENE_MAX], tri_mat[LIGHT_SCENE_MAX];
    material mats[LIGHT_SCENE_MAX];
    mesh m;
    light_set ls;
} light_scene;
/* Builds the scene in place (m points into s); 0 on success. */
int light_scene_build(light_scene *s, int which);
void light_scene_free(light_scene *s);

/* Stream k of a case's seed: 0 the chi-square samples, 1 the pilot sample, 2 the spot checks. */
static inline pcg32 check_stream(uint64_t seed, int k)
{
    pcg32 r;
    pcg32_init(&r, seed + 0x9E3779B97F4A7C15ULL * (uint64_t)k, (uint64_t)k);
    return r;
}
#endif
