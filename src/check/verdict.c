/* verdict.c — the pass/fail rules of a case's result (verdict.h). */
#include "check/verdict.h"
#include <math.h>

int sampling_chi2_pass(const sampling_result *r, double alpha_case) { return r->chi2.p >= alpha_case; }

int sampling_integral_pass(const sampling_result *r, int k)
{
    return fabs(r->integral[k] - r->integral_want[k]) < CHECK_INTEGRAL_TOL;
}

int sampling_pdf_pass(const sampling_result *r)
{
    return r->pdf_mismatch == 0 && (!r->has_formula || r->formula_gap <= r->formula_tol);
}

int sampling_samples_pass(const sampling_result *r) { return r->outside == 0 && (!r->has_geom || r->geom_gap <= r->geom_tol); }

int sampling_result_pass(const sampling_result *r, double alpha_case)
{
    int k, ok = sampling_chi2_pass(r, alpha_case) && sampling_pdf_pass(r) && sampling_samples_pass(r);
    for (k = 0; k < r->nintegrals; k++) ok &= sampling_integral_pass(r, k);
    return ok;
}
