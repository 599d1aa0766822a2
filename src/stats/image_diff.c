/* image_diff.c — the error metrics of an image against a reference (image_diff.h). */
#include "stats/image_diff.h"
#include <math.h>
#include <string.h>

int image_diff_compute(image_diff *s, const image *a, const image *ref)
{
    long i, npix = (long)a->w * a->h;
    double se = 0.0, rel = 0.0, ae = 0.0, sum = 0.0, peak = 0.0, pix2 = 0.0;
    memset(s, 0, sizeof *s);
    if (a->w != ref->w || a->h != ref->h) return 1;
    s->n = 3L * npix;
    for (i = 0; i < s->n; i++) {
        double b = ref->px[i], d = (double)a->px[i] - b;
        se += d * d;
        rel += d * d / (b * b + IMAGE_DIFF_REL_EPS);
        ae += fabs(d);
        sum += d;
        if (fabs(d) > s->max) s->max = fabs(d);
        if (b > peak) peak = b;
        if (i % 3 == 2) {   /* the pixel's mean difference over RGB */
            double m = ((double)a->px[i - 2] - ref->px[i - 2] + (double)a->px[i - 1] - ref->px[i - 1] + d) / 3.0;
            pix2 += m * m;
        }
    }
    s->rmse = sqrt(se / s->n);
    s->relmse = rel / s->n;
    s->mae = ae / s->n;
    s->mean = sum / s->n;
    /* the standard error of the mean from the pixels' means, not the channels: a pixel's channels
     * are not independent (those of a greyscale image are one value, three times: sqrt(3) too small) */
    s->mean_se = npix > 1 ? sqrt(fmax(0.0, (pix2 - npix * s->mean * s->mean) / (npix - 1)) / npix) : 0.0;
    /* identical: inf; a black reference has no peak: no PSNR (inf read as a perfect match) */
    s->psnr = se == 0.0 ? INFINITY : peak > 0.0 ? 10.0 * log10(peak * peak / (se / s->n)) : NAN;
    return 0;
}
