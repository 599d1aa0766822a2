/* integrity.c — copies and images made from the reference (see integrity.h).
 *
 * The scatter test. Let d = image - ref per pixel-channel and v the reference's variance of its pixel
 * mean (REF_var.pfm, `render --variance`). If the image was rendered independently of the reference,
 * the reference's own error is in d whatever the image's: E[d^2] = var(image) + var(ref) + bias^2
 * >= var(ref), so u = d^2 / v has a mean of about 1 or more even for an image with a million samples
 * per pixel (it is then the truth, d is the reference's error and u its Student t^2, of mean
 * dof/(dof-2) > 1). Only an image that shares the reference's noise (the reference copied, scaled by a
 * factor close to 1, blended with something, denoised) has u well below 1. Over the n pixel-channels
 * where v > 0, the mean of u is tested against 1 with t = (mean u - 1) / (sd(u) / sqrt(n)); the image
 * is flagged when t < -3.09 (level 1e-3, one-sided, normal: thousands of terms) and mean u < 3/4 (well
 * below 1, not a fluctuation of a heavy-tailed reference). Measured on ref/cornell.pfm (4096 spp),
 * 64x64: honest renders at 4, 64, 1024 and 8192 spp gave mean u 637-674, 27-33, 2.5-2.6 and 1.23
 * (t +10.7 or more); the copy 0, the copy times 1.001 0.15 (t -44), the reference averaged with a
 * 1024-spp render 0.62 (t -42), with a 64-spp render 6.8 (not flagged: its own noise is in it). */
#include "grade/integrity.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "math/sha256.h"

void grade_pixel_hash(const image *img, unsigned char digest[32])
{
    sha256_ctx c;
    int size[2];
    size[0] = img->w, size[1] = img->h;
    sha256_init(&c);
    sha256_update(&c, size, sizeof size);
    sha256_update(&c, img->px, 3 * sizeof(float) * (size_t)img->w * img->h);
    sha256_final(&c, digest);
}

void grade_scatter_test(grade_scatter *s, const image *img, const image *ref, const image *var)
{
    size_t i, n = 3 * (size_t)img->w * img->h;
    double su = 0.0, su2 = 0.0, sd;
    memset(s, 0, sizeof *s);
    for (i = 0; i < n; i++) {
        double v = var->px[i], d = (double)img->px[i] - ref->px[i], u = d * d / v;
        if (!(v > 0.0) || !isfinite(u)) continue;
        su += u, su2 += u * u, s->n++;
    }
    if (s->n < 2) return;
    s->ratio = su / s->n;
    sd = sqrt(fmax(0.0, (su2 - s->n * s->ratio * s->ratio) / (s->n - 1)));
    s->z = sd > 0.0 ? (s->ratio - 1.0) / (sd / sqrt((double)s->n)) : s->ratio < 1.0 ? -HUGE_VAL : 0.0;
    s->low = s->z < -GRADE_SCATTER_Z && s->ratio < GRADE_SCATTER_RATIO;
}

int grade_integrity_remark(char *out, size_t cap, const image *img, const image *ref, const image *var)
{
    grade_scatter s;
    out[0] = '\0';
    if (img->w != ref->w || img->h != ref->h) return 0;
    if (!memcmp(img->px, ref->px, 3 * sizeof(float) * (size_t)img->w * img->h)) {
        snprintf(out, cap, "identical to the reference, pixel for pixel (a copy)");
        return 1;
    }
    if (!var) return 0;
    grade_scatter_test(&s, img, ref, var);
    if (!s.low) return 0;
    snprintf(out, cap, "too close to the reference: its squared difference is %.3g times the reference's own variance (about 1 "
             "or more for an image rendered independently; t %.1f, level %g): the reference copied, scaled, blended or denoised?",
             s.ratio, s.z, GRADE_SCATTER_ALPHA);
    return 1;
}
