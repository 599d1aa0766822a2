/* diff.h — `pathlab diff A.pfm B.pfm [--heatmap out.ppm]`: how far an image is from a reference.
 * Over every pixel channel, with d = a - b (B is the reference):
 *   RMSE = sqrt(mean d^2);  relMSE = mean d^2 / (b^2 + eps), eps = 1e-2 (so black pixels count);
 *   MAE = mean |d|;  max = max |d|;  PSNR = 10 log10(peak^2 / MSE), peak = max of b;
 *   mean signed difference mean(d) with its standard error sd(d)/sqrt(n) (over pixel channels). */
#ifndef PATHLAB_DIFF_H
#define PATHLAB_DIFF_H
#include "image/image.h"

typedef struct {
    double rmse, relmse, mae, max, psnr, mean, mean_se;
    long n;
} diff_stats;

#define DIFF_REL_EPS 1e-2

/* 0 on success, 1 if the sizes differ. */
int diff_compute(diff_stats *s, const image *a, const image *ref);
/* |a - ref| per pixel (mean over channels) as a colour ramp black-red-yellow-white, scaled so that
 * white is max |d| (or `scale` if > 0). */
int diff_heatmap(image *out, const image *a, const image *ref, double scale);
int diff_main(int argc, char **argv);
#endif
