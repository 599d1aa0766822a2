/* tdist.c — the incomplete beta function by its continued fraction, and Student's t from it. */
#include "stats/tdist.h"
#include <math.h>
#include "stats/significance.h"

#define CF_ITERATIONS 300
#define CF_EPS 1e-15
#define CF_TINY 1e-300

/* The continued fraction of I_x(a, b) (Abramowitz & Stegun 26.5.8), evaluated by the modified Lentz
 * method; it converges fast for x < (a + 1) / (a + b + 2). */
static double incbeta_fraction(double x, double a, double b)
{
    double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0), f;
    int m;
    d = fabs(d) < CF_TINY ? 1.0 / CF_TINY : 1.0 / d;
    f = d;
    for (m = 1; m <= CF_ITERATIONS; m++) {
        int step;
        for (step = 0; step < 2; step++) {   /* the even term d_2m, then the odd d_2m+1 */
            double num = step == 0 ? m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m))
                                   : -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
            double delta;
            d = 1.0 + num * d;
            c = 1.0 + num / c;
            d = fabs(d) < CF_TINY ? 1.0 / CF_TINY : 1.0 / d;
            if (fabs(c) < CF_TINY) c = CF_TINY;
            delta = c * d;
            f *= delta;
            if (step == 1 && fabs(delta - 1.0) < CF_EPS) return f;
        }
    }
    return f;
}

double incbeta_regularized(double x, double a, double b)
{
    double front;
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    /* x^a (1 - x)^b / (a B(a, b)), in logarithms */
    front = exp(a * log(x) + b * log1p(-x) - (lgamma(a) + lgamma(b) - lgamma(a + b)));
    if (x < (a + 1.0) / (a + b + 2.0)) return front * incbeta_fraction(x, a, b) / a;
    return 1.0 - front * incbeta_fraction(1.0 - x, b, a) / b;   /* I_x(a, b) = 1 - I_(1-x)(b, a) */
}

double t_two_sided_tail(double t, double df)
{
    t = fabs(t);
    if (isinf(t)) return 0.0;
    if (df <= 0.0) return erfc(t / sqrt(2.0));
    return incbeta_regularized(df / (df + t * t), 0.5 * df, 0.5);
}

double t_equivalent_z(double t, double df)
{
    double p = t_two_sided_tail(t, df), z;
    if (df <= 0.0) return t;
    z = p > 0.0 ? -normal_quantile(0.5 * p) : HUGE_VAL;   /* the lower tail: no cancellation for small p */
    return t < 0.0 ? -z : z;
}

double welch_dof(double va, double da, double vb, double db)
{
    double den = (da > 0.0 ? va * va / da : 0.0) + (db > 0.0 ? vb * vb / db : 0.0);
    return den > 0.0 ? (va + vb) * (va + vb) / den : 0.0;
}
