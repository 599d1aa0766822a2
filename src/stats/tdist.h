/* tdist.h — Student's t distribution for any (real) degrees of freedom, through the regularized
 * incomplete beta function: for the per-pixel tests on a variance estimated with few degrees of
 * freedom (--sampler sobol: 3), where the normal distribution's tails would be far too thin. The
 * integer-df series of significance.h (student_t_tail) is the check of this one. */
#ifndef PATHLAB_TDIST_H
#define PATHLAB_TDIST_H

/* I_x(a, b), the regularized incomplete beta function, for 0 <= x <= 1, a, b > 0. */
double incbeta_regularized(double x, double a, double b);
/* P(|T| > t) for Student's t with df > 0 degrees of freedom; df <= 0 means infinitely many (normal). */
double t_two_sided_tail(double t, double df);
/* The z with the same two-sided tail as t with df degrees of freedom (same sign as t): a t statistic
 * turned into the equivalent standard normal one. */
double t_equivalent_z(double t, double df);
/* Welch-Satterthwaite: the degrees of freedom of va + vb for variance estimates va (da degrees of
 * freedom) and vb (db); 0 (= many) stands for infinitely many, and is returned if both are. */
double welch_dof(double va, double da, double vb, double db);
#endif
