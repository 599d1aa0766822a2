/* imgstat.h — is the difference between two renders noise or bias? Z-tests that use each pixel's
 * variance of the mean (written by `render --variance`):
 *   per pixel: z = (a - b) / sqrt(va + vb), |z| below the Sidak-corrected critical value;
 *   per block: the same on the mean of B x B pixel blocks (averaging shrinks noise, not bias);
 *   whole image: the same on the mean of all pixels, the most sensitive to a uniform bias.
 * Pixels are independent (one random stream each), so block and image means are sums of
 * independent terms and their variances add.
 * A variance estimated with few degrees of freedom (--sampler sobol: 3, from 4 group means; the
 * sidecar's variance-dof) makes the per-pixel z a Student t: its tails are far heavier, and the
 * pixel test compares its two-sided tail P(|T| > |t|) (Welch-Satterthwaite degrees of freedom
 * when both variances are estimated) with the Sidak level instead. Block and image sums add the
 * variances of 64 pixels or more, whose degrees of freedom add too: those tests stay normal. */
#ifndef PATHLAB_IMGSTAT_H
#define PATHLAB_IMGSTAT_H
#include "image/image.h"

typedef struct {
    double alpha;               /* family-wise significance level of each test */
    int npix, npix_fail;        /* pixel-channels tested, and failing at the Sidak level */
    double pixel_zcrit;
    int nblocks, nblocks_fail;
    double block_zcrit, block_zmax;
    double image_z[3];          /* z of the whole-image mean difference, per channel */
    double image_zcrit;
    double mean_diff[3];        /* mean of a - b per channel */
    double mean_sd[3];          /* its standard deviation (noise and rounding), per channel */
    double mean_b[3];           /* mean of b per channel (for relative figures) */
} zreport;

/* Runs the three tests; images must have the same size. dof_a, dof_b: the degrees of freedom of va
 * and vb (0: many, the normal test). Returns 0, or 1 if sizes differ. */
int zreport_compute_dof(zreport *r, const image *a, const image *va, double dof_a, const image *b, const image *vb,
                        double dof_b, double alpha, int block);
#endif
