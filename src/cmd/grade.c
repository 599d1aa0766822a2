/* grade.c — is the difference between a student's image and a reference noise or bias?
 *
 * Both images are Monte Carlo estimates: per pixel-channel, d = image - ref has expectation 0 when
 * the student's estimator is unbiased (same expectation as the reference's), whatever its variance.
 * The student's image comes without a variance, and the student's estimator may be noisier or less
 * noisy than the reference's, so the noise must be measured on d itself. Pixels are independent
 * (each has its own random stream, in both renders), so it can be: over a group of m pixels, the
 * scatter of d estimates the noise of the group's mean d. Subtracting the reference removes the
 * picture (edges, shading), so what scatters is the noise of both renders. Averaging m pixels
 * divides the noise by sqrt(m) but leaves a bias as it is: that is what tells them apart.
 *
 * The image is cut into B x B blocks (B = max(8, min(w, h) / 16) unless --block; the last row and
 * column of blocks take the leftover pixels). Per block and channel: the mean d, the mean ref, the
 * sample variance s^2 of d. Then two tests, each per channel (R, G, B):
 *   blocks: t = mean d / sqrt(s'^2 / m), against Student's t with m - 1 degrees of freedom. Finds a
 *     bias confined to a region and says where. s'^2 is the larger of the block's own s^2 and s^2
 *     pooled over the 3 x 3 blocks around it (sum (m-1) s^2 / sum (m-1)); see "heavy tails".
 *   whole image: d = eps * ref fitted to the block means by weighted least squares,
 *     eps = sum w mean_d / sum w mean_ref,  w = mean_ref / (noise of the block mean),
 *     var(eps) = sum w^2 noise / (sum w mean_ref)^2,  z = eps / sd(eps), normal (many blocks).
 *     eps is the image's relative bias ("2% too bright"), each block weighted by how precisely it
 *     measures it; a plain mean of d would weigh noisy pixels as much as clean ones, and finds a 2%
 *     bias at 64 spp on 64 x 64 pixels with z ~ 3 instead of ~ 9. The weight's noise comes from
 *     the neighbours only (s^2 pooled over the 3 x 3 blocks without the block itself), so that
 *     weight and mean d of a block are independent and E[z] = 0 without bias. Blocks whose
 *     neighbours are exact (no noise) get no weight: the block test judges them.
 * alpha (default 0.01) is split in two: alpha/2 for the 3 whole-image tests, alpha/2 for the
 * 3 x nblocks block tests, each family with Sidak's correction (per-test level
 * 1 - (1 - alpha/2)^(1/k)): an unbiased image fails with probability at most alpha.
 * Float rounding (a few ulps of the values, as in imgstat.c) is added to every standard error,
 * so that identical deterministic pixels (emitters seen directly) count as equal.
 *
 * Heavy tails. At 4 spp a few pixels hold rare large samples (paths that found the light after a
 * long walk): d is skewed. A block that drew none of them has a mean d below 0 and, with its own
 * s alone, looks precise: on 64 x 64 Cornell boxes at 4 spp, 3 of 20 unbiased renders failed that
 * way (a block "darker" with |t| up to 5.8). With s' >= s pooled over the neighbourhood, which
 * did draw large samples, the largest block |t| of 20 renders was 2.97 (limit 4.54). A block
 * that drew one keeps its own, larger, s: t stays small (self-normalised). Measured false alarms
 * and power are in tests/test_grade.sh.
 *
 * With --var REF_VAR.pfm (the reference's variance of the pixel mean, `render --variance`),
 * --spp N and --ref-spp M, a per-pixel Z-test is also run, z = d / sqrt(var_ref (1 + M/N)),
 * which assumes the student used the reference's estimator (variance of the mean var_ref M/N).
 * That is not the student's assumption to make, and one pixel at 4 spp is far from normal, so
 * this test is printed for information and is not part of the verdict. */
#include "cmd/grade.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "math/vec.h"
#include "stats/imgstat.h"
#include "stats/significance.h"

/* Rounding allowed per value, relative (see imgstat.c): added linearly over a mean. */
#define GRADE_ROUNDING 4e-7
#define GRADE_MIN_BLOCK 8
#define GRADE_POOL 1           /* the noise of a block is pooled over (2 GRADE_POOL + 1)^2 blocks */

/* mean / standard error, with rounding added to the error; 0/0 is 0 (identical values) */
static double t_stat(double mean, double se2)
{
    if (se2 > 0.0) return mean / sqrt(se2);
    return mean == 0.0 ? 0.0 : copysign(HUGE_VAL, mean);
}

static double d_at(const image *img, const image *ref, size_t i)
{
    double a = img->px[i];
    return isfinite(a) ? a - ref->px[i] : 0.0;   /* NaN/inf pixels are counted apart */
}

/* Mean of d and of ref, sample variance of d and the rounding bound of the mean, over the pixels
 * [x0,x1) x [y0,y1) of one channel; two passes for accuracy. */
static void block_stats(grade_block *b, const image *img, const image *ref, int ch)
{
    double sum = 0.0, rsum = 0.0, ss = 0.0, rounding = 0.0, mean, m;
    int x, y;
    m = (double)(b->x1 - b->x0) * (b->y1 - b->y0);
    for (y = b->y0; y < b->y1; y++)
        for (x = b->x0; x < b->x1; x++) {
            size_t i = 3 * ((size_t)y * img->w + x) + ch;
            sum += d_at(img, ref, i);
            rsum += ref->px[i];
            rounding += GRADE_ROUNDING * (fabs(ref->px[i]) + fabs(ref->px[i] + d_at(img, ref, i)));
        }
    mean = sum / m;
    for (y = b->y0; y < b->y1; y++)
        for (x = b->x0; x < b->x1; x++) {
            double e = d_at(img, ref, 3 * ((size_t)y * img->w + x) + ch) - mean;
            ss += e * e;
        }
    b->diff[ch] = mean;
    b->ref[ch] = rsum / m;
    b->var[ch] = m > 1 ? ss / (m - 1.0) : 0.0;
    b->round[ch] = rounding / m;
    b->df = (int)m - 1;
}

/* The within-block variance of d pooled over the blocks around (bx, by): sum of (m - 1) s^2 over
 * sum of (m - 1), with or without the block itself. */
static double pooled_var(const grade_report *r, int bx, int by, int ch, int self)
{
    double ss = 0.0, df = 0.0;
    int x, y;
    for (y = by - GRADE_POOL; y <= by + GRADE_POOL; y++)
        for (x = bx - GRADE_POOL; x <= bx + GRADE_POOL; x++)
            if (x >= 0 && y >= 0 && x < r->nbx && y < r->nby && (self || x != bx || y != by)) {
                const grade_block *b = &r->blocks[y * r->nbx + x];
                ss += b->df * b->var[ch];
                df += b->df;
            }
    return df > 0.0 ? ss / df : 0.0;
}

/* The variance of a block's mean d: the larger of its own and its neighbourhood's pixel variance,
 * over m, plus rounding. */
static double block_noise(const grade_report *r, int bx, int by, int ch)
{
    const grade_block *b = &r->blocks[by * r->nbx + bx];
    double var = fmax(b->var[ch], pooled_var(r, bx, by, ch, 1));
    return var / (b->df + 1.0) + b->round[ch] * b->round[ch];
}

static void test_blocks(grade_report *r, const image *img, const image *ref)
{
    int bx, by, ch;
    r->block_level = sidak_level(r->alpha / 2.0, 3L * r->nblocks);
    for (by = 0; by < r->nby; by++)
        for (bx = 0; bx < r->nbx; bx++) {
            grade_block *b = &r->blocks[by * r->nbx + bx];
            b->x0 = bx * r->block;
            b->y0 = by * r->block;
            b->x1 = bx == r->nbx - 1 ? r->w : b->x0 + r->block;
            b->y1 = by == r->nby - 1 ? r->h : b->y0 + r->block;
            for (ch = 0; ch < 3; ch++) block_stats(b, img, ref, ch);
        }
    r->block_tcrit = r->blocks[0].df >= 1 ? t_critical(r->block_level, r->blocks[0].df) : 0.0;   /* a full block */
    for (by = 0; by < r->nby; by++)
        for (bx = 0; bx < r->nbx; bx++) {
            grade_block *b = &r->blocks[by * r->nbx + bx];
            double tbest = 0.0;
            for (ch = 0; ch < 3; ch++) {
                b->noise[ch] = block_noise(r, bx, by, ch);
                b->t[ch] = b->df >= 1 ? t_stat(b->diff[ch], b->noise[ch]) : 0.0;
                if (fabs(b->t[ch]) > r->block_tmax) r->block_tmax = fabs(b->t[ch]);
                if (b->df >= 1 && student_t_tail(b->t[ch], b->df) < r->block_level && fabs(b->t[ch]) > tbest) {
                    tbest = fabs(b->t[ch]);
                    b->sign = b->t[ch] > 0 ? 1 : -1;
                }
            }
            r->nbrighter += b->sign > 0;
            r->ndarker += b->sign < 0;
        }
}

/* The weight of a block in the relative-bias fit, ref / (noise of its mean), the noise taken from
 * its neighbours only so that the weight does not depend on the block's own d. 0 for a block whose
 * neighbours are exact (noise within rounding): the block test judges those. */
static double fit_weight(const grade_report *r, int bx, int by, int ch)
{
    const grade_block *b = &r->blocks[by * r->nbx + bx];
    double m = b->df + 1.0, v = (r->nblocks > 1 ? pooled_var(r, bx, by, ch, 0) : b->var[ch]) / m;
    return v > b->round[ch] * b->round[ch] ? b->ref[ch] / v : 0.0;
}

/* Whole image, per channel: the relative bias eps of d = eps * ref, fitted to the block means by
 * weighted least squares, eps = sum w d / sum w ref, with var(eps) = sum w^2 noise / (sum w ref)^2. */
static void test_image(grade_report *r)
{
    int bx, by, ch;
    double area = (double)r->w * r->h;
    r->image_level = sidak_level(r->alpha / 2.0, 3);
    r->image_zcrit = normal_quantile(1.0 - 0.5 * r->image_level);
    for (ch = 0; ch < 3; ch++) {
        double wd = 0.0, wref = 0.0, wvar = 0.0;
        for (by = 0; by < r->nby; by++)
            for (bx = 0; bx < r->nbx; bx++) {
                const grade_block *b = &r->blocks[by * r->nbx + bx];
                double w = fit_weight(r, bx, by, ch), m = (double)(b->x1 - b->x0) * (b->y1 - b->y0);
                r->image_nfit += w > 0.0;
                wd += w * b->diff[ch];
                wref += w * b->ref[ch];
                wvar += w * w * b->noise[ch];
                r->image_diff[ch] += m * b->diff[ch] / area;
                r->image_ref[ch] += m * b->ref[ch] / area;
            }
        r->image_eps[ch] = wref > 0.0 ? wd / wref : 0.0;
        r->image_eps_se[ch] = wref > 0.0 ? sqrt(wvar) / wref : 0.0;
        r->image_z[ch] = wref > 0.0 ? t_stat(wd, wvar) : 0.0;
        if (fabs(r->image_z[ch]) > r->image_zcrit) r->image_fail = 1;
    }
}

/* Information only: z per pixel-channel with the student's variance taken as var_ref M / N. */
static void test_pixels(grade_report *r, const image *img, const image *ref, const image *var, const grade_opts *o)
{
    size_t i, n = 3 * (size_t)img->w * img->h;
    double k = 1.0 + (double)o->ref_spp / o->spp;
    r->pixel_test = 1;
    r->pixel_n = (long)n;
    r->pixel_zcrit = sidak_zcrit(r->alpha, (long)n);
    for (i = 0; i < n; i++) {
        double d = d_at(img, ref, i), rounding = GRADE_ROUNDING * (fabs(ref->px[i]) + fabs(ref->px[i] + d));
        if (fabs(t_stat(d, var->px[i] * k + rounding * rounding)) > r->pixel_zcrit) r->pixel_fail++;
    }
}

int grade_compute(grade_report *r, const image *img, const image *ref, const image *ref_var, const grade_opts *o)
{
    size_t i;
    memset(r, 0, sizeof *r);
    if (img->w != ref->w || img->h != ref->h) return 1;
    if (ref_var && (ref_var->w != ref->w || ref_var->h != ref->h)) return 1;
    r->alpha = o->alpha;
    r->w = img->w;
    r->h = img->h;
    r->block = o->block > 0 ? o->block : (img->w < img->h ? img->w : img->h) / 16;
    if (r->block < GRADE_MIN_BLOCK && o->block <= 0) r->block = GRADE_MIN_BLOCK;
    r->nbx = img->w / r->block > 0 ? img->w / r->block : 1;
    r->nby = img->h / r->block > 0 ? img->h / r->block : 1;
    r->nblocks = r->nbx * r->nby;
    r->blocks = calloc((size_t)r->nblocks, sizeof *r->blocks);
    if (!r->blocks) return 1;
    for (i = 0; i < 3 * (size_t)img->w * img->h; i++) r->nonfinite += !isfinite(img->px[i]);
    test_blocks(r, img, ref);
    test_image(r);
    if (ref_var && o->spp > 0 && o->ref_spp > 0) test_pixels(r, img, ref, ref_var, o);
    return 0;
}

void grade_free(grade_report *r)
{
    free(r->blocks);
    r->blocks = NULL;
}

int grade_failed(const grade_report *r)
{
    return r->image_fail || r->nbrighter > 0 || r->ndarker > 0 || r->nonfinite > 0;
}

int grade_heatmap(image *out, const grade_report *r, const image *ref)
{
    static const float red[3] = {0.9f, 0.03f, 0.03f}, blue[3] = {0.03f, 0.1f, 0.9f};
    int b, x, y, ch;
    if (img_alloc(out, r->w, r->h)) return 1;
    for (b = 0; b < r->nblocks; b++) {
        const grade_block *k = &r->blocks[b];
        for (y = k->y0; y < k->y1; y++)
            for (x = k->x0; x < k->x1; x++) {
                size_t i = 3 * ((size_t)y * r->w + x);
                float Y = luminance(v3(ref->px[i], ref->px[i + 1], ref->px[i + 2]));
                float grey = 0.5f * fminf(fmaxf(Y, 0.0f), 1.0f);   /* dimmed so that colours stand out */
                for (ch = 0; ch < 3; ch++)
                    out->px[i + ch] = k->sign == 0 ? grey : 0.8f * (k->sign > 0 ? red : blue)[ch] + 0.2f * grey;
            }
    }
    return 0;
}
