/* sky_check.c — sky_sample against its pdf and the course's pdf1 (sky_check.h). */
#include "check/sky_check.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SKY_SPOT_CHECKS 200000   /* samples whose returned pdf is compared with sky_pdf_sa */
#define EDGE_TOL 1e-5            /* samples this close to a pixel's edge may round into the next one */

/* The test image's radiance at pixel (i, j): one bright pixel, every seventh black, the rest from
 * 0.3 to 1.8, tinted; the 1 x 1 sky is (1, 1, 1). */
static vec3 test_radiance(int i, int j, int w, int h)
{
    float v = 0.3f + 0.5f * (float)((i * 5 + j * 3) % 4);
    if (w * h == 1) return v3(1, 1, 1);
    if (i == w / 3 && j == h / 2) v = 50.0f;
    else if ((i + j * w) % 7 == 3) v = 0.0f;
    return v3(v, 0.7f * v, 1.3f * v);
}

static double lum_d(vec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

/* The direction at (cos theta, phi) */
static vec3 direction(double cos_theta, double phi)
{
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    return v3((float)(sin_theta * cos(phi)), (float)cos_theta, (float)(sin_theta * sin(phi)));
}

/* The cell of w, 2 x 2 per pixel (sky.h's mapping, in double), and whether it is within EDGE_TOL of an edge */
static int cell_of(vec3 w, int W, int H, int *near_edge)
{
    double x = acos(fmin(1.0, fmax(-1.0, w.y / v3_length(w)))) / PI * H, y = (atan2(w.z, w.x) / (2.0 * PI) + 0.5) * W;
    int j = (int)x, i = (int)y, a, b;
    double c_top, c_bot, c_mid;
    if (j >= H) j = H - 1;
    if (i >= W) i = W - 1;
    if (i < 0) i = 0;
    c_top = cos(PI * j / H), c_bot = cos(PI * (j + 1) / H), c_mid = 0.5 * (c_top + c_bot);
    a = w.y / v3_length(w) < c_mid;
    b = y - i >= 0.5;
    *near_edge = fabs(x - floor(x + 0.5)) < EDGE_TOL * H || fabs(y - floor(y + 0.5)) < EDGE_TOL * W;
    return ((j * 2 + a) * W + i) * 2 + b;
}

/* The expected counts (n x probability of each cell), the pdf at each cell's centre against the
 * formula luminance / integral, and the integral of the pdf over the sphere. */
static void expected(const sky_routine *k, const sky *s, long n, double *expct, sampling_result *r)
{
    double z = 0.0;
    int i, j, a, b;
    for (j = 0; j < k->h; j++)
        for (i = 0; i < k->w; i++) z += lum_d(test_radiance(i, j, k->w, k->h)) * 2.0 * PI / k->w * (cos(PI * j / k->h) - cos(PI * (j + 1) / k->h));
    r->nintegrals = 1, r->integral[0] = 0.0, r->integral_want[0] = 1.0, r->integral_what[0] = "over the sphere";
    r->has_formula = 1, r->formula_tol = 1e-5;
    for (j = 0; j < k->h; j++)
        for (a = 0; a < 2; a++)
            for (i = 0; i < k->w; i++)
                for (b = 0; b < 2; b++) {
                    double c0 = cos(PI * j / k->h), c1 = cos(PI * (j + 1) / k->h), cm = 0.5 * (c0 + c1);
                    double sa = PI / k->w * 0.5 * (c0 - c1), want = lum_d(test_radiance(i, j, k->w, k->h)) / z;
                    double pdf = k->pdf(s, direction(a ? 0.5 * (cm + c1) : 0.5 * (c0 + cm), 2.0 * PI * ((i + 0.25 + 0.5 * b) / k->w - 0.5)));
                    expct[((j * 2 + a) * k->w + i) * 2 + b] = (double)n * want * sa;
                    r->integral[0] += pdf * sa;
                    r->formula_gap = fmax(r->formula_gap, want > 0.0 ? fabs(pdf - want) / want : pdf > 0.0 ? INFINITY : 0.0);
                }
}

void check_sky(const sky_routine *k, long n, uint64_t seed, sampling_result *r)
{
    int ncells = 4 * k->w * k->h, i, j, edge;
    double *obs = calloc((size_t)ncells, sizeof(double)), *expct = calloc((size_t)ncells, sizeof(double));
    image im;
    pcg32 rng = case_stream(seed, 0);
    sky s;
    long m;
    memset(&s, 0, sizeof s);
    im.w = k->w, im.h = k->h, im.px = malloc(sizeof(float) * 3 * (size_t)ncells / 4);
    if (!obs || !expct || !im.px) goto out_of_memory;
    for (j = 0; j < k->h; j++)
        for (i = 0; i < k->w; i++) {
            vec3 c = test_radiance(i, j, k->w, k->h);
            im.px[3 * (j * k->w + i)] = c.x, im.px[3 * (j * k->w + i) + 1] = c.y, im.px[3 * (j * k->w + i) + 2] = c.z;
        }
    if (sky_from_image(&s, &im)) goto out_of_memory;
    expected(k, &s, n, expct, r);
    r->has_geom = 1, r->geom_tol = 1e-5;
    for (m = 0; m < n; m++) {
        float pdf, u2;
        double u1 = pcg32_double(&rng);
        vec3 L, w;
        u2 = pcg32_float(&rng);
        w = k->sample(&s, u1, u2, &pdf, &L);
        r->geom_gap = fmax(r->geom_gap, fabs(v3_length(w) - 1.0));
        obs[cell_of(w, k->w, k->h, &edge)] += 1.0;
        if (m < SKY_SPOT_CHECKS && !edge) r->pdf_checked++, r->pdf_mismatch += !(pdf > 0.0f) || fabsf(pdf - k->pdf(&s, w)) > 1e-6f * pdf;
    }
    r->n = n, r->chi2 = chi2_test(obs, expct, ncells);
    snprintf(r->cells, sizeof r->cells, "%d x %d pixels x 2 x 2 cells in (cos theta, phi)", k->w, k->h);
    sky_free(&s), free(im.px), free(obs), free(expct);
    return;
out_of_memory:
    snprintf(r->cells, sizeof r->cells, "out of memory"), r->outside = 1;
    free(im.px), free(obs), free(expct);
}
