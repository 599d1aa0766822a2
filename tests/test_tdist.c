/* test_tdist.c — Student's t for real degrees of freedom (stats/tdist.h), the per-pixel test of a
 * variance with few degrees of freedom (--sampler sobol):
 *   1. the incomplete beta function at closed forms: I_x(1, 1) = x, I_x(a, 1) = x^a, I_x(1, b) =
 *      1 - (1 - x)^b, I_1/2(2, 3) = 11/16;
 *   2. the t tail equals the exact integer-df series of significance.c (student_t_tail) to 1e-9
 *      relative, df 1..100, |t| 0.05..40 where the tail is above 1e-6 (the series computes 1 - A,
 *      which cancels below), and printed tables (df 3: 3.182 at 5%, 5.841 at 1%);
 *   3. between integer df the tail lies between its neighbours' (monotone in df);
 *   4. t_equivalent_z: df 3, t 3.182 is z 1.960; many df, z = t; the sign kept; z has t's tail;
 *   5. Welch-Satterthwaite: one estimate keeps its df, two equal ones add them, none is "many". */
#include "check.h"
#include "stats/significance.h"
#include "stats/tdist.h"
#include <math.h>

static void closed_forms(void)
{
    double x, worst = 0.0;
    for (x = 0.01; x < 1.0; x += 0.07) {
        worst = fmax(worst, fabs(incbeta_regularized(x, 1, 1) - x));
        worst = fmax(worst, fabs(incbeta_regularized(x, 3.5, 1) - pow(x, 3.5)));
        worst = fmax(worst, fabs(incbeta_regularized(x, 1, 2.5) - (1.0 - pow(1.0 - x, 2.5))));
    }
    worst = fmax(worst, fabs(incbeta_regularized(0.5, 2, 3) - 11.0 / 16.0));
    check(worst < 1e-12, "incbeta_regularized: closed forms", "largest error %.2g", worst);
}

static void against_series(void)
{
    static const double ts[] = {0.05, 0.3, 1.0, 1.7, 2.5, 3.182, 5.0, 8.0, 15.0, 40.0};
    double worst = 0.0;
    int df;
    size_t i;
    for (df = 1; df <= 100; df++)
        for (i = 0; i < sizeof ts / sizeof ts[0]; i++) {
            double a = t_two_sided_tail(ts[i], df), b = student_t_tail(ts[i], df);
            if (b > 1e-6) worst = fmax(worst, fabs(a - b) / b);   /* the series' 1 - A cancels below */
        }
    check(worst < 1e-9, "t_two_sided_tail equals the integer-df series (df 1..100)", "largest relative difference %.2g", worst);
    check(fabs(t_two_sided_tail(3.182, 3) - 0.05) < 1e-4 && fabs(t_two_sided_tail(-5.841, 3) - 0.01) < 1e-5,
          "t_two_sided_tail: df 3 table (3.182 at 5%, 5.841 at 1%)", "%.6f %.6f", t_two_sided_tail(3.182, 3),
          t_two_sided_tail(-5.841, 3));
    check(fabs(t_two_sided_tail(2.0, 0) - erfc(2.0 / sqrt(2.0))) < 1e-15, "t_two_sided_tail: df 0 is the normal", NULL);
}

static void monotone_in_df(void)
{
    int ok = 1, df;
    for (df = 1; df < 30; df++) {
        double lo = t_two_sided_tail(3.0, df + 1), mid = t_two_sided_tail(3.0, df + 0.5), hi = t_two_sided_tail(3.0, df);
        ok = ok && lo < mid && mid < hi;
    }
    check(ok, "t_two_sided_tail at df + 1/2 lies between df and df + 1", NULL);
}

static void equivalent_z(void)
{
    double z = t_equivalent_z(3.182, 3), zn = t_equivalent_z(-2.5, 0), zbig = t_equivalent_z(-2.5, 1e7);
    check(fabs(z - 1.960) < 1e-3, "t_equivalent_z: t 3.182 with 3 df is z 1.960", "z %.4f", z);
    check(zn == -2.5 && fabs(zbig + 2.5) < 1e-5, "t_equivalent_z: many df, z = t (sign kept)", "%.6f", zbig);
    z = t_equivalent_z(40.0, 3);
    check(fabs(erfc(z / sqrt(2.0)) / t_two_sided_tail(40.0, 3) - 1.0) < 1e-9, "t_equivalent_z: z has the tail of t (t 40, 3 df)",
          "z %.4f", z);
}

static void welch(void)
{
    check(welch_dof(2.0, 3, 0.0, 0) == 3.0 && welch_dof(1.0, 3, 1.0, 3) == 6.0 && welch_dof(1.0, 0, 1.0, 0) == 0.0,
          "welch_dof: one estimate 3, two equal 6, none many", "%g %g %g", welch_dof(2.0, 3, 0.0, 0), welch_dof(1.0, 3, 1.0, 3),
          welch_dof(1.0, 0, 1.0, 0));
    check(welch_dof(1.0, 3, 3.0, 0) == 48.0, "welch_dof: an exact variance beside an estimated one: (1 + 3)^2 / (1 / 3)", NULL);
}

int main(void)
{
    closed_forms();
    against_series();
    monotone_in_df();
    equivalent_z();
    welch();
    return check_summary();
}
