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
 * Exact pixels. Where the reference has no noise at all (the interior of the background, of an
 * emitter without reflectance: the pixel and its 8 neighbours equal bit for bit and, with
 * REF_var.pfm, of variance 0), every unbiased renderer gives the same value: those pixels are
 * compared as numbers, |d| <= 1e-4 |ref| + 1e-6 x the reference's mean, and left out of the groups
 * below. (A noisy pixel is never equal to its 8 neighbours, but a pixel where the reference drew
 * only zeros can be: a reference needs enough samples that its dark pixels are lit.)
 *
 * The noisy pixels form two families of groups, each tested per channel (R, G, B) with Student's
 * t = mean d / sqrt(s'^2 / m), m - 1 degrees of freedom:
 *   blocks: B x B pixels (B = max(8, min(w, h) / 16) unless --block; the last row and column of
 *     blocks take the leftover pixels). Finds a bias confined to a region and says where. s'^2 is
 *     the larger of the block's own s^2 and s^2 pooled over the 3 x 3 blocks around it (sum (m-1) s^2
 *     / sum (m-1)); see "heavy tails".
 *   levels: the pixels whose reference luminance (the mean of their 8 neighbours', see
 *     neighbours_luminance) lies in one octave [2^k, 2^(k+1)), wherever they are. A bias that follows the picture (the lamp seen directly missing, highlights clamped)
 *     is the same for every pixel of a level, so the level's scatter stays the noise's; in a block
 *     that mixes the lamp and the ceiling it would be counted as noise, and a lamp of 20 pixels in
 *     a 64x64 image would go unseen. Only the pixels brighter than the image's mean are put in
 *     levels: bias in a few pixels is bias in bright ones (emitters, highlights, values clamped),
 *     and dark pixels are where rare-event noise (light found by chance) hides unseen in a whole
 *     level: on mis-plates at 1-16 spp with --light area against a --light solid-angle reference,
 *     4 of 16 honest images failed on a dark level. Blocks and the whole image judge dark pixels.
 *   whole image: d = eps * ref fitted to the block means by weighted least squares,
 *     eps = sum w mean_d / sum w mean_ref,  w = mean_ref / (noise of the block mean),
 *     var(eps) = sum w^2 noise / (sum w mean_ref)^2,  z = eps / sd(eps), normal (many blocks).
 *     eps is the image's relative bias ("2% too bright"), each block weighted by how precisely it
 *     measures it; a plain mean of d would weigh noisy pixels as much as clean ones, and finds a 2%
 *     bias at 64 spp on 64 x 64 pixels with z ~ 3 instead of ~ 9. The weight's noise comes from
 *     the neighbours only (s^2 pooled over the 3 x 3 blocks without the block itself), so that
 *     weight and mean d of a block are independent and E[z] = 0 without bias.
 * The blocks are tested at several scales: B, 2B, 4B... as long as the image holds 2 x 2 of them (a
 * bias over a quarter of the image is too thin for 8x8 blocks, too local for the whole image).
 *   whole image, unweighted: the plain mean of d over the noisy pixels, Student's t on their own
 *     scatter (test_plain): what a black image at low spp cannot hide from.
 * alpha (default 0.01) is split in three: alpha/3 for the 6 whole-image tests, alpha/3 for the
 * blocks (shared equally by the scales, 3 x nblocks tests each), alpha/3 for the 3 x nlevels
 * level tests, each family with Sidak's correction (per-test level 1 - (1 - alpha/3)^(1/k)): an unbiased image fails with probability at
 * most alpha (the exact pixels, compared as numbers, never fail it). Float rounding (a few ulps of
 * the values) is added to every standard error.
 *
 * Heavy tails. At 4 spp a few pixels hold rare large samples (paths that found the light after a
 * long walk): d is skewed. A block that drew none of them has a mean d below 0 and, with its own
 * s alone, looks precise: on 64 x 64 Cornell boxes at 4 spp, 3 of 20 unbiased renders failed that
 * way (a block "darker" with |t| up to 5.8). With s' >= s pooled over the neighbourhood, which
 * did draw large samples, the largest block |t| of 20 renders was 2.97 (limit 4.54). A block
 * that drew one keeps its own, larger, s: t stays small (self-normalised). Levels hold hundreds
 * of pixels, which draw their share. Measured false alarms and power: docs/grading.md.
 *
 * With --var REF_VAR.pfm (the reference's variance of the pixel mean, `render --variance`),
 * --spp N and --ref-spp M, a per-pixel Z-test is also run, z = d / sqrt(var_ref (1 + M/N)),
 * which assumes the student used the reference's estimator (variance of the mean var_ref M/N).
 * That is not the student's assumption to make, and one pixel at 4 spp is far from normal, so
 * this test is printed for information and is not part of the verdict. */
#include "grade/grade.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "math/vec.h"
#include "stats/imgstat.h"
#include "stats/significance.h"
#include "stats/tdist.h"

/* Rounding allowed per value, relative (see imgstat.c): added linearly over a mean. */
#define GRADE_ROUNDING 4e-7
#define GRADE_MIN_BLOCK 8
#define GRADE_POOL 1           /* the noise of a block is pooled over (2 GRADE_POOL + 1)^2 blocks */
#define GRADE_LEVELS 48        /* level 0: luminance <= 0; level k: [2^(k-25), 2^(k-24)), ends open */
#define GRADE_EXACT_REL 1e-4   /* an exact pixel may differ by this much, relative... */
#define GRADE_EXACT_ABS 1e-6   /* ... plus this much of the reference's mean */
#define GRADE_HITS_RADIUS 5    /* the window (11 x 11) where the dimmest lit pixel of a black one is sought */

static int imin(int a, int b) { return a < b ? a : b; }
static int imax(int a, int b) { return a > b ? a : b; }

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Moves the k-th smallest of q[0..n) (from 0) to q[k], the smaller ones before it, the larger after:
 * quickselect, expected O(n) where sorting was 80% of a failing grade's time (its diagnosis grades
 * some twenty hypotheses). An image made to defeat the middle-of-three pivot gets 2 log2(n) + 8
 * rounds, then the rest is sorted: the worst case stays O(n log n). No NaN reaches here (grade refuses
 * them). */
static void select_kth(double *q, size_t n, size_t k)
{
    size_t lo = 0, hi = n - 1, rounds = 8, m;
    for (m = n; m > 1; m >>= 1) rounds += 2;
    while (hi > lo) {
        size_t i = lo, j = hi;
        double a = q[lo], b = q[lo + (hi - lo) / 2], c = q[hi];
        double pivot = a < b ? (b < c ? b : a < c ? c : a) : (a < c ? a : b < c ? c : b);
        if (rounds-- == 0) { qsort(q + lo, hi - lo + 1, sizeof *q, cmp_double); return; }
        while (i <= j) {   /* Hoare: ends with q[lo..j] <= pivot <= q[i..hi], j < i */
            while (q[i] < pivot) i++;
            while (q[j] > pivot) j--;
            if (i <= j) {
                double t = q[i];
                q[i++] = q[j];
                q[j] = t;
                if (j-- == lo) break;
            }
        }
        if (k <= j && j >= lo && j < hi) hi = j;
        else if (k >= i) lo = i;
        else return;   /* q[j+1..i-1] all equal the pivot, k among them */
    }
}

/* The median of q[0..n), n >= 1 (q is reordered). */
static double median(double *q, size_t n)
{
    size_t k = n / 2, i;
    double below;
    select_kth(q, n, k);
    if (n % 2) return q[k];
    for (below = q[0], i = 1; i < k; i++) below = q[i] > below ? q[i] : below;
    return 0.5 * (below + q[k]);
}

/* mean / standard error, with rounding added to the error; 0/0 is 0 (identical values) */
static double t_stat(double mean, double se2)
{
    if (se2 > 0.0) return mean / sqrt(se2);
    return mean == 0.0 ? 0.0 : copysign(HUGE_VAL, mean);
}

static double ref_luminance(const image *ref, size_t p)
{
    return luminance(v3(ref->px[3 * p], ref->px[3 * p + 1], ref->px[3 * p + 2]));
}

static int zero_variance(const image *var, size_t p)
{
    return var->px[3 * p] == 0.0f && var->px[3 * p + 1] == 0.0f && var->px[3 * p + 2] == 0.0f;
}

/* The number of light-finding samples a pixel of the reference drew, estimated from its mean m and
 * the variance of its mean v: for a pixel whose samples are c with probability q and 0 otherwise,
 * m^2 / v = n q / (1 - q), about the hits among its n samples (the largest over the channels). 0
 * for a black pixel; huge for a pixel of variance 0 that is not black (nothing random there). */
static float hits_of(const image *ref, const image *var, size_t p)
{
    double h = 0.0;
    int ch;
    for (ch = 0; ch < 3; ch++) {
        double m = ref->px[3 * p + ch], v = var->px[3 * p + ch];
        if (m != 0.0) h = fmax(h, v > 0.0 ? m * m / v : 1e30);
    }
    return (float)fmin(h, 1e30);
}

/* dst = the smallest positive value of src within GRADE_HITS_RADIUS along one axis (stride step,
 * len values per line, lines lines of stride pitch), +inf where none is positive. */
static void min_positive_1d(float *dst, const float *src, int len, int lines, size_t step, size_t pitch)
{
    int i, j, k;
    for (j = 0; j < lines; j++)
        for (i = 0; i < len; i++) {
            float m = HUGE_VALF;
            for (k = imax(0, i - GRADE_HITS_RADIUS); k <= imin(len - 1, i + GRADE_HITS_RADIUS); k++) {
                float v = src[j * pitch + k * step];
                if (v > 0.0f && v < m) m = v;
            }
            dst[j * pitch + i * step] = m;
        }
}

/* Per pixel, the hits of the dimmest lit pixel of the reference within GRADE_HITS_RADIUS (a square
 * window, two passes): what a black pixel there would have drawn, had it any light. NULL when out
 * of memory. */
static float *dimmest_lit(const grade_report *r, const image *ref, const image *var)
{
    size_t p, n = (size_t)r->w * r->h;
    float *h = malloc(n * sizeof *h), *t = malloc(n * sizeof *t);
    if (!h || !t) { free(h); free(t); return NULL; }
    for (p = 0; p < n; p++) h[p] = hits_of(ref, var, p);
    min_positive_1d(t, h, r->w, r->h, 1, (size_t)r->w);
    min_positive_1d(h, t, r->h, r->w, (size_t)r->w, 1);
    free(t);
    return h;
}

/* 1 if the pixel and its 8 neighbours equal bit for bit in the reference and (with the variance)
 * are each of variance 0. */
static int flat_at(const grade_report *r, const image *ref, const image *var, int x, int y)
{
    size_t p = (size_t)y * r->w + x;
    int u, v, flat = !var || zero_variance(var, p);
    for (v = y - 1; v <= y + 1 && flat; v++)
        for (u = x - 1; u <= x + 1 && flat; u++) {
            size_t q = (size_t)v * r->w + u;
            if (u < 0 || v < 0 || u >= r->w || v >= r->h) continue;
            flat = !memcmp(&ref->px[3 * p], &ref->px[3 * q], 3 * sizeof(float)) && (!var || zero_variance(var, q));
        }
    return flat;
}

/* Exact pixels: where the reference shows that the value cannot vary. Flat (flat_at) is necessary:
 * in the interior of the background or of an emitter without reflectance, every unbiased renderer
 * gives the same value. It is not enough for a black pixel: where light is rare, a reference can
 * draw only zeros (a deep penumbra at 2,044 spp, a third of its neighbours lit by a few samples
 * each) and an honest image that found the light there would fail. A black flat pixel is exact only
 * where zero hits are themselves unlikely: the dimmest lit pixel around it drew lambda hits, and
 * exp(-lambda) is below the level alpha / (black flat pixels) (Bonferroni). Without the variance the
 * hits are unknown and no black pixel is exact. The others are judged in their groups, as rare
 * events, with the noise floor of their neighbours (floor_var). */
static int mark_exact(grade_report *r, const image *ref, const image *var)
{
    size_t p, n = (size_t)r->w * r->h;
    long black = 0;
    float *lit = NULL;
    double lambda;
    r->exact = calloc(n, 1);
    if (!r->exact) return 1;
    r->exact_from_var = var != NULL;
    for (p = 0; p < n; p++) {
        r->exact[p] = (unsigned char)flat_at(r, ref, var, (int)(p % (size_t)r->w), (int)(p / (size_t)r->w));
        if (r->exact[p] && ref->px[3 * p] == 0.0f && ref->px[3 * p + 1] == 0.0f && ref->px[3 * p + 2] == 0.0f) {
            r->exact[p] = 2;   /* black and flat: decided below */
            black++;
        }
    }
    if (black && var && !(lit = dimmest_lit(r, ref, var))) return 1;
    lambda = -log(r->alpha / (double)(black > 0 ? black : 1));
    for (p = 0; p < n; p++)
        if (r->exact[p] == 2) {
            r->exact[p] = lit && lit[p] >= lambda && lit[p] < HUGE_VALF;
            r->black_rare += !r->exact[p];
        }
    free(lit);
    return 0;
}

/* The variance the noise floor uses: the reference's, and where it is 0 at a pixel that is not
 * exact (a black pixel where light is rare, the reference drew none), the smallest positive one
 * within GRADE_HITS_RADIUS, per channel: a rare event there is as likely as at its dimmest lit
 * neighbour. 0 where no pixel around is lit. Returns 1 when out of memory. */
static int floor_var(image *out, const grade_report *r, const image *var)
{
    size_t p, n = (size_t)r->w * r->h;
    float *t = malloc(3 * n * sizeof *t);
    int ch;
    if (!t || img_alloc(out, r->w, r->h)) { free(t); return 1; }
    for (ch = 0; ch < 3; ch++) {
        min_positive_1d(t + ch, var->px + ch, r->w, r->h, 3, 3 * (size_t)r->w);
        min_positive_1d(out->px + ch, t + ch, r->h, r->w, 3 * (size_t)r->w, 3);
    }
    free(t);
    for (p = 0; p < 3 * n; p++) {
        float v = var->px[p];
        out->px[p] = v > 0.0f || r->exact[p / 3] ? v : out->px[p] < HUGE_VALF ? out->px[p] : 0.0f;
    }
    return 0;
}

/* Compares the exact pixels as numbers; keeps the worst miss (largest |d| relative to the limit). */
static void test_exact(grade_report *r, const image *img, const image *ref, const image *step)
{
    size_t p, n = (size_t)r->w * r->h;
    double mean = 0.0, worst = 1.0;
    int ch;
    for (p = 0; p < 3 * n; p++) mean += fabs(ref->px[p]) / (3.0 * n);
    for (p = 0; p < n; p++) {
        double excess = 0.0, e;
        int side = 0, x = (int)(p % (size_t)r->w), y = (int)(p / (size_t)r->w), *box;
        if (!r->exact[p]) continue;
        r->nexact++;
        for (ch = 0; ch < 3; ch++) {
            double a = img->px[3 * p + ch], b = ref->px[3 * p + ch];
            e = fabs(a - b) / (GRADE_EXACT_REL * fabs(b) + GRADE_EXACT_ABS * mean + 1e-30 + (step ? 0.5 * step->px[3 * p + ch] : 0.0));
            if (e > excess) { excess = e; side = a > b; }
        }
        if (excess <= 1.0) continue;
        r->exact_fail++;
        box = r->exact_box[side];   /* where the brighter (1) and darker (0) misses are */
        if (r->exact_side[side]++ == 0) { box[0] = box[2] = x; box[1] = box[3] = y; }
        box[0] = imin(box[0], x); box[1] = imin(box[1], y); box[2] = imax(box[2], x + 1); box[3] = imax(box[3], y + 1);
        if (excess <= worst) continue;
        worst = excess;
        r->exact_x = (int)(p % (size_t)r->w);
        r->exact_y = (int)(p / (size_t)r->w);
        for (ch = 0; ch < 3; ch++) { r->exact_img[ch] = img->px[3 * p + ch]; r->exact_ref[ch] = ref->px[3 * p + ch]; }
    }
}

/* The noise floor's scale: the student's noise is taken to be at least k[ch] times the reference's
 * variance at each pixel, k = median of d^2 / var_ref over the noisy pixels / 0.455 (the median of
 * chi-square with 1 degree of freedom). The shape of the reference's variance says where noise is
 * rare-event noise (the edge of the lamp in a pixel, light found by chance): a group there whose
 * pixels all missed the rare event has a small scatter that would otherwise pass for precision.
 * The median makes k small rather than large with heavy tails: the floor is a safeguard, not the
 * estimate. */
static int floor_scale(grade_report *r, const image *img, const image *ref, const image *var)
{
    size_t p, n = (size_t)r->w * r->h, m;
    int ch;
    double *q = malloc(n * sizeof *q);
    if (!q) return 1;
    for (ch = 0; ch < 3; ch++) {
        for (p = 0, m = 0; p < n; p++) {
            double d = (double)img->px[3 * p + ch] - ref->px[3 * p + ch], v = var->px[3 * p + ch];
            if (!r->exact[p] && v > 0.0) q[m++] = d * d / v;
        }
        r->floor_k[ch] = m > 0 ? median(q, m) / 0.455 : 0.0;
    }
    free(q);
    return 0;
}

/* Mean d, mean ref, the sample variance of d (two passes, for accuracy), the rounding bound of the
 * mean and the noise floor (see floor_scale), for the groups g[0..ng) of the noisy pixels; id[p] is
 * pixel p's group (-1: none). zero[k] counts the pixels where the image is 0 and the reference not. */
static void group_stats(const grade_report *r, grade_block *g, int ng, const int *id, const image *img, const image *ref,
                        const image *var)
{
    size_t p, n = (size_t)img->w * img->h;
    int k, ch;
    for (p = 0; p < n; p++) {
        if (id[p] < 0) continue;
        g[id[p]].n++;
        g[id[p]].nzero += img->px[3 * p] == 0.0f && img->px[3 * p + 1] == 0.0f && img->px[3 * p + 2] == 0.0f &&
                          ref_luminance(ref, p) > 0.0;
        for (ch = 0; ch < 3; ch++) {
            double a = img->px[3 * p + ch], b = ref->px[3 * p + ch];
            g[id[p]].diff[ch] += a - b;
            g[id[p]].ref[ch] += b;
            g[id[p]].round[ch] += GRADE_ROUNDING * (fabs(a) + fabs(b));
            if (var) g[id[p]].floor[ch] += r->floor_k[ch] * var->px[3 * p + ch];
            if (r->step) g[id[p]].quant[ch] += r->step->px[3 * p + ch] * r->step->px[3 * p + ch] / 12.0;
        }
    }
    for (k = 0; k < ng; k++)
        for (ch = 0; ch < 3 && g[k].n > 0; ch++) {
            g[k].diff[ch] /= g[k].n;
            g[k].ref[ch] /= g[k].n;
            g[k].round[ch] /= g[k].n;
            g[k].floor[ch] /= (double)g[k].n * g[k].n;
            g[k].quant[ch] /= (double)g[k].n * g[k].n;
        }
    for (p = 0; p < n; p++)
        for (ch = 0; ch < 3 && id[p] >= 0; ch++) {
            double e = img->px[3 * p + ch] - ref->px[3 * p + ch] - g[id[p]].diff[ch];
            g[id[p]].var[ch] += e * e;
            g[id[p]].skew[ch] += e * e * e;
        }
    for (k = 0; k < ng; k++) {
        for (ch = 0; ch < 3; ch++) {
            double m2 = g[k].n > 0 ? g[k].var[ch] / g[k].n : 0.0;
            g[k].skew[ch] = m2 > 0.0 ? g[k].skew[ch] / g[k].n / (m2 * sqrt(m2)) : 0.0;
            g[k].var[ch] = g[k].n > 1 ? g[k].var[ch] / (g[k].n - 1.0) : 0.0;
        }
        g[k].df = g[k].n > 0 ? (int)g[k].n - 1 : 0;
    }
}

/* Critical |t| at a level for df degrees of freedom, remembered for the last few df (a family
 * has one level and few distinct df: full blocks, edge blocks). */
typedef struct { int df[8]; double level, t[8]; int next; } tcrit_memo;

static double tcrit_at(tcrit_memo *m, double level, int df)
{
    int k;
    if (m->level != level) { memset(m, 0, sizeof *m); m->level = level; }
    for (k = 0; k < 8; k++) if (m->df[k] == df) return m->t[k];
    k = m->next;
    m->next = (k + 1) % 8;
    m->df[k] = df;
    m->t[k] = t_critical(level, df);
    return m->t[k];
}

/* The critical |t| on the side where the noise's skewness makes t's tail longer. Rare large samples
 * (a path that finds a small light, a highlight) make d skewed to the right; a group that drew few
 * of them has a mean and a scatter both too small, so t's left tail is longer than Student's. The
 * one-term Edgeworth expansion of the studentised mean (Hall 1987), P(T <= x) ~ Phi(x) +
 * gamma / (6 sqrt(n)) (2x^2 + 1) phi(x), moves the lower quantile out by gamma (2x^2 + 1) /
 * (6 sqrt(n)): gamma is the sample's skewness on that side (gamma > 0 widens the darker side),
 * none on the other side (its tail is shorter: the limit stays, conservative). Measured on
 * mis-plates at 1-64 spp (glossy plates, small lights): without it, 5 to 8 of 16 honest images
 * failed on a darker level. */
static double skewed_limit(double crit, double gamma, long n)
{
    return gamma > 0.0 && n > 0 ? crit + gamma * (2.0 * crit * crit + 1.0) / (6.0 * sqrt((double)n)) : crit;
}

/* The t of each channel of a group, its sign if one is beyond level (the largest |t| wins), and
 * the largest |t| / critical |t| of the family so far in *excess. */
static void judge_group(grade_block *g, double level, tcrit_memo *memo, double *tmax, double *excess)
{
    double tbest = 0.0, crit;
    int ch;
    g->sign = 0;
    g->rare = 2 * g->nzero > g->n;   /* mostly black where the reference is not: rare-event noise */
    if (g->df < 1 || g->rare) { g->t[0] = g->t[1] = g->t[2] = 0.0; return; }
    for (ch = 0; ch < 3; ch++) {
        g->t[ch] = t_stat(g->diff[ch], g->noise[ch]);
        crit = skewed_limit(tcrit_at(memo, level, g->df), g->t[ch] < 0.0 ? g->skew[ch] : -g->skew[ch], g->n);
        if (fabs(g->t[ch]) > *tmax) *tmax = fabs(g->t[ch]);
        if (fabs(g->t[ch]) / crit > *excess) *excess = fabs(g->t[ch]) / crit;
        if (fabs(g->t[ch]) > crit && fabs(g->t[ch]) > tbest) {
            tbest = fabs(g->t[ch]);
            g->sign = g->t[ch] > 0 ? 1 : -1;
            g->channel = ch;
        }
    }
}

/* The within-block variance of d pooled over the blocks around (bx, by) of a grid of nbx x nby
 * blocks: sum of (m - 1) s^2 over sum of (m - 1), with or without the block itself. */
static double pooled_in(const grade_block *g, int nbx, int nby, int bx, int by, int ch, int self)
{
    double ss = 0.0, df = 0.0;
    int x, y;
    for (y = by - GRADE_POOL; y <= by + GRADE_POOL; y++)
        for (x = bx - GRADE_POOL; x <= bx + GRADE_POOL; x++)
            if (x >= 0 && y >= 0 && x < nbx && y < nby && (self || x != bx || y != by)) {
                const grade_block *b = &g[y * nbx + x];
                ss += b->df * b->var[ch];
                df += b->df;
            }
    return df > 0.0 ? ss / df : 0.0;
}

static double pooled_var(const grade_report *r, int bx, int by, int ch, int self)
{
    return pooled_in(r->blocks, r->nbx, r->nby, bx, by, ch, self);
}

/* The variance of a block's mean d: the larger of its own and its neighbourhood's pixel variance,
 * over m, plus rounding. */
static double block_noise(const grade_report *r, int bx, int by, int ch)
{
    const grade_block *b = &r->blocks[by * r->nbx + bx];
    double var = fmax(b->var[ch], pooled_var(r, bx, by, ch, 1));
    return b->n > 0 ? fmax(var / b->n, b->floor[ch]) + b->quant[ch] + b->round[ch] * b->round[ch] : 0.0;
}

static void test_blocks(grade_report *r, const image *img, const image *ref, const image *var, int *id)
{
    int bx, by, ch, x, y, full = 0;
    tcrit_memo memo = {{0}, 0.0, {0}, 0};
    for (by = 0; by < r->nby; by++)
        for (bx = 0; bx < r->nbx; bx++) {
            grade_block *b = &r->blocks[by * r->nbx + bx];
            b->x0 = bx * r->block;
            b->y0 = by * r->block;
            b->x1 = bx == r->nbx - 1 ? r->w : b->x0 + r->block;
            b->y1 = by == r->nby - 1 ? r->h : b->y0 + r->block;
            for (y = b->y0; y < b->y1; y++)
                for (x = b->x0; x < b->x1; x++) {
                    size_t p = (size_t)y * r->w + x;
                    id[p] = r->exact[p] ? -1 : by * r->nbx + bx;
                }
        }
    group_stats(r, r->blocks, r->nblocks, id, img, ref, var);
    r->block_level = sidak_level(r->alpha / 3.0 / (1 + r->ncoarse), 3L * r->nblocks);
    for (by = 0; by < r->nby; by++)
        for (bx = 0; bx < r->nbx; bx++) {
            grade_block *b = &r->blocks[by * r->nbx + bx];
            for (ch = 0; ch < 3; ch++) b->noise[ch] = block_noise(r, bx, by, ch);
            judge_group(b, r->block_level, &memo, &r->block_tmax, &r->block_excess);
            r->nbrighter += b->sign > 0;
            r->ndarker += b->sign < 0;
            if (b->df > full) full = b->df;
        }
    r->block_tcrit = full >= 1 ? t_critical(r->block_level, full) : 0.0;
}

/* The mean luminance of the reference over the 8 pixels around p, p left out. A pixel is put in a
 * level by its neighbours, not by itself: grouped by its own reference value, a pixel whose
 * reference drew high lands in the level above, where d = image - ref is then low on average (a
 * regression to the mean that, over thousands of pixels, fails honest images: measured on the
 * furnace, +0.4% and -0.3% on either side of an octave). The neighbours' noise is independent of
 * the pixel's. */
static double neighbours_luminance(const grade_report *r, const image *ref, size_t p)
{
    int x = (int)(p % (size_t)r->w), y = (int)(p / (size_t)r->w), u, v, n = 0;
    double sum = 0.0;
    for (v = y - 1; v <= y + 1; v++)
        for (u = x - 1; u <= x + 1; u++)
            if (u >= 0 && v >= 0 && u < r->w && v < r->h && (u != x || v != y)) {
                sum += ref_luminance(ref, (size_t)v * r->w + u);
                n++;
            }
    return n ? sum / n : ref_luminance(ref, p);
}

/* The blocks of the coarser scales, each scale its own family of alpha/3 / (1 + ncoarse): a bias
 * over a quarter of the image is too thin in any 8x8 block and too local for the whole-image fit.
 * Their noise is as the finest blocks': the larger of their own scatter and their neighbours'. */
static void test_coarse(grade_report *r, const image *img, const image *ref, const image *var, int *id)
{
    size_t p, n = (size_t)r->w * r->h;
    int k, b, ch;
    tcrit_memo memo = {{0}, 0.0, {0}, 0};
    for (k = 0; k < r->ncoarse; k++) {
        grade_scale *s = &r->coarse[k];
        for (b = 0; b < s->nblocks; b++) {
            grade_block *g = &s->blocks[b];
            g->x0 = b % s->nbx * s->side;
            g->y0 = b / s->nbx * s->side;
            g->x1 = b % s->nbx == s->nbx - 1 ? r->w : g->x0 + s->side;
            g->y1 = b / s->nbx == s->nby - 1 ? r->h : g->y0 + s->side;
        }
        for (p = 0; p < n; p++) {
            int bx = imin((int)(p % (size_t)r->w) / s->side, s->nbx - 1), by = imin((int)(p / (size_t)r->w) / s->side, s->nby - 1);
            id[p] = r->exact[p] ? -1 : by * s->nbx + bx;
        }
        group_stats(r, s->blocks, s->nblocks, id, img, ref, var);
        s->level = sidak_level(r->alpha / 3.0 / (1 + r->ncoarse), 3L * s->nblocks);
        for (b = 0; b < s->nblocks; b++) {
            grade_block *g = &s->blocks[b];
            for (ch = 0; ch < 3; ch++) {
                double v = fmax(g->var[ch], pooled_in(s->blocks, s->nbx, s->nby, b % s->nbx, b / s->nbx, ch, 1));
                g->noise[ch] = g->n > 0 ? fmax(v / g->n, g->floor[ch]) + g->quant[ch] + g->round[ch] * g->round[ch] : 0.0;
            }
            judge_group(g, s->level, &memo, &(double){0.0}, &s->excess);
            s->brighter += g->sign > 0;
            s->darker += g->sign < 0;
        }
    }
}

/* The level of a reference luminance: one octave each (see GRADE_LEVELS). */
static int level_of(double lum)
{
    int k;
    if (!(lum > 0.0)) return 0;
    k = (int)floor(log2(fmin(fmax(lum, 1e-12), 1e12))) + 25;
    return k < 1 ? 1 : k >= GRADE_LEVELS ? GRADE_LEVELS - 1 : k;
}

static void test_levels(grade_report *r, const image *img, const image *ref, const image *var, int *id)
{
    size_t p, n = (size_t)r->w * r->h, noisy = 0;
    int k, ch;
    tcrit_memo memo = {{0}, 0.0, {0}, 0};
    for (p = 0; p < n; p++)
        if (!r->exact[p]) { r->level_min_lum += ref_luminance(ref, p); noisy++; }
    r->level_min_lum = noisy ? r->level_min_lum / noisy : 0.0;
    for (k = 0; k < GRADE_LEVELS; k++) {
        grade_block *g = &r->levels[k];
        g->lum_lo = k == 0 ? 0.0 : ldexp(1.0, k - 25);
        g->lum_hi = k == 0 ? 0.0 : ldexp(1.0, k - 24);
        g->x0 = r->w; g->y0 = r->h;
    }
    for (p = 0; p < n; p++) {
        grade_block *g;
        double lum = neighbours_luminance(r, ref, p);
        id[p] = r->exact[p] || lum < r->level_min_lum ? -1 : level_of(lum);
        if (id[p] < 0) continue;
        g = &r->levels[id[p]];
        g->x0 = imin(g->x0, (int)(p % (size_t)r->w));
        g->y0 = imin(g->y0, (int)(p / (size_t)r->w));
        g->x1 = imax(g->x1, (int)(p % (size_t)r->w) + 1);
        g->y1 = imax(g->y1, (int)(p / (size_t)r->w) + 1);
    }
    group_stats(r, r->levels, GRADE_LEVELS, id, img, ref, var);
    for (k = 0; k < GRADE_LEVELS; k++) r->nlevels_tested += r->levels[k].df >= 1;
    r->nlevels = GRADE_LEVELS;
    r->level_level = sidak_level(r->alpha / 3.0, 3L * (r->nlevels_tested > 0 ? r->nlevels_tested : 1));
    for (k = 0; k < GRADE_LEVELS; k++) {
        grade_block *g = &r->levels[k];
        for (ch = 0; ch < 3; ch++)
            g->noise[ch] = g->n > 0 ? fmax(g->var[ch] / g->n, g->floor[ch]) + g->quant[ch] + g->round[ch] * g->round[ch] : 0.0;
        judge_group(g, r->level_level, &memo, &r->level_tmax, &r->level_excess);
        r->level_brighter += g->sign > 0;
        r->level_darker += g->sign < 0;
    }
}

/* 1 if most pixels of the blocks around (bx, by), the block itself left out, are black in the image
 * where the reference is not: their scatter says nothing of the noise (rare-event noise unseen). */
static int dark_neighbours(const grade_report *r, int bx, int by)
{
    long zero = 0, n = 0;
    int x, y;
    for (y = by - GRADE_POOL; y <= by + GRADE_POOL; y++)
        for (x = bx - GRADE_POOL; x <= bx + GRADE_POOL; x++)
            if (x >= 0 && y >= 0 && x < r->nbx && y < r->nby && (x != bx || y != by)) {
                zero += r->blocks[y * r->nbx + x].nzero;
                n += r->blocks[y * r->nbx + x].n;
            }
    return 2 * zero > n;
}

/* The weight of a block in the relative-bias fit, ref / (noise of its mean), the noise taken from
 * its neighbours only so that the weight does not depend on the block's own d. 0 for a block whose
 * neighbours are exact (noise within rounding) or mostly black in the image (at 1 spp with light
 * found by BSDF sampling only, such blocks took nearly all the weight and an honest image fitted
 * -82% +- 14%), or that has no noisy pixel. Both are told by the neighbours, not by the block: a
 * block left out for its own d would bias the fit. */
static double fit_weight(const grade_report *r, int bx, int by, int ch)
{
    const grade_block *b = &r->blocks[by * r->nbx + bx];
    double v;
    if (b->n < 1 || (r->nblocks > 1 && dark_neighbours(r, bx, by))) return 0.0;
    v = (r->nblocks > 1 ? pooled_var(r, bx, by, ch, 0) : b->var[ch]) / b->n;
    return v > b->round[ch] * b->round[ch] ? b->ref[ch] / v : 0.0;
}

/* One channel of the whole-image fit: eps = sum w d / sum w ref over the blocks, and the variance of
 * sum w d: the larger of the model's sum w^2 noise and the sandwich sum w^2 (d - eps ref)^2. The
 * model trusts each block's noise estimate; with heavy tails (1 spp, light found by BSDF sampling
 * only) the blocks that drew no rare sample look precise and weigh much, and the model's variance
 * is far too small (an honest 128x128 image at 1 spp failed at z -5.8). The sandwich measures the
 * scatter the blocks actually show, rare samples included. Returns the blocks with a weight. */
static int fit_channel(grade_report *r, int ch, double *wd, double *wref, double *wvar, double *skew)
{
    int b, nw = 0;
    double model = 0.0, sandwich = 0.0, m3 = 0.0, eps;
    *wd = *wref = 0.0;
    for (b = 0; b < r->nblocks; b++) {
        double w = fit_weight(r, b % r->nbx, b / r->nbx, ch);
        nw += w > 0.0;
        *wd += w * r->blocks[b].diff[ch];
        *wref += w * r->blocks[b].ref[ch];
        model += w * w * r->blocks[b].noise[ch];
    }
    eps = *wref > 0.0 ? *wd / *wref : 0.0;
    for (b = 0; b < r->nblocks; b++) {
        double w = fit_weight(r, b % r->nbx, b / r->nbx, ch), e = r->blocks[b].diff[ch] - eps * r->blocks[b].ref[ch];
        sandwich += w * w * e * e;
        m3 += w * w * w * e * e * e;
    }
    *wvar = fmax(model, sandwich);
    /* the skewness of the contributions w (d - eps ref), for skewed_limit: n of them, so sum of
     * cubes / n over (sum of squares / n)^1.5 */
    *skew = nw > 0 && sandwich > 0.0 ? (m3 / nw) / pow(sandwich / nw, 1.5) : 0.0;
    return nw;
}

/* Whole image, per channel: the relative bias eps of d = eps * ref, fitted to the block means by
 * weighted least squares (fit_channel), z = sum w d / sd, against Student's t with (blocks with a
 * weight - 1) degrees of freedom: the sandwich variance is estimated from that many blocks.
 * The plain means of d and ref are over every pixel (exact ones too). */
static void test_image(grade_report *r, const image *img, const image *ref)
{
    int ch, nw[3], df;
    double wd[3], wref[3], wvar[3], skew[3];
    size_t p, n = (size_t)r->w * r->h;
    for (p = 0; p < 3 * n; p++) {
        r->image_diff[p % 3] += ((double)img->px[p] - ref->px[p]) / n;
        r->image_ref[p % 3] += (double)ref->px[p] / n;
    }
    for (ch = 0; ch < 3; ch++) {
        nw[ch] = fit_channel(r, ch, &wd[ch], &wref[ch], &wvar[ch], &skew[ch]);
        r->image_nfit += nw[ch];
    }
    df = imin(nw[0], imin(nw[1], nw[2])) - 1;
    r->image_level = sidak_level(r->alpha / 3.0, 6);
    r->image_zcrit = df >= 1 ? t_critical(r->image_level, df) : HUGE_VAL;
    for (ch = 0; ch < 3; ch++) {
        r->image_eps[ch] = wref[ch] > 0.0 ? wd[ch] / wref[ch] : 0.0;
        r->image_eps_se[ch] = wref[ch] > 0.0 ? sqrt(wvar[ch]) / wref[ch] : 0.0;
        r->image_z[ch] = wref[ch] > 0.0 ? t_stat(wd[ch], wvar[ch]) : 0.0;
        r->image_zlimit[ch] = skewed_limit(r->image_zcrit, r->image_z[ch] < 0.0 ? skew[ch] : -skew[ch], nw[ch]);
        if (fabs(r->image_z[ch]) > r->image_zlimit[ch]) r->image_fail = 1;
    }
}

/* Whole image, unweighted: the mean of d over the noisy pixels, per channel, with their own scatter,
 * Student's t, the limit widened by the skewness. Weaker than the fit when the noise is tame, but it
 * weighs every pixel alike: an image black where light is rare is judged here, rare samples and all
 * (a black image passes no other test when its every block is black). */
static void test_plain(grade_report *r, const image *img, const image *ref)
{
    size_t p, n = (size_t)r->w * r->h;
    long m = 0;
    int ch;
    double sum[3] = {0, 0, 0}, m2[3] = {0, 0, 0}, m3[3] = {0, 0, 0}, refsum[3] = {0, 0, 0}, crit;
    for (p = 0; p < n; p++)
        for (ch = 0; ch < 3 && !r->exact[p]; ch++) {
            sum[ch] += (double)img->px[3 * p + ch] - ref->px[3 * p + ch];
            refsum[ch] += ref->px[3 * p + ch];
        }
    for (p = 0; p < n; p++) m += !r->exact[p];
    for (p = 0; p < n; p++)
        for (ch = 0; ch < 3 && !r->exact[p] && m > 0; ch++) {
            double e = (double)img->px[3 * p + ch] - ref->px[3 * p + ch] - sum[ch] / m;
            m2[ch] += e * e;
            m3[ch] += e * e * e;
        }
    crit = m > 1 ? t_critical(r->image_level, (int)fmin(m - 1, 1e9)) : 0.0;   /* one df for the 3 channels */
    for (ch = 0; ch < 3 && m > 1; ch++) {
        double skew = m2[ch] > 0.0 ? (m3[ch] / m) / pow(m2[ch] / m, 1.5) : 0.0;
        r->plain_t[ch] = t_stat(sum[ch] / m, m2[ch] / (m - 1.0) / m);
        r->plain_limit[ch] = skewed_limit(crit, r->plain_t[ch] < 0.0 ? skew : -skew, m);
        if (fabs(r->plain_t[ch]) > r->plain_limit[ch]) r->image_fail = 1;
        if (refsum[ch] > 0.0) r->plain_rel_se = fmax(r->plain_rel_se, sqrt(m2[ch] / (m - 1.0) / m) / (refsum[ch] / m));
    }
    r->too_noisy = r->plain_rel_se > GRADE_MAX_REL_SE;
}

/* Information only: z per pixel-channel with the student's variance taken as var_ref M / N. A
 * reference variance with few degrees of freedom (a sobol reference: 3) makes that z a Student t:
 * it fails when its t tail (Welch-Satterthwaite with the exact rounding term) is below the Sidak
 * level, i.e. when the z with the same tail passes the critical z. */
static void test_pixels(grade_report *r, const image *img, const image *ref, const image *var, const grade_opts *o)
{
    size_t i, n = 3 * (size_t)img->w * img->h;
    double k = 1.0 + (double)o->ref_spp / o->spp, level = sidak_level(r->alpha, (long)n);
    r->pixel_test = 1;
    r->pixel_n = (long)n;
    r->pixel_zcrit = sidak_zcrit(r->alpha, (long)n);
    for (i = 0; i < n; i++) {
        double d = (double)img->px[i] - ref->px[i], rounding = GRADE_ROUNDING * (fabs(ref->px[i]) + fabs(img->px[i]));
        double t = t_stat(d, var->px[i] * k + rounding * rounding);
        if (o->ref_var_dof > 0 && isfinite(t))   /* |z| > zcrit, i.e. the tail below the level, on t's tail */
            r->pixel_fail += t_two_sided_tail(t, welch_dof(var->px[i] * k, o->ref_var_dof, rounding * rounding, 0)) < level;
        else if (fabs(t) > r->pixel_zcrit) r->pixel_fail++;
    }
}

static void choose_blocks(grade_report *r, const grade_opts *o)
{
    int side;
    r->block = o->block > 0 ? o->block : (r->w < r->h ? r->w : r->h) / 16;
    if (r->block < GRADE_MIN_BLOCK && o->block <= 0) r->block = GRADE_MIN_BLOCK;
    r->nbx = r->w / r->block > 0 ? r->w / r->block : 1;
    r->nby = r->h / r->block > 0 ? r->h / r->block : 1;
    r->nblocks = r->nbx * r->nby;
    for (side = 2 * r->block; r->ncoarse < GRADE_MAX_COARSE && r->w / side >= 2 && r->h / side >= 2; side *= 2) {
        grade_scale *s = &r->coarse[r->ncoarse++];
        s->side = side;
        s->nbx = r->w / side;
        s->nby = r->h / side;
        s->nblocks = s->nbx * s->nby;
    }
}

int grade_compute(grade_report *r, const image *img, const image *ref, const image *ref_var, const grade_opts *o)
{
    int *id, k, oom = 0;
    image vf = {0, 0, NULL};   /* the noise floor's variance (floor_var) */
    memset(r, 0, sizeof *r);
    if (img->w != ref->w || img->h != ref->h) return 1;
    if (ref_var && (ref_var->w != ref->w || ref_var->h != ref->h)) return 1;
    r->alpha = o->alpha;
    r->step = o->step && o->step->w == img->w && o->step->h == img->h ? o->step : NULL;
    r->w = img->w;
    r->h = img->h;
    choose_blocks(r, o);
    r->blocks = calloc((size_t)r->nblocks, sizeof *r->blocks);
    r->levels = calloc(GRADE_LEVELS, sizeof *r->levels);
    id = malloc((size_t)r->w * r->h * sizeof *id);
    for (k = 0; k < r->ncoarse; k++) {
        r->coarse[k].blocks = calloc((size_t)r->coarse[k].nblocks, sizeof *r->coarse[k].blocks);
        oom |= !r->coarse[k].blocks;
    }
    if (oom || !r->blocks || !r->levels || !id || mark_exact(r, ref, ref_var)) {
        free(id);
        grade_free(r);
        return 1;
    }
    test_exact(r, img, ref, o->step);
    if (ref_var && (floor_scale(r, img, ref, ref_var) || floor_var(&vf, r, ref_var))) { free(id); grade_free(r); return 1; }
    test_blocks(r, img, ref, ref_var ? &vf : NULL, id);
    test_coarse(r, img, ref, ref_var ? &vf : NULL, id);
    test_levels(r, img, ref, ref_var ? &vf : NULL, id);
    test_image(r, img, ref);
    test_plain(r, img, ref);
    free(id);
    img_free(&vf);
    if (ref_var && o->spp > 0 && o->ref_spp > 0) test_pixels(r, img, ref, ref_var, o);
    return 0;
}

void grade_free(grade_report *r)
{
    int k;
    for (k = 0; k < r->ncoarse; k++) {
        free(r->coarse[k].blocks);
        r->coarse[k].blocks = NULL;
    }
    free(r->blocks);
    free(r->levels);
    free(r->exact);
    r->blocks = r->levels = NULL;
    r->exact = NULL;
}

int grade_failed(const grade_report *r) { return grade_biased(r) || r->too_noisy; }

int grade_biased(const grade_report *r)
{
    int k;
    for (k = 0; k < r->ncoarse; k++) if (r->coarse[k].brighter || r->coarse[k].darker) return 1;
    return r->image_fail || r->nbrighter > 0 || r->ndarker > 0 || r->level_brighter > 0 || r->level_darker > 0 ||
           r->exact_fail > 0;
}

double grade_excess(const grade_report *r)
{
    double e = fmax(r->block_excess, r->level_excess);
    int ch, k;
    if (r->exact_fail) return 1e9;
    for (k = 0; k < r->ncoarse; k++) e = fmax(e, r->coarse[k].excess);
    for (ch = 0; ch < 3; ch++) e = fmax(e, fabs(r->image_z[ch]) / r->image_zlimit[ch]);
    for (ch = 0; ch < 3; ch++) if (r->plain_limit[ch] > 0.0) e = fmax(e, fabs(r->plain_t[ch]) / r->plain_limit[ch]);
    return e;
}

int grade_rgbe_steps(image *steps, const image *img)
{
    size_t p;
    int ch, e;
    if (img_alloc(steps, img->w, img->h)) return 1;
    for (p = 0; p < (size_t)img->w * img->h; p++) {
        double m = fmax(img->px[3 * p], fmax(img->px[3 * p + 1], img->px[3 * p + 2]));
        frexp(m, &e);
        for (ch = 0; ch < 3; ch++) steps->px[3 * p + ch] = m > 0.0 ? (float)ldexp(1.0, e - 8) : 0.0f;
    }
    return 0;
}

double grade_bias_energy(const grade_report *r, double *sd)
{
    double e = 0.0;
    long n = 0;
    int b, ch;
    for (b = 0; b < r->nblocks; b++)
        for (ch = 0; ch < 3 && r->blocks[b].df >= 1 && !r->blocks[b].rare; ch++) {
            double t = r->blocks[b].t[ch];
            e += isfinite(t) ? t * t - 1.0 : 1e12;
            n++;
        }
    *sd = sqrt(2.0 * n);
    return e;
}

/* Paints the significant blocks of one scale: red brighter, blue darker, over what is there, with
 * weight `strength` (the coarse scales lighter, so that the finest show their detail on them). */
static void paint_blocks(image *out, const grade_block *g, int ng, int w, float strength)
{
    static const float red[3] = {0.9f, 0.03f, 0.03f}, blue[3] = {0.03f, 0.1f, 0.9f};
    int b, x, y, ch;
    for (b = 0; b < ng; b++) {
        if (!g[b].sign) continue;
        for (y = g[b].y0; y < g[b].y1; y++)
            for (x = g[b].x0; x < g[b].x1; x++)
                for (ch = 0; ch < 3; ch++) {
                    float *v = &out->px[3 * ((size_t)y * w + x) + ch];
                    *v = strength * (g[b].sign > 0 ? red : blue)[ch] + (1.0f - strength) * *v;
                }
    }
}

/* The signed t of a block: its channel farthest from 0. */
static double signed_t(const grade_block *g)
{
    int ch, best = 0;
    for (ch = 1; ch < 3; ch++) if (fabs(g->t[ch]) > fabs(g->t[best])) best = ch;
    return isfinite(g->t[best]) ? g->t[best] : copysign(1e9, g->t[best]);
}

/* The finest blocks' signed t as a tint: light (at most GRADE_HEAT_FAINT) below the limit, from
 * 0.6 at the limit to full colour at twice the limit; blocks not judged (exact, rare) untouched. */
#define GRADE_HEAT_FAINT 0.35f
static void paint_t(image *out, const grade_report *r)
{
    int b;
    for (b = 0; b < r->nblocks; b++) {
        const grade_block *g = &r->blocks[b];
        double u = fabs(signed_t(g)) / r->block_tcrit;
        float a = (float)(u < 1.0 ? GRADE_HEAT_FAINT * u : fmin(1.0, 0.6 + 0.4 * (u - 1.0)));
        grade_block one = *g;
        if (g->df < 1 || g->rare || !(r->block_tcrit > 0.0) || a <= 0.0f) continue;
        one.sign = signed_t(g) > 0 ? 1 : -1;
        paint_blocks(out, &one, 1, r->w, a);
    }
}

double grade_heatmap_mid(const image *ref)
{
    size_t p, n = (size_t)ref->w * ref->h;
    double sum = 0.0;
    for (p = 0; p < n; p++) sum += fmax(ref_luminance(ref, p), 0.0);
    return n ? sum / n : 0.0;
}

int grade_heatmap(image *out, const grade_report *r, const image *ref)
{
    size_t p;
    int k, ch;
    double mid = grade_heatmap_mid(ref);
    if (img_alloc(out, r->w, r->h)) return 1;
    for (p = 0; p < (size_t)r->w * r->h; p++) {   /* tone-mapped at the mean: a dark scene stays visible */
        double Y = fmax(ref_luminance(ref, p), 0.0);
        for (ch = 0; ch < 3; ch++) out->px[3 * p + ch] = (float)(0.6 * (mid > 0.0 ? Y / (Y + mid) : 0.0));
    }
    for (k = r->ncoarse - 1; k >= 0; k--) paint_blocks(out, r->coarse[k].blocks, r->coarse[k].nblocks, r->w, 0.3f);
    paint_t(out, r);
    return 0;
}
