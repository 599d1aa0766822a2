/* pixel_sums.h — what render keeps per pixel and image layer across passes, and the mean and the
 * variance of the mean it gives, per sampler:
 *   independent  the sums of the samples and of their squares (RGB): mean, and sample variance / n
 *                (n - 1 degrees of freedom: "many").
 *   sobol        the sums of each of the SAMPLER_GROUPS groups (sample i in group i mod K, each
 *                group an independent scrambling): mean of all samples, and the variance of it
 *                from the spread between the group means (K - 1 = 3 degrees of freedom). The
 *                samples of one group are not independent: their own spread would not do.
 * A sample dropped for being NaN or infinite adds nothing but still counts (as 0), as before. */
#ifndef PATHLAB_PIXEL_SUMS_H
#define PATHLAB_PIXEL_SUMS_H
#include <stdint.h>
#include "math/vec.h"
#include "sampler/sampler.h"

/* The doubles kept per pixel and layer. */
int pixel_sums_size(sampler_kind kind);
/* Adds sample `index` (its value c) to the sums a. */
void pixel_sums_add(double *a, sampler_kind kind, int64_t index, vec3 c);
/* The mean and the variance of the mean (RGB) of the samples first .. first + n - 1 summed in a. */
void pixel_sums_store(const double *a, sampler_kind kind, int64_t first, int n, float mean[3], float var[3]);
/* The degrees of freedom of that variance: 0 for "many" (independent), -1 for none (sobol1: one
 * scrambling), else groups with samples - 1. */
int pixel_sums_dof(sampler_kind kind, int n);
#endif
