/* significance.h — the levels and critical values every statistical verdict of pathlab uses:
 * Sidak's correction for a family of tests, and the quantiles of the normal and Student's t
 * distributions (bisection on exact tails: slow, accurate to double precision, called a few times). */
#ifndef PATHLAB_SIGNIFICANCE_H
#define PATHLAB_SIGNIFICANCE_H

/* The level of each of k independent tests so that all pass together with probability 1 - alpha:
 * 1 - (1 - alpha)^(1/k), computed without cancellation (accurate for alpha = 1e-12 too). */
double sidak_level(double alpha, long k);
/* Standard normal quantile: x with P(Z < x) = p. */
double normal_quantile(double p);
/* Two-sided critical |z| for k tests at family-wise level alpha (Sidak). */
double sidak_zcrit(double alpha, long k);
/* P(|T| > t) for Student's t with df degrees of freedom (df >= 1). */
double student_t_tail(double t, int df);
/* |t| whose two-sided tail P(|T| > t) is level. */
double t_critical(double level, int df);
#endif
