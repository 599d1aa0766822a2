/* zcheck — test tool: are two renders equal up to their noise?
 *   zcheck A.pfm A_var.pfm B.pfm B_var.pfm [--alpha 0.01] [--block 8] [--pixel-pass 0.9975]
 *          [--precision R] [--dof-a D] [--dof-b D]
 * Passes (exit 0) when at least --pixel-pass of the pixel-channels pass the Sidak-corrected
 * per-pixel Z-test, every block passes its Z-test, and the whole-image means agree (each family at
 * level alpha). With --precision R, the whole-image test must also be sharp enough to see a relative
 * error R: its tolerance (critical z times the standard deviation of the mean difference, about
 * 3 sigma) must be at most R times the mean of B, in every channel; otherwise exit 3 (too few samples
 * to tell, not a wrong answer). Prints the figures on one line. Exit 1: a test failed; 2: bad input.
 * The degrees of freedom of each variance come from its sidecar (variance-dof: --sampler sobol's 3;
 * absent: many), or --dof-a/--dof-b (0: many); with few, the per-pixel test is Student's t. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "stats/imgstat.h"
#include "files/sidecar.h"

/* The variance-dof of the sidecar of path (0: many, or no sidecar); -1 if the sidecar is malformed. */
static double sidecar_dof(const char *path)
{
    sidecar m;
    int rc = sidecar_read(&m, path);
    return rc < 0 ? 0.0 : rc > 0 ? -1.0 : m.variance_dof;
}

int main(int argc, char **argv)
{
    image im[4];
    zreport r;
    double alpha = 0.01, pixel_pass = 0.9975, precision = 0.0, frac, zimg = 0.0, reltol = 0.0;
    double dof_a, dof_b;
    int block = 8, i, ch, ok;
    if (argc < 5) { fprintf(stderr, "usage: zcheck A A_var B B_var [--alpha a] [--block B] [--pixel-pass f]\n"); return 2; }
    dof_a = sidecar_dof(argv[2]);
    dof_b = sidecar_dof(argv[4]);
    if (dof_a < 0 || dof_b < 0) return 2;
    for (i = 5; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--alpha")) alpha = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--block")) block = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--pixel-pass")) pixel_pass = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--precision")) precision = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--dof-a")) dof_a = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--dof-b")) dof_b = atof(argv[i + 1]);
        else { fprintf(stderr, "zcheck: unknown option %s\n", argv[i]); return 2; }
    }
    for (i = 0; i < 4; i++)
        if (img_read_pfm(&im[i], argv[1 + i])) return 2;
    if (zreport_compute_dof(&r, &im[0], &im[1], dof_a, &im[2], &im[3], dof_b, alpha, block)) { fprintf(stderr, "zcheck: sizes differ\n"); return 2; }
    frac = 1.0 - (double)r.npix_fail / r.npix;
    for (ch = 0; ch < 3; ch++) {
        double rel = r.image_zcrit * r.mean_sd[ch] / fabs(r.mean_b[ch]);
        if (fabs(r.image_z[ch]) > zimg) zimg = fabs(r.image_z[ch]);
        if (!(rel <= reltol)) reltol = rel;     /* NaN (a zero mean) counts as too coarse */
    }
    ok = frac >= pixel_pass && r.nblocks_fail == 0 && zimg <= r.image_zcrit;
    if (dof_a > 0 || dof_b > 0) printf("variance dof %g %g (0: many): pixel test on Student's t; ", dof_a, dof_b);
    printf("alpha %g: pixels %.4f pass (|z| < %.2f, need %.4f); blocks %d/%d fail (max |z| %.2f, crit %.2f); "
           "image |z| %.2f (crit %.2f), mean diff %.3g %.3g %.3g, relative diff %.2g, tolerance %.2g of the mean\n",
           alpha, frac, r.pixel_zcrit, pixel_pass, r.nblocks_fail, r.nblocks, r.block_zmax, r.block_zcrit,
           zimg, r.image_zcrit, r.mean_diff[0], r.mean_diff[1], r.mean_diff[2],
           fabs(r.mean_diff[0] / r.mean_b[0]), reltol);
    for (i = 0; i < 4; i++) img_free(&im[i]);
    if (ok && precision > 0.0 && !(reltol <= precision)) {
        printf("too few samples: the whole-image tolerance is %.2g of the mean, over the %.2g asked\n", reltol, precision);
        return 3;
    }
    return ok ? 0 : 1;
}
