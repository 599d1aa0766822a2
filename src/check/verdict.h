/* verdict.h — the pass/fail rules of a case's result (case.h). The chi-square of each case is
 * judged at the level alpha_case that makes all of them pass together with probability
 * 1 - CHECK_ALPHA: sidak_level(CHECK_ALPHA, number of cases) (stats/significance.h). */
#ifndef PATHLAB_CHECK_VERDICT_H
#define PATHLAB_CHECK_VERDICT_H
#include "check/case.h"

#define CHECK_ALPHA 0.01          /* family-wise level of the chi-square tests of all the cases */
#define CHECK_INTEGRAL_TOL 1e-3   /* absolute, on an integral of the pdf */

/* The chi-square's p-value is at least alpha_case (the level of one case). */
int sampling_chi2_pass(const sampling_result *r, double alpha_case);
/* Integral k of the pdf is its integral_want[k], to CHECK_INTEGRAL_TOL. */
int sampling_integral_pass(const sampling_result *r, int k);
/* Every pdf returned is the pdf function's, which is the course's formula up to formula_tol. */
int sampling_pdf_pass(const sampling_result *r);
/* No sample out of its domain, none farther than geom_tol from where it belongs. */
int sampling_samples_pass(const sampling_result *r);
/* All of the above, for every integral. */
int sampling_result_pass(const sampling_result *r, double alpha_case);
#endif
