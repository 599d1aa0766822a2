/* heatmap.c — |a - ref| as a colour ramp, and the ramp as a legend (heatmap.h). */
#include "image/heatmap.h"
#include <stddef.h>
#include <math.h>

/* black -> red -> yellow -> white as t goes 0 -> 1 */
static vec3 ramp(double t)
{
    float x = (float)(t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t) * 3.0f;
    return v3(fminf(x, 1.0f), fminf(fmaxf(x - 1.0f, 0.0f), 1.0f), fminf(fmaxf(x - 2.0f, 0.0f), 1.0f));
}

/* What a heatmap pixel shows: |a - ref| averaged over RGB. */
static double pixel_error(const float *p, const float *q)
{
    return (fabs((double)p[0] - q[0]) + fabs((double)p[1] - q[1]) + fabs((double)p[2] - q[2])) / 3.0;
}

int img_heatmap(image *out, const image *a, const image *ref, double scale, double *used)
{
    long i, n = (long)a->w * a->h;
    double max = 0.0;
    if (a->w != ref->w || a->h != ref->h || img_alloc(out, a->w, a->h)) return 1;
    /* white at the largest of what is shown (the largest channel's difference left a one-channel
     * difference a third of the way up the ramp) */
    for (i = 0; i < n; i++) max = fmax(max, pixel_error(a->px + 3 * i, ref->px + 3 * i));
    if (scale <= 0.0) scale = max > 0.0 ? max : 1.0;
    if (used) *used = scale;
    for (i = 0; i < n; i++) {
        double d = pixel_error(a->px + 3 * i, ref->px + 3 * i);
        vec3 c = ramp(d / scale);
        out->px[3 * i] = c.x;
        out->px[3 * i + 1] = c.y;
        out->px[3 * i + 2] = c.z;
    }
    return 0;
}

int img_heatmap_legend(image *legend, int w, int h)
{
    image grad, zero;
    int x, y, err;
    if (img_alloc(&grad, w, h)) return 1;
    if (img_alloc(&zero, w, h)) { img_free(&grad); return 1; }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float t = w > 1 ? (float)x / (float)(w - 1) : 1.0f;
            grad.px[3 * (y * w + x)] = grad.px[3 * (y * w + x) + 1] = grad.px[3 * (y * w + x) + 2] = t;
        }
    err = img_heatmap(legend, &grad, &zero, 1.0, NULL);
    img_free(&grad);
    img_free(&zero);
    return err;
}
