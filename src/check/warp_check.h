/* warp_check.h — running a warp case and a triangle case (case.h): the warps of sampling.c against
 * their pdfs, directions about +z binned in (1 - cos theta, phi) (chi2_sphere.h), and the uniform
 * point on a triangle binned in sub-triangles (chi2_triangle.h). */
#ifndef PATHLAB_CHECK_WARP_CHECK_H
#define PATHLAB_CHECK_WARP_CHECK_H
#include "check/case.h"

/* n samples of the warp w from the streams of seed; the findings in r (which the caller cleared). */
void check_warp(const warp_routine *w, long n, uint64_t seed, sampling_result *r);
/* n points of the triangle sampler t, uniform in area: uniform density 2 in barycentrics (b1, b2). */
void check_triangle(const triangle_routine *t, long n, uint64_t seed, sampling_result *r);
#endif
