/* brdf_check.h — running a BRDF case (case.h): brdf_sample against brdf_pdf for one material and one
 * wo, the samples binned through their half vector (chi2_sphere.h), the pdf integrated over the
 * directions above the surface, and the pdf of every sample checked against the slides' formula. */
#ifndef PATHLAB_CHECK_BRDF_CHECK_H
#define PATHLAB_CHECK_BRDF_CHECK_H
#include "check/case.h"

/* n samples of the BRDF case b from the streams of seed; the findings in r (which the caller cleared). */
void check_brdf(const brdf_routine *b, long n, uint64_t seed, sampling_result *r);
#endif
