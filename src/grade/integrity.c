/* integrity.c — copies and images made from the reference (see integrity.h).
 *
 * The scatter test. Let d = image - ref per pixel-channel and v the reference's variance of its pixel
 * mean (REF_var.pfm). If the image was rendered independently of the reference, the reference's own
 * error is in d whatever the image's: E[d^2] = var(image) + var(ref) + bias^2 >= var(ref) = E[v]
 * (v is the sample variance, unbiased). So sum d^2 >= sum v is expected even from an image with a
 * million samples per pixel (it is the truth, and d is the reference's error). Only an image that
 * shares the reference's noise — the reference copied, scaled by a factor close to 1, blended with
 * something, denoised — has sum d^2 well below sum v. Over the n pixel-channels where v > 0, with
 * a = d^2 - v, z = sum a / sqrt(sum a^2) is a self-normalised sum, close to normal for the thousands
 * of terms of an image; the image is flagged when z < -3.09 (level 1e-3, one-sided, against the
 * least favourable honest image: the exact truth) and sum d^2 < sum v / 2 (far below, not a
 * fluctuation of a heavy-tailed reference). A copy has d = 0: ratio 0, z = -sqrt(n_eff). */
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
    double sd2 = 0.0, sv = 0.0, sa2 = 0.0;
    memset(s, 0, sizeof *s);
    for (i = 0; i < n; i++) {
        double v = var->px[i], d = (double)img->px[i] - ref->px[i], a = d * d - v;
        if (!(v > 0.0)) continue;
        sd2 += d * d, sv += v, sa2 += a * a, s->n++;
    }
    if (s->n < 2 || !(sv > 0.0)) return;
    s->ratio = sd2 / sv;
    s->z = sa2 > 0.0 ? (sd2 - sv) / sqrt(sa2) : 0.0;
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
    snprintf(out, cap, "too close to the reference: the squared difference is %.3g times the reference's own variance (about 1 "
             "or more for an image rendered independently; z %.1f, level %g): the reference copied, scaled, blended or denoised?",
             s.ratio, s.z, GRADE_SCATTER_ALPHA);
    return 1;
}
