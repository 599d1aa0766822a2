/* imgstat.c — Z-tests between renders with known per-pixel variances. */
#include "stats/imgstat.h"
#include <math.h>
#include <string.h>
#include "stats/significance.h"
#include "stats/tdist.h"

static double zscore(double d, double var) { return var > 0.0 ? d / sqrt(var) : (d == 0.0 ? 0.0 : HUGE_VAL); }

/* Float rounding, a few ulps of the values, is allowed on top of the noise: an estimator that is
 * exact up to rounding (the BRDF-sampled furnace: every sample is a^k) has zero sample variance,
 * and its last-bit differences must not count as bias. Rounding errors may all lean the same way,
 * so over a block or the image their bounds add up linearly, not in quadrature. */
#define ROUNDING 4e-7
static double rounding(double a, double b) { return ROUNDING * (fabs(a) + fabs(b)); }

static void block_test(zreport *r, const image *a, const image *va, const image *b, const image *vb, int B)
{
    int bx, by, ch, x, y, bw = a->w / B, bh = a->h / B;
    r->nblocks = bw * bh * 3;
    r->block_zcrit = sidak_zcrit(r->alpha, r->nblocks);
    for (by = 0; by < bh; by++)
        for (bx = 0; bx < bw; bx++)
            for (ch = 0; ch < 3; ch++) {
                double d = 0.0, v = 0.0, rsum = 0.0, z;
                for (y = by * B; y < (by + 1) * B; y++)
                    for (x = bx * B; x < (bx + 1) * B; x++) {
                        size_t i = 3 * ((size_t)y * a->w + x) + ch;
                        d += (double)a->px[i] - b->px[i];
                        v += (double)va->px[i] + vb->px[i];
                        rsum += rounding(a->px[i], b->px[i]);
                    }
                z = fabs(zscore(d, v + rsum * rsum));
                if (z > r->block_zmax) r->block_zmax = z;
                if (z > r->block_zcrit) r->nblocks_fail++;
            }
}

/* The per-pixel test: |z| beyond the critical value, or with few degrees of freedom its t tail below the level. */
static int pixel_fails(const zreport *r, double d, double v1, double dof1, double v2, double dof2, double rnd2)
{
    double dof, level;
    if (dof1 <= 0.0 && dof2 <= 0.0) return fabs(zscore(d, v1 + v2 + rnd2)) > r->pixel_zcrit;
    dof = welch_dof(v1, dof1, v2, dof2);   /* the rounding term is exact: infinitely many */
    level = sidak_level(r->alpha, r->npix);
    if (v1 + v2 + rnd2 <= 0.0) return d != 0.0;
    return t_two_sided_tail(d / sqrt(v1 + v2 + rnd2), dof) < level;
}

int zreport_compute_dof(zreport *r, const image *a, const image *va, double dof_a, const image *b, const image *vb,
                        double dof_b, double alpha, int block)
{
    size_t i, n = (size_t)a->w * a->h;
    double d[3] = {0, 0, 0}, v[3] = {0, 0, 0}, rs[3] = {0, 0, 0}, mb[3] = {0, 0, 0};
    int ch;
    memset(r, 0, sizeof *r);
    if (a->w != b->w || a->h != b->h || va->w != a->w || va->h != a->h || vb->w != a->w || vb->h != a->h) return 1;
    r->alpha = alpha;
    r->npix = (int)(3 * n);
    r->pixel_zcrit = sidak_zcrit(alpha, r->npix);
    for (i = 0; i < 3 * n; i++) {
        double di = (double)a->px[i] - b->px[i], vi = (double)va->px[i] + vb->px[i], ri = rounding(a->px[i], b->px[i]);
        if (pixel_fails(r, di, va->px[i], dof_a, vb->px[i], dof_b, ri * ri)) r->npix_fail++;
        d[i % 3] += di;
        v[i % 3] += vi;
        rs[i % 3] += ri;
        mb[i % 3] += b->px[i];
    }
    r->image_zcrit = sidak_zcrit(alpha, 3);
    for (ch = 0; ch < 3; ch++) {
        r->image_z[ch] = zscore(d[ch], v[ch] + rs[ch] * rs[ch]);
        r->mean_diff[ch] = d[ch] / (double)n;
        r->mean_sd[ch] = sqrt(v[ch] + rs[ch] * rs[ch]) / (double)n;
        r->mean_b[ch] = mb[ch] / (double)n;
    }
    if (block > 0) block_test(r, a, va, b, vb, block);
    return 0;
}
