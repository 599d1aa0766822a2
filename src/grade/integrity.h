/* integrity.h — images that were not rendered by the student: the reference itself or another
 * student's image (found by the SHA-256 of the pixels), or an image made from the reference
 * (denoised, blended, scaled: its difference from the reference scatters less than the reference's
 * own noise alone would make it scatter). These are remarks beside the verdict, not a verdict: the
 * teacher decides. The test is described in integrity.c and docs/grading.md. */
#ifndef PATHLAB_GRADE_INTEGRITY_H
#define PATHLAB_GRADE_INTEGRITY_H
#include <stddef.h>
#include "image/image.h"

#define GRADE_SCATTER_ALPHA 1e-3   /* the scatter test's level (one-sided) */
#define GRADE_SCATTER_Z 3.0902     /* its normal quantile: z below -3.09 */
#define GRADE_SCATTER_RATIO 0.75   /* and the mean of d^2 / var below 3/4 */

typedef struct {
    long n;          /* pixel-channels tested: where the reference's variance is > 0 */
    double ratio;    /* the mean of d^2 / var over them: about 1 or more for an image independent of the reference */
    double z;        /* its Student t against 1: (ratio - 1) / (sd / sqrt(n)) */
    int low;         /* 1: z < -GRADE_SCATTER_Z and ratio < GRADE_SCATTER_RATIO */
} grade_scatter;

/* The SHA-256 of an image's size and pixels. */
void grade_pixel_hash(const image *img, unsigned char digest[32]);
/* The scatter of d = img - ref against var (the reference's variance of the pixel mean, same size). */
void grade_scatter_test(grade_scatter *s, const image *img, const image *ref, const image *var);
/* The remark on img against the reference (var may be NULL: no scatter test) into out[cap]: "the
 * reference's pixels, bit for bit", "scatter ...", or "" for none; 1 when there is one. */
int grade_integrity_remark(char *out, size_t cap, const image *img, const image *ref, const image *var);
#endif
