/* sky.c — the sky's radiance, its pdf1 and its sampling (sky.h): a pixel chosen in proportion to
 * luminance x solid angle (rows first, then the column in the row), then a direction uniform in
 * solid angle inside it. */
#include "tracer/sky.h"
#include "image/rgbe.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sky_free(sky *s)
{
    free(s->L);
    free(s->pdf);
    free(s->row_cdf);
    free(s->col_cdf);
    free(s->cos_edge);
    memset(s, 0, sizeof *s);
}

/* The cumulative sums of the n weights w into cdf, normalised (0 everywhere if they sum to 0);
 * returns their sum. In double: a float cdf would quantise the probabilities to 2^-24. */
static double cumulate(double *cdf, const double *w, int n)
{
    double acc = 0.0;
    int i;
    for (i = 0; i < n; i++) cdf[i] = acc += w[i];
    for (i = 0; i < n; i++) cdf[i] = acc > 0.0 ? cdf[i] / acc : 0.0;
    if (acc > 0.0) cdf[n - 1] = 1.0;
    return acc;
}

static double pixel_luminance(const sky *s, int k)
{
    const float *L = s->L + 3 * k;
    return 0.2126 * L[0] + 0.7152 * L[1] + 0.0722 * L[2];   /* luminance() in double: values >= 0 */
}

/* The distributions of a sky whose L, w, h are set: each row's columns by luminance, the rows by
 * luminance x solid angle (the row's sum times its solid angle per pixel), each pixel's pdf1. */
static int build_distributions(sky *s)
{
    double *row = malloc(sizeof(double) * (size_t)(s->w > s->h ? s->w : s->h)), *row_w = malloc(sizeof(double) * (size_t)s->h);
    int i, j, n = s->w * s->h;
    s->pdf = malloc(sizeof(float) * (size_t)n);
    s->row_cdf = malloc(sizeof(double) * (size_t)s->h);
    s->col_cdf = malloc(sizeof(double) * (size_t)n);
    s->cos_edge = malloc(sizeof(double) * (size_t)(s->h + 1));
    if (!row || !row_w || !s->pdf || !s->row_cdf || !s->col_cdf || !s->cos_edge) { free(row), free(row_w); return 1; }
    for (j = 0; j <= s->h; j++) s->cos_edge[j] = cos(PI * (double)j / s->h);
    for (j = 0; j < s->h; j++) {
        double pixel_sa = 2.0 * PI / s->w * (s->cos_edge[j] - s->cos_edge[j + 1]);
        for (i = 0; i < s->w; i++) row[i] = pixel_luminance(s, j * s->w + i);
        row_w[j] = cumulate(s->col_cdf + (size_t)j * s->w, row, s->w) * pixel_sa;
    }
    s->integral = cumulate(s->row_cdf, row_w, s->h);
    for (j = 0; j < s->h; j++)
        for (i = 0; i < s->w; i++) s->pdf[j * s->w + i] = s->integral > 0.0 ? (float)(pixel_luminance(s, j * s->w + i) / s->integral) : 0.0f;
    free(row), free(row_w);
    return 0;
}

int sky_from_image(sky *s, const image *im)
{
    size_t n = (size_t)im->w * (size_t)im->h * 3;
    memset(s, 0, sizeof *s);
    if (!(s->L = malloc(sizeof(float) * n))) return 1;
    memcpy(s->L, im->px, sizeof(float) * n);
    s->w = im->w, s->h = im->h;
    if (build_distributions(s)) { sky_free(s); return 1; }
    return 0;
}

/* An image's radiances must be finite and >= 0: a NaN or a negative sky has no meaning as light. */
static int check_values(const image *im, const char *path)
{
    size_t k, n = (size_t)im->w * (size_t)im->h * 3;
    for (k = 0; k < n; k++)
        if (!(im->px[k] >= 0.0f && im->px[k] <= 3.4e38f)) {
            fprintf(stderr, "%s: pixel (%d, %d) from the top left has radiance %g: a sky must be finite and >= 0\n", path,
                    (int)(k / 3 % (size_t)im->w), (int)(k / 3 / (size_t)im->w), (double)im->px[k]);
            return 1;
        }
    return 0;
}

int sky_build(sky *s, const sky_spec *spec)
{
    image im;
    int rc;
    memset(s, 0, sizeof *s);
    if (spec->kind == SKY_NONE) return 0;
    if (spec->kind == SKY_CONSTANT) {
        float px[3];
        px[0] = spec->rgb.x, px[1] = spec->rgb.y, px[2] = spec->rgb.z;
        im.w = im.h = 1, im.px = px;
        rc = sky_from_image(s, &im);
        if (rc) fprintf(stderr, "pathlab: out of memory for the sky\n");
        return rc;
    }
    if (img_format_of(spec->path) == IMG_HDR ? img_read_hdr(&im, spec->path) : img_read_pfm(&im, spec->path)) return 1;
    rc = check_values(&im, spec->path);
    if (!rc && (rc = sky_from_image(s, &im)) != 0) fprintf(stderr, "%s: out of memory for the sky's %dx%d tables\n", spec->path, im.w, im.h);
    img_free(&im);
    return rc;
}

/* The pixel (i, j) of the direction w (sky.h): theta from +Y gives the row, phi = atan2(z, x) the column. */
static int pixel_of(const sky *s, vec3 w)
{
    double len = sqrt((double)w.x * w.x + (double)w.y * w.y + (double)w.z * w.z);
    double cos_theta = fmin(1.0, fmax(-1.0, w.y / len));
    int j = (int)(acos(cos_theta) / PI * s->h), i = (int)((atan2(w.z, w.x) / (2.0 * PI) + 0.5) * s->w);
    if (j >= s->h) j = s->h - 1;
    if (i >= s->w) i = s->w - 1;   /* phi = pi exactly */
    if (i < 0) i = 0;
    return j * s->w + i;
}

vec3 sky_radiance(const sky *s, vec3 w)
{
    const float *L;
    if (s->w == 0) return v3(0, 0, 0);
    L = s->L + 3 * pixel_of(s, w);
    return v3(L[0], L[1], L[2]);
}

float sky_pdf_sa(const sky *s, vec3 w) { return s->w ? s->pdf[pixel_of(s, w)] : 0.0f; }

/* Smallest i with u < cdf[i] (binary search), and where u fell in that item's share, in [0, 1). */
static int pick(const double *cdf, int n, double u, double *rest)
{
    int lo = 0, hi = n - 1;
    double below, share;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (u < cdf[mid]) hi = mid; else lo = mid + 1;
    }
    below = lo > 0 ? cdf[lo - 1] : 0.0;
    share = cdf[lo] - below;
    *rest = share > 0.0 ? fmin(fmax((u - below) / share, 0.0), 0x1.fffffffffffffp-1) : 0.0;
    return lo;
}

vec3 sky_sample(const sky *s, double u1, float u2, float *pdf_sa, vec3 *L)
{
    double r1, r2, cos_theta, sin_theta, phi;
    int j = pick(s->row_cdf, s->h, u1, &r1), i = pick(s->col_cdf + (size_t)j * s->w, s->w, u2, &r2), k = j * s->w + i;
    cos_theta = s->cos_edge[j] + r1 * (s->cos_edge[j + 1] - s->cos_edge[j]);
    sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    phi = 2.0 * PI * ((i + r2) / s->w - 0.5);
    *pdf_sa = s->pdf[k];
    *L = v3(s->L[3 * k], s->L[3 * k + 1], s->L[3 * k + 2]);
    return v3((float)(sin_theta * cos(phi)), (float)cos_theta, (float)(sin_theta * sin(phi)));
}
