/* negatives.h — where a student's image holds negative radiance and the likely cause. Radiance is
 * never negative; a student's image is when a cosine is not clamped: cos theta at the light (light
 * leaving the back of the emitter: negative where the reference is black, behind the light) or
 * at the surface (a normal facing away: on silhouettes and creases, the edges of the reference).
 * The image stays unreadable for grading (exit 2); this says why in the teacher's words. */
#ifndef PATHLAB_NEGATIVES_H
#define PATHLAB_NEGATIVES_H
#include <stddef.h>
#include "image/image.h"

/* The pixels with a negative value beyond the tolerance of image/radiance.h, described against the
 * reference into out[cap]: how many, where (a box, in thirds of the image), on which kind of
 * surface, and the likely cause. 0 when there is none (out empty). */
int grade_explain_negatives(char *out, size_t cap, const image *img, const image *ref);
#endif
