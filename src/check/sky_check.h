/* sky_check.h — running a sky case (case.h): sky_sample against sky_pdf_sa and the course's pdf1,
 * on a test sky of w x h pixels (a bright one, a black one, the rest in between; 1 x 1: constant).
 * The cells are 2 x 2 per pixel, halves in cos theta and in phi (equal solid angles), each expected
 * N x luminance x solid angle / the integral of the luminance, computed here in double from the
 * image: a sampler that chose the wrong pixel, or drew non-uniformly in solid angle inside it, fails. */
#ifndef PATHLAB_CHECK_SKY_CHECK_H
#define PATHLAB_CHECK_SKY_CHECK_H
#include "check/case.h"

/* n samples of the routine k from the streams of seed; the findings in r (which the caller cleared). */
void check_sky(const sky_routine *k, long n, uint64_t seed, sampling_result *r);
#endif
