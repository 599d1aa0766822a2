/* zcheck — test tool: are two renders equal up to their noise?
 *   zcheck A.pfm A_var.pfm B.pfm B_var.pfm [--alpha 0.01] [--block 8] [--pixel-pass 0.9975]
 * Passes (exit 0) when at least --pixel-pass of the pixel-channels pass the Sidak-corrected
 * per-pixel Z-test, every block passes its Z-test, and the whole-image means agree (each family at
 * level alpha). Prints the figures on one line. Exit 1: a test failed; 2: bad input. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "imgstat.h"

int main(int argc, char **argv)
{
    image im[4];
    zreport r;
    double alpha = 0.01, pixel_pass = 0.9975, frac, zimg = 0.0;
    int block = 8, i, ch, ok;
    if (argc < 5) { fprintf(stderr, "usage: zcheck A A_var B B_var [--alpha a] [--block B] [--pixel-pass f]\n"); return 2; }
    for (i = 5; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--alpha")) alpha = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--block")) block = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--pixel-pass")) pixel_pass = atof(argv[i + 1]);
        else { fprintf(stderr, "zcheck: unknown option %s\n", argv[i]); return 2; }
    }
    for (i = 0; i < 4; i++)
        if (img_read_pfm(&im[i], argv[1 + i])) return 2;
    if (zreport_compute(&r, &im[0], &im[1], &im[2], &im[3], alpha, block)) { fprintf(stderr, "zcheck: sizes differ\n"); return 2; }
    frac = 1.0 - (double)r.npix_fail / r.npix;
    for (ch = 0; ch < 3; ch++) if (fabs(r.image_z[ch]) > zimg) zimg = fabs(r.image_z[ch]);
    ok = frac >= pixel_pass && r.nblocks_fail == 0 && zimg <= r.image_zcrit;
    printf("alpha %g: pixels %.4f pass (|z| < %.2f, need %.4f); blocks %d/%d fail (max |z| %.2f, crit %.2f); "
           "image |z| %.2f (crit %.2f), mean diff %.3g %.3g %.3g\n",
           alpha, frac, r.pixel_zcrit, pixel_pass, r.nblocks_fail, r.nblocks, r.block_zmax, r.block_zcrit,
           zimg, r.image_zcrit, r.mean_diff[0], r.mean_diff[1], r.mean_diff[2]);
    for (i = 0; i < 4; i++) img_free(&im[i]);
    return ok ? 0 : 1;
}
