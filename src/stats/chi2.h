/* chi2.h — Pearson's chi-square goodness-of-fit test, as the sampling checks use it: counts of
 * samples in cells against the counts the pdf predicts (N times its integral over each cell), the
 * cells with an expected count under 5 pooled, and the p-value from the chi-square distribution.
 * Over several cases, Sidak's correction keeps the chance of any false alarm at alpha. */
#ifndef PATHLAB_CHI2_H
#define PATHLAB_CHI2_H

typedef struct {
    double chi2;             /* sum over the cells of (observed - expected)^2 / expected */
    int dof;                 /* degrees of freedom: cells left after pooling, minus 1 */
    double p;                /* P(a chi-square with dof degrees >= chi2): tiny = sampler and pdf disagree */
    double expected_total;   /* sum of the expected counts: N when the pdf integrates to 1 */
} chi2_result;

/* P-value of the statistic chi2 with dof degrees of freedom: Q(dof/2, chi2/2); 0 for dof < 1. */
double chi2_pvalue(double chi2, int dof);
/* The test on n cells. Cells expected under 5 are pooled into one; if the pool itself stays under 5,
 * it joins the largest cell. Observed samples where nothing is expected make chi2 infinite (p = 0). */
chi2_result chi2_test(const double *observed, const double *expected, int n);
#endif
