/* light_check.h — running a light case (case.h) in its test scene (light_scene.h):
 * light_sample_point against light_pdf_area, the choice of an emitter (one cell per emitter) and the
 * point on it (sub-triangles, or Arvo's coordinates for the solid-angle strategy, arvo.h). */
#ifndef PATHLAB_CHECK_LIGHT_CHECK_H
#define PATHLAB_CHECK_LIGHT_CHECK_H
#include "check/case.h"

/* n samples binned by emitter; the findings in r (which the caller cleared). */
void check_light_choice(const light_routine *l, long n, uint64_t seed, sampling_result *r);
/* n samples binned by emitter and by the cells of l->grid^2 on each. */
void check_light_point(const light_routine *l, long n, uint64_t seed, sampling_result *r);
#endif
