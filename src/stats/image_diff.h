/* image_diff.h — how far an image is from a reference, over every pixel channel, with d = a - b
 * (b the reference's value):
 *   RMSE = sqrt(mean d^2);  relMSE = mean d^2 / (b^2 + eps), eps = 1e-2 (so black pixels count);
 *   MAE = mean |d|;  max = max |d|;  PSNR = 10 log10(peak^2 / MSE), peak = max of b;
 *   (NaN when the reference is black and a is not), mean signed difference mean(d) with its standard
 *   error sd(m)/sqrt(pixels), m a pixel's mean d over RGB (its channels are not independent).
 * pathlab diff prints them; pathlab compare's table holds RMSE, relMSE and MAE. */
#ifndef PATHLAB_IMAGE_DIFF_H
#define PATHLAB_IMAGE_DIFF_H
#include "image/image.h"

typedef struct {
    double rmse, relmse, mae, max, psnr, mean, mean_se;
    long n;
} image_diff;

#define IMAGE_DIFF_REL_EPS 1e-2

/* 0 on success, 1 if the sizes differ. */
int image_diff_compute(image_diff *s, const image *a, const image *ref);
#endif
