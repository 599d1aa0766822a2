/* cases.h — the list of `pathlab check-sampling`'s cases (case.h), each with pathlab's own routines:
 * the warps of sampling.c (uniform, cosine, cos^m for 4 exponents), brdf_sample for 7 materials at
 * 5 angles of wo, the uniform point on a triangle, the choice of an emitter (area, triangle, power;
 * tree from 4 points, among 5 and 40 emitters), and the point on the emitters (uniform; solid-angle
 * from 6 points, Omega inside and outside the bounds of Arvo's map; tree, plain and joint), and a
 * direction toward the sky (constant, and two images). A test may swap a routine of a case for a broken one. */
#ifndef PATHLAB_CHECK_CASES_H
#define PATHLAB_CHECK_CASES_H
#include "check/case.h"

#define CHECK_MAX_CASES 64        /* room for the list (61 cases) */

/* Fills cases[0..] with the list; returns how many (at most max). */
int check_sampling_cases(sampling_case *cases, int max);
/* The test materials: Kd tinted (kd, 0.8 kd, 0.6 kd) so that the lobes' mixture is not grey, Ks grey. */
material check_sampling_material(float kd, float ks, float Ns);
#endif
