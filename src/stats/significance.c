/* significance.c — Sidak's level and the normal and t quantiles. */
#include "stats/significance.h"
#include <math.h>
#include "math/vec.h"

double normal_quantile(double p)
{
    /* bisection on the cdf 0.5 erfc(-x / sqrt 2): slow but exact to double precision, and tests
     * call it a handful of times */
    double lo = -40.0, hi = 40.0;
    int i;
    for (i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (0.5 * erfc(-mid / sqrt(2.0)) < p) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

double sidak_zcrit(double alpha, long n)
{
    return normal_quantile(1.0 - 0.5 * sidak_level(alpha, n));
}

double student_t_tail(double t, int df)
{
    /* Abramowitz & Stegun 26.7.3-4: A(t|df) = P(|T| < t) is a finite series in c = cos(theta),
     * theta = atan(t / sqrt(df)):
     *   df odd:  A = 2/pi (theta + sin(theta) (c + 2/3 c^3 + 2.4/(3.5) c^5 + ... up to c^(df-2)))
     *   df even: A = sin(theta) (1 + 1/2 c^2 + 1.3/(2.4) c^4 + ... up to c^(df-2))
     * Beyond 10^5 degrees of freedom, the normal distribution. */
    double theta, c, term, sum = 0.0, A;
    int k;
    t = fabs(t);
    if (isinf(t)) return 0.0;
    if (df > 100000) return erfc(t / sqrt(2.0));
    theta = atan(t / sqrt((double)df));
    c = cos(theta);
    if (df % 2 == 1) {
        term = c;
        for (k = 1; k <= (df - 1) / 2; k++) {      /* (df - 1) / 2 terms; none when df = 1 */
            sum += term;
            term *= c * c * (2.0 * k) / (2.0 * k + 1.0);
        }
        A = 2.0 / PI * (theta + sin(theta) * sum);
    } else {
        term = 1.0;
        for (k = 1; k <= df / 2; k++) {            /* df / 2 terms */
            sum += term;
            term *= c * c * (2.0 * k - 1.0) / (2.0 * k);
        }
        A = sin(theta) * sum;
    }
    return A < 1.0 ? 1.0 - A : 0.0;
}

/* |t| whose two-sided tail is level: by bisection on the tail, which costs 200 x df/2 terms; above
 * 300 degrees of freedom by the Cornish-Fisher expansion about the normal quantile z (Abramowitz &
 * Stegun 26.7.5), t = z + (z^3 + z)/(4 df) + (5z^5 + 16z^3 + 3z)/(96 df^2)
 * + (3z^7 + 19z^5 + 17z^3 - 15z)/(384 df^3), whose next term is below 1e-5 there even at z = 6. */
double t_critical(double level, int df)
{
    double lo = 0.0, hi = 1e6;
    int i;
    if (df > 300) {
        double z = normal_quantile(1.0 - 0.5 * level), z2 = z * z, n = df;
        return z + z * (z2 + 1.0) / (4.0 * n) + z * ((5.0 * z2 + 16.0) * z2 + 3.0) / (96.0 * n * n) +
               z * (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) / (384.0 * n * n * n);
    }
    for (i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (student_t_tail(mid, df) > level) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* Sidak: the per-test level that gives family-wise level alpha over k independent tests. */
double sidak_level(double alpha, long k) { return -expm1(log1p(-alpha) / (double)(k > 0 ? k : 1)); }

