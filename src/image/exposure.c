/* exposure.c — the automatic exposure (exposure.h). */
#include "image/exposure.h"
#include <math.h>
#include <stdlib.h>

#define SAMPLES 65536   /* the median of at most this many evenly spread pixels: enough to 0.1 stop */

static int by_value(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

float img_auto_exposure(const image *im)
{
    size_t n = (size_t)im->w * im->h, step = n > SAMPLES ? n / SAMPLES : 1, i, m = 0;   /* the viewer's pixels */
    float *y = malloc((n / step + 1) * sizeof *y), med;
    double stops;
    if (!y) return 0.0f;
    for (i = 0; i < n; i += step) {
        const float *p = im->px + 3 * i;
        float v = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
        if (v > 0.0f && isfinite(v)) y[m++] = v;
    }
    if (!m) { free(y); return 0.0f; }
    qsort(y, m, sizeof *y, by_value);
    med = y[m / 2];
    free(y);
    stops = log2(EXPOSURE_MID_GREY / med);
    if (stops > 99.0) stops = 99.0;   /* convert's range of --exposure */
    if (stops < -99.0) stops = -99.0;
    return (float)(floor(stops * 10.0 + 0.5) / 10.0);
}
