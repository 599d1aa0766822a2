/* student_check.h — the checks of a student's directions (sample_file.h) against the density they
 * claim (student_pdf.h), for `pathlab check-sampler`:
 *   0. domain: no direction below the surface when the density lives on z > 0 (blinn excepted:
 *      its reflections below the surface are expected, in their own chi-square cell);
 *   1. chi-square of the directions against the density (chi2_sphere.h's cells, their rings placed
 *      by a reference sampler), and the lobe's exponent K fitted from the mean cosine;
 *   2. the density integrates to 1 (pathlab's formula, by quadrature) and, with a pdf column, the
 *      column is the density of the directions: mean(named / column) = the named density's mass
 *      on the hemisphere (1, blinn: P(above)), within its standard error (importance sampling);
 *      mean(1 / column) over z > 0 = 2 pi (4 pi on the sphere) is reported, not judged (1/pdf has
 *      an infinite variance for cos^M lobes, M >= 1);
 *   3. the column equals the named density at every direction, to the digits a %g file keeps.
 * The diagnoses of failures are in student_diagnosis.h. */
#ifndef PATHLAB_STUDENT_CHECK_H
#define PATHLAB_STUDENT_CHECK_H
#include "check/sample_file.h"
#include "check/student_pdf.h"

#define STUDENT_MIN_SAMPLES 2000      /* fewer: under 5 expected in each of the 320 cells, they pool into few */
#define STUDENT_INTEGRAL_TOL 1e-3     /* absolute, on the quadrature of the named density */
#define STUDENT_NORM_TOL 1e-3         /* added to the z-test of the column's normalisation */

typedef struct {
    long n;                    /* samples in the file */
    double alpha, alpha_each;  /* family-wise level, and each statistical test's (Sidak) */
    /* 0. domain */
    long below, first_below;   /* directions with z < 0 (z = 0 is on the surface), and the first one's line */
    int below_allowed;         /* uniform: the sphere; blinn: the reflections below are a cell */
    double below_expected;     /* blinn: n P(reflection below the surface) */
    /* 1. chi-square */
    sphere_chi2 chi2;
    double K, K_se;            /* the lobe cos^K fitted from the mean cosine (K < 0: none) */
    double theta_p;            /* chi-square p-value of "uniform in theta" (-1: not tried) */
    /* 2. integrals */
    double integral;           /* the named density over its domain, want 1 */
    double binned_mass;        /* P(a sample is binned): blinn P(above), else 1 */
    double norm, norm_se;      /* mean(named / column): want binned_mass */
    double inv, inv_se;        /* mean(1 / column) over the measure's domain: want the measure */
    double measure;            /* 2 pi or 4 pi */
    long zero_pdf;             /* column 0 where the named density is not */
    /* 3. the column against the named density */
    long ratio_n, ratio_bad, worst_line;   /* compared, off by more than their tolerance, the worst */
    double ratio_min, ratio_max, ratio_median, worst_col, worst_named;
} student_report;

/* Runs every check (the pilot of the chi-square from seed); 0, or 1 when out of memory. */
int student_check_run(const sample_file *s, const student_pdf *p, double alpha, uint64_t seed, student_report *r);

/* The verdicts (1 = pass). */
int student_domain_pass(const student_report *r);
int student_chi2_pass(const student_report *r);
int student_integral_pass(const student_report *r);
int student_norm_pass(const student_report *r);
int student_ratio_pass(const student_report *r);
/* The ratio's tolerance at a sample: 1e-3, widened by what 6 printed digits of the direction move
 * the density (cos^M: M 2e-6 / cos; blinn: also 2e-6 / (wo.h)). */
double student_ratio_tol(const student_pdf *p, dvec w);
#endif
