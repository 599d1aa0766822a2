/* chi2.c — the chi-square distribution and the pooled statistic of chi2.h. */
#include "stats/chi2.h"
#include <math.h>
#include "math/vec.h"

#define GAMMA_EPS 1e-15
#define GAMMA_MAX_ITER 100000
#define POOL_BELOW 5.0   /* the classical rule: each cell of the statistic expects at least 5 */

/* ln Gamma(x), x > 0, by Lanczos' approximation (g = 7, 9 terms; relative error ~1e-15). Not libm's
 * lgamma: it writes the global signgam, a data race when cases run on threads. */
static double log_gamma(double x)
{
    static const double c[9] = {0.99999999999980993,  676.5203681218851,     -1259.1392167224028,
                                771.32342877765313,   -176.61502916214059,   12.507343278686905,
                                -0.13857109526572012, 9.9843695780195716e-6, 1.5056327351493116e-7};
    double sum = c[0], t;
    int i;
    if (x < 0.5) return log(PI / sin(PI * x)) - log_gamma(1.0 - x);   /* reflection */
    x -= 1.0;
    for (i = 1; i < 9; i++) sum += c[i] / (x + i);
    t = x + 7.5;
    return 0.5 * log(2.0 * PI) + (x + 0.5) * log(t) - t + log(sum);
}

/* Q(a, x) for x < a + 1 from the power series of P = 1 - Q (Numerical Recipes 6.2). */
static double gamma_q_series(double a, double x, double lead)
{
    double term = 1.0 / a, sum = term;
    int n;
    for (n = 1; n < GAMMA_MAX_ITER && fabs(term) > GAMMA_EPS * fabs(sum); n++) {
        term *= x / (a + n);
        sum += term;
    }
    return fmax(0.0, 1.0 - lead * sum);
}

/* Q(a, x) for x >= a + 1 from its continued fraction, by Lentz's method. */
static double gamma_q_fraction(double a, double x, double lead)
{
    double tiny = 1e-300, b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    int n;
    for (n = 1; n < GAMMA_MAX_ITER; n++) {
        double an = -n * (n - a), del;
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        del = d * c;
        h *= del;
        if (fabs(del - 1.0) < GAMMA_EPS) break;
    }
    return lead * h;
}

/* The regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a), a > 0. */
static double chi2_gamma_q(double a, double x)
{
    double lead;
    if (x <= 0.0) return 1.0;
    if (isinf(x)) return 0.0;
    lead = exp(a * log(x) - x - log_gamma(a));   /* x^a e^-x / Gamma(a) */
    return x < a + 1.0 ? gamma_q_series(a, x, lead) : gamma_q_fraction(a, x, lead);
}

double chi2_pvalue(double chi2, int dof) { return dof >= 1 ? chi2_gamma_q(0.5 * dof, 0.5 * chi2) : 0.0; }


static double pearson_term(double o, double e) { return (o - e) * (o - e) / e; }

chi2_result chi2_test(const double *obs, const double *expct, int n)
{
    chi2_result r;
    double pool_o = 0.0, pool_e = 0.0, big_o = 0.0, big_e = -1.0;
    int i, cells = 0, big = -1;
    r.chi2 = 0.0, r.expected_total = 0.0;
    for (i = 0; i < n; i++) {   /* the pool, and the largest cell */
        r.expected_total += expct[i];
        if (expct[i] < POOL_BELOW) pool_o += obs[i], pool_e += expct[i];
        else if (expct[i] > big_e) big = i, big_e = expct[i], big_o = obs[i];
    }
    for (i = 0; i < n; i++) {
        if (expct[i] < POOL_BELOW || i == big) continue;
        r.chi2 += pearson_term(obs[i], expct[i]);
        cells++;
    }
    if (pool_e == 0.0 && pool_o > 0.0) r.chi2 = INFINITY;   /* samples where the pdf says none can be */
    if (pool_e >= POOL_BELOW || big < 0) {                   /* the pool is a cell of its own */
        if (pool_e > 0.0) r.chi2 += pearson_term(pool_o, pool_e), cells++;
        pool_o = pool_e = 0.0;
    }
    if (big >= 0) {                                          /* else it joins the largest cell */
        r.chi2 += pearson_term(big_o + pool_o, big_e + pool_e);
        cells++;
    }
    r.dof = cells - 1;
    r.p = chi2_pvalue(r.chi2, r.dof);
    return r;
}
