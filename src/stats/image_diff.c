/* image_diff.c — the error metrics of an image against a reference (image_diff.h). */
#include "stats/image_diff.h"
#include <math.h>
#include <string.h>

int image_diff_compute(image_diff *s, const image *a, const image *ref)
{
    long i;
    double se = 0.0, rel = 0.0, ae = 0.0, sum = 0.0, peak = 0.0;
    memset(s, 0, sizeof *s);
    if (a->w != ref->w || a->h != ref->h) return 1;
    s->n = 3L * a->w * a->h;
    for (i = 0; i < s->n; i++) {
        double b = ref->px[i], d = (double)a->px[i] - b;
        se += d * d;
        rel += d * d / (b * b + IMAGE_DIFF_REL_EPS);
        ae += fabs(d);
        sum += d;
        if (fabs(d) > s->max) s->max = fabs(d);
        if (b > peak) peak = b;
    }
    s->rmse = sqrt(se / s->n);
    s->relmse = rel / s->n;
    s->mae = ae / s->n;
    s->mean = sum / s->n;
    /* sample variance of d from its moments, then the standard error of its mean */
    s->mean_se = s->n > 1 ? sqrt(fmax(0.0, (se - s->n * s->mean * s->mean) / (s->n - 1)) / s->n) : 0.0;
    s->psnr = se > 0.0 && peak > 0.0 ? 10.0 * log10(peak * peak / (se / s->n)) : INFINITY;
    return 0;
}
