/* grade_print.c — the verdict in words (see grade_print.h). Positions are in pixels with y = 0 the
 * top row, as an image viewer shows them. */
#include "grade/grade_print.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sys/shown.h"

static const char *const CHANNELS[3] = {"red", "green", "blue"};

/* "+1.23% +- 0.45%": the error bar to 2 significant digits, the value to the same decimal place (an
 * error bar of 0.000012% is printed as such, not as "0.00%"). */
static const char *pct_pm(char *s, size_t cap, double value, double se)
{
    int decimals = se > 0.0 ? (int)fmin(8.0, fmax(0.0, 1.0 - floor(log10(100.0 * se)))) : 0;
    if (fabs(value) >= 1e4 || se >= 1e4)   /* a million percent and more: in powers of ten */
        snprintf(s, cap, "%+.3g%% +- %.2g%%", 100.0 * value, 100.0 * se);
    else snprintf(s, cap, "%+.*f%% +- %.*f%%", decimals, 100.0 * value, decimals, 100.0 * se);
    return s;
}

/* Channel-averaged relative difference over the groups of one sign (0: over the whole image). */
static double relative_diff(const grade_report *r, const grade_block *g, int ng, int sign)
{
    double d = 0.0, ref = 0.0;
    int k, ch;
    if (sign == 0) {
        ref = r->image_ref[0] + r->image_ref[1] + r->image_ref[2];
        return ref != 0.0 ? (r->image_diff[0] + r->image_diff[1] + r->image_diff[2]) / ref : 0.0;
    }
    for (k = 0; k < ng; k++) {
        if (g[k].sign != sign) continue;
        for (ch = 0; ch < 3; ch++) { d += g[k].n * g[k].diff[ch]; ref += g[k].n * g[k].ref[ch]; }
    }
    return ref != 0.0 ? d / ref : 0.0;
}

/* Where a box [lo, hi) lies along a side of the given size: 0, 1, 2 for the thirds, -1 if it spans. */
static int third(int lo, int hi, int size)
{
    if (3 * (hi - lo) > 2 * size) return -1;
    return (int)(3L * (lo + hi) / (2L * size));
}

static void describe_box(char *s, size_t cap, int x0, int y0, int x1, int y1, int w, int h)
{
    static const char *rows[] = {"top", "middle", "bottom"}, *cols[] = {"left", "centre", "right"};
    int tx = third(x0, x1, w), ty = third(y0, y1, h);
    if (tx < 0 && ty < 0) snprintf(s, cap, "most of the image");
    else if (tx < 0) snprintf(s, cap, ty == 1 ? "a band across the middle" : "the %s", rows[ty]);
    else if (ty < 0) snprintf(s, cap, tx == 1 ? "a band down the centre" : "the %s side", cols[tx]);
    else if (tx == 1 && ty == 1) snprintf(s, cap, "the centre");
    else snprintf(s, cap, "the %s-%s", rows[ty], cols[tx]);
}

void grade_describe_box(char *s, size_t cap, int x0, int y0, int x1, int y1, int w, int h)
{
    describe_box(s, cap, x0, y0, x1, y1, w, h);
}

/* The box around the groups of one sign, its area in pixels and the number of groups; 0 if none. */
static int sign_box(const grade_block *g, int ng, int sign, int box[4], long *area)
{
    int k, n = 0;
    box[0] = box[1] = 1 << 30;
    box[2] = box[3] = 0;
    *area = 0;
    for (k = 0; k < ng; k++) {
        if (g[k].sign != sign) continue;
        n++;
        *area += g[k].n;
        if (g[k].x0 < box[0]) box[0] = g[k].x0;
        if (g[k].y0 < box[1]) box[1] = g[k].y0;
        if (g[k].x1 > box[2]) box[2] = g[k].x1;
        if (g[k].y1 > box[3]) box[3] = g[k].y1;
    }
    return n;
}

/* One line for the significant blocks of one sign at one scale: how many, where, by how much. */
static void print_blocks(const grade_report *r, const grade_block *g, int ng, int side, int sign)
{
    int b[4], n = sign_box(g, ng, sign, b, &(long){0});
    char where[64];
    if (n == 0) return;
    describe_box(where, sizeof where, b[0], b[1], b[2], b[3], r->w, r->h);
    printf("  %s in %d of %d blocks of %dx%d, within x %d..%d, y %d..%d (%s): %+.2f%% there\n", sign > 0 ? "brighter" : "darker",
           n, ng, side, side, b[0], b[2] - 1, b[1], b[3] - 1, where, 100.0 * relative_diff(r, g, ng, sign));
}

/* Blocks at every scale */
static int block_count(const grade_report *r)
{
    int k, n = r->nblocks;
    for (k = 0; k < r->ncoarse; k++) n += r->coarse[k].nblocks;
    return n;
}

/* Significant blocks at any scale, of either sign */
static int any_block(const grade_report *r)
{
    int k, n = r->nbrighter + r->ndarker;
    for (k = 0; k < r->ncoarse; k++) n += r->coarse[k].brighter + r->coarse[k].darker;
    return n;
}

/* One line per significant level: its luminance range, its pixels, where they are, by how much. */
static void print_levels(const grade_report *r)
{
    int k;
    char where[64];
    for (k = 0; k < r->nlevels; k++) {
        const grade_block *g = &r->levels[k];
        double rel;
        if (!g->sign) continue;
        rel = g->ref[g->channel] != 0.0 ? g->diff[g->channel] / g->ref[g->channel] : 0.0;
        describe_box(where, sizeof where, g->x0, g->y0, g->x1, g->y1, r->w, r->h);
        printf("  %s where the reference's luminance is %.3g to %.3g: %ld pixels (%.1f%% of the image) within x %d..%d, "
               "y %d..%d (%s): %+.2f%% in %s there\n", g->sign > 0 ? "brighter" : "darker", g->lum_lo, g->lum_hi, g->n,
               100.0 * g->n / ((double)r->w * r->h), g->x0, g->x1 - 1, g->y0, g->y1 - 1, where, 100.0 * rel, CHANNELS[g->channel]);
    }
}

/* The whole-image line: the fitted relative bias per channel, and the plain mean difference. */
static void print_image_test(const grade_report *r)
{
    char pm[64];
    int ch;
    if (!r->image_nfit) {
        printf("whole image: no relative-bias fit (no block has noise to weigh it: exact, or black around it)\n");
    } else {
        printf("whole image: relative bias fitted to the block means (weights ref / noise):");
        for (ch = 0; ch < 3; ch++) printf(" %c %s", "RGB"[ch], pct_pm(pm, sizeof pm, r->image_eps[ch], r->image_eps_se[ch]));
        printf("; z %+.2f %+.2f %+.2f, limits %.2f %.2f %.2f (Student %.2f at level %.2g, widened by skewness)\n", r->image_z[0],
               r->image_z[1], r->image_z[2], r->image_zlimit[0], r->image_zlimit[1], r->image_zlimit[2], r->image_zcrit, r->image_level);
    }
    printf("whole image, unweighted: plain mean of image - ref %+.4g %+.4g %+.4g (%+.2f%% of the reference's mean); t over the noisy "
           "pixels %+.2f %+.2f %+.2f, limits %.2f %.2f %.2f; standard error %.2g%% of the reference's mean\n", r->image_diff[0], r->image_diff[1], r->image_diff[2],
           100.0 * relative_diff(r, NULL, 0, 0), r->plain_t[0], r->plain_t[1], r->plain_t[2], r->plain_limit[0],
           r->plain_limit[1], r->plain_limit[2], 100.0 * r->plain_rel_se);
}

static void print_tests(const grade_report *r, const char *image, const char *ref, const grade_opts *o)
{
    int k, full = r->blocks[0].x1 - r->blocks[0].x0;
    printf("pathlab grade: %s against %s, %dx%d pixels", shown(image), shown(ref), r->w, r->h);
    if (o->spp) printf(", %d spp", o->spp);
    if (o->ref_spp) printf(" (reference %d spp)", o->ref_spp);
    printf("\nalpha %g, family-wise over 3 families of tests, alpha/3 each, Sidak within each:\n", r->alpha);
    print_image_test(r);
    printf("blocks of %dx%d pixels: %d blocks x 3 channels, max |t| %.2f, limit |t| %.2f (Student, %d df, level %.2g per test): "
           "%d brighter, %d darker\n", full, full, r->nblocks, r->block_tmax, r->block_tcrit, full * full - 1, r->block_level,
           r->nbrighter, r->ndarker);
    for (k = 0; k < r->ncoarse; k++)
        printf("blocks of %dx%d: %d blocks x 3 channels, largest |t| / limit %.2f (level %.2g per test): %d brighter, %d darker\n",
               r->coarse[k].side, r->coarse[k].side, r->coarse[k].nblocks, r->coarse[k].excess, r->coarse[k].level,
               r->coarse[k].brighter, r->coarse[k].darker);
    printf("levels (the pixels brighter than the mean %.3g, grouped by the reference's luminance, one octave each): %d levels "
           "x 3 channels, largest |t| / limit %.2f (level %.2g per test): %d brighter, %d darker\n", r->level_min_lum,
           r->nlevels_tested, r->level_excess, r->level_level, r->level_brighter, r->level_darker);
    printf("exact pixels (flat in the reference: equal to their 8 neighbours%s): %ld, compared as numbers (|d| <= 1e-4 |ref| "
           "+ 1e-6 mean): %ld differ\n", r->exact_from_var ? ", variance 0" : "; no REF_var.pfm", r->nexact, r->exact_fail);
    if (r->black_rare)
        printf("black flat pixels not exact: %ld (the reference drew no light there, but its dimmest lit pixel within 5 pixels drew "
               "too few hits for that to prove the pixel dark: judged in their blocks, as rare events)\n", r->black_rare);
    if (r->floor_k[0] > 0.0)
        printf("noise floor: at least %.3g %.3g %.3g x the reference's variance per pixel (robust fit; guards rare-event noise)\n",
               r->floor_k[0], r->floor_k[1], r->floor_k[2]);
    if (r->step)
        printf("RGBE (.hdr): its quantisation, a uniform error of one step per channel (step^2 / 12), added to the noise; exact "
               "pixels allowed half a step\n");
    if (r->pixel_test)
        printf("pixels (information only, not in the verdict; assumes the reference's estimator at %d spp): "
               "%ld of %ld pixel-channels beyond |z| %.2f\n", o->spp, r->pixel_fail, r->pixel_n, r->pixel_zcrit);
}

/* The exact pixels that miss on one side (1 brighter, 0 darker): how many and where. */
static void print_exact_side(const grade_report *r, int side)
{
    const int *b = r->exact_box[side];
    char where[64];
    if (!r->exact_side[side]) return;
    describe_box(where, sizeof where, b[0], b[1], b[2], b[3], r->w, r->h);
    printf("    %ld of them %s, within x %d..%d, y %d..%d (%s)\n", r->exact_side[side], side ? "brighter" : "darker", b[0], b[2] - 1,
           b[1], b[3] - 1, where);
}

/* Pixels of the blocks not judged because the image is mostly black there (rare-event noise). */
static long rare_pixels(const grade_report *r)
{
    long n = 0;
    int b;
    for (b = 0; b < r->nblocks; b++) n += r->blocks[b].rare ? r->blocks[b].n : 0;
    return n;
}

/* The channel whose whole-image fit is farthest past its limit: each channel's limit is widened by
 * its own skewness, so the largest |z| need not be the one that fails. */
static int worst_fit_channel(const grade_report *r)
{
    int ch, worst = 0;
    for (ch = 1; ch < 3; ch++)
        if (fabs(r->image_z[ch]) / r->image_zlimit[ch] > fabs(r->image_z[worst]) / r->image_zlimit[worst]) worst = ch;
    return worst;
}

static void print_verdict(const grade_report *r)
{
    char pm[64];
    long n = 3L * r->w * r->h;
    int ch, k, worst = 0;
    if (rare_pixels(r))
        printf("note: %ld pixels (%.0f%% of the image) lie in blocks mostly black in the image where the reference is not: rare-event "
               "noise (light not yet found at this spp), not judged; more samples per pixel would judge them\n", rare_pixels(r),
               100.0 * rare_pixels(r) / ((double)r->w * r->h));
    if (!grade_failed(r)) {
        printf("PASS: the difference is consistent with noise (alpha %g; %ld pixel-channels, %d block, %d level and 6 whole-image tests)\n",
               r->alpha, n, 3 * block_count(r), 3 * r->nlevels_tested);
        return;
    }
    printf("FAIL: %s (alpha %g; %ld pixel-channels, %d block, %d level and 6 whole-image tests)\n", grade_biased(r) ? "biased" :
           "too noisy to judge", r->alpha, n, 3 * block_count(r), 3 * r->nlevels_tested);
    if (r->too_noisy)
        printf("  too noisy to judge: the whole image's mean is known to +-%.0f%% of the reference's only (one standard error; a PASS "
               "needs %.0f%%): a few pixels hold most of its light; render more samples per pixel\n", 100.0 * r->plain_rel_se,
               100.0 * GRADE_MAX_REL_SE);
    if (r->exact_fail)
        printf("  %ld of %ld exact pixels differ; the worst at x %d, y %d: %.4g %.4g %.4g, the reference %.4g %.4g %.4g\n",
               r->exact_fail, r->nexact, r->exact_x, r->exact_y, r->exact_img[0], r->exact_img[1], r->exact_img[2],
               r->exact_ref[0], r->exact_ref[1], r->exact_ref[2]);
    for (ch = 1; ch >= 0; ch--) print_exact_side(r, ch);
    worst = worst_fit_channel(r);
    if (fabs(r->image_z[worst]) > r->image_zlimit[worst])
        printf("  %s over the whole image: %s in %s (|z| %.1f > %.2f)\n", r->image_z[worst] > 0 ? "brighter" : "darker",
               pct_pm(pm, sizeof pm, r->image_eps[worst], r->image_eps_se[worst]), CHANNELS[worst], fabs(r->image_z[worst]), r->image_zlimit[worst]);
    for (ch = 0; ch < 3; ch++)
        if (r->plain_limit[ch] > 0.0 && fabs(r->plain_t[ch]) > r->plain_limit[ch]) {
            printf("  %s on the whole image's plain mean: %+.2f%% in %s (|t| %.1f > %.2f)\n", r->plain_t[ch] > 0 ? "brighter" : "darker",
                   100.0 * r->image_diff[ch] / r->image_ref[ch], CHANNELS[ch], fabs(r->plain_t[ch]), r->plain_limit[ch]);
            break;
        }
    print_blocks(r, r->blocks, r->nblocks, r->block, 1);
    print_blocks(r, r->blocks, r->nblocks, r->block, -1);
    for (k = 0; k < r->ncoarse; k++) {
        print_blocks(r, r->coarse[k].blocks, r->coarse[k].nblocks, r->coarse[k].side, 1);
        print_blocks(r, r->coarse[k].blocks, r->coarse[k].nblocks, r->coarse[k].side, -1);
    }
    print_levels(r);
    if (grade_biased(r) && grade_excess(r) < 1.5)
        printf("  (the worst statistic is only %.2f times its limit: this is how a false alarm looks (at most 1 honest image in %.0f fails); "
               "more samples per pixel would settle it)\n", grade_excess(r), 1.0 / r->alpha);
    if (r->image_fail && !any_block(r) && !r->level_brighter && !r->level_darker)
        printf("  no block or level alone is significant: the bias is spread over the image\n");
}

void grade_print_report(const grade_report *r, const char *image, const char *ref, const grade_opts *o)
{
    print_tests(r, image, ref, o);
    print_verdict(r);
}

void grade_print_hypotheses(const grade_hypothesis *h, int n)
{
    int k;
    if (n == 0) printf("likely mistake: none of the catalogue explains the difference (docs/grading.md lists it)\n");
    for (k = 0; k < n; k++) printf("likely mistake: %s\n    evidence: %s\n", h[k].what, h[k].evidence);
}

/* The box of the finest coarse scale with a significant block; 0 if none. */
static int coarse_box(const grade_report *r, int b[4])
{
    int k;
    long area;
    for (k = 0; k < r->ncoarse; k++)
        if (sign_box(r->coarse[k].blocks, r->coarse[k].nblocks, -1, b, &area) || sign_box(r->coarse[k].blocks, r->coarse[k].nblocks, 1, b, &area))
            return 1;
    return 0;
}

/* 1 if the whole-image fit fails in a channel */
static int fit_failed(const grade_report *r)
{
    int ch;
    for (ch = 0; ch < 3; ch++) if (fabs(r->image_z[ch]) > r->image_zlimit[ch]) return 1;
    return 0;
}

/* 1 if the unweighted whole-image test fails in a channel */
static int plain_failed(const grade_report *r)
{
    int ch;
    for (ch = 0; ch < 3; ch++) if (r->plain_limit[ch] > 0.0 && fabs(r->plain_t[ch]) > r->plain_limit[ch]) return 1;
    return 0;
}

/* The relative difference over the significant finest blocks of the sign that covers more pixels,
 * else over the significant levels. */
static double group_diff(const grade_report *r)
{
    int b[4];
    long up = 0, down = 0;
    sign_box(r->blocks, r->nblocks, 1, b, &up);
    sign_box(r->blocks, r->nblocks, -1, b, &down);
    if (up || down) return relative_diff(r, r->blocks, r->nblocks, up >= down ? 1 : -1);
    sign_box(r->levels, r->nlevels, 1, b, &up);
    sign_box(r->levels, r->nlevels, -1, b, &down);
    return relative_diff(r, r->levels, r->nlevels, up >= down ? 1 : -1);
}

void grade_fill_row(grade_row *row, const grade_report *r)
{
    int worst, b[4];
    long area;
    row->w = r->w;
    row->h = r->h;
    worst = worst_fit_channel(r);
    row->bias = r->image_eps[worst];
    row->bias_se = r->image_eps_se[worst];
    snprintf(row->channel, sizeof row->channel, "%s", CHANNELS[worst]);
    if (!r->image_nfit || (r->too_noisy && !grade_biased(r))) {   /* no fit (black around every block), or too noisy: the plain mean */
        row->bias = relative_diff(r, NULL, 0, 0);
        row->bias_se = r->plain_rel_se;
        snprintf(row->channel, sizeof row->channel, "mean");
    } else if (!fit_failed(r) && plain_failed(r)) {   /* the fit misses it (few pixels): the plain mean says how much */
        row->bias = relative_diff(r, NULL, 0, 0);
        row->bias_se = -1.0;
        snprintf(row->channel, sizeof row->channel, "mean");
    } else if (!fit_failed(r) && grade_biased(r)) {   /* only groups: how much there, not over the image */
        row->bias = group_diff(r);
        row->bias_se = -2.0;
        snprintf(row->channel, sizeof row->channel, "groups");
    }
    row->where[0] = '\0';
    if (r->exact_fail) snprintf(row->where, sizeof row->where, "%ld exact pixels, worst at x %d y %d", r->exact_fail, r->exact_x, r->exact_y);
    else if (sign_box(r->blocks, r->nblocks, -1, b, &area) || sign_box(r->blocks, r->nblocks, 1, b, &area) ||
             coarse_box(r, b) || sign_box(r->levels, r->nlevels, -1, b, &area) || sign_box(r->levels, r->nlevels, 1, b, &area))
        describe_box(row->where, sizeof row->where, b[0], b[1], b[2], b[3], r->w, r->h);
    else if (r->image_fail) snprintf(row->where, sizeof row->where, "spread over the image");
    else if (r->too_noisy) snprintf(row->where, sizeof row->where, "too noisy to judge");
}

void grade_print_row(const grade_row *row)
{
    const char *name = shown(row->path);
    char pm[64];
    /* each number says what it is computed over (the whole image, or the significant blocks and where
     * they are); a place stands beside the number only when the number is computed there */
    if (row->status == 2) printf("%s: UNREADABLE, %s", name, shown(row->mistake));
    else if (row->status == 0) printf("%s: PASS (%s in %s over the whole image)", name, pct_pm(pm, sizeof pm, row->bias, row->bias_se), row->channel);
    else {
        printf("%s: FAIL", name);
        if (row->channel[0] && row->bias_se == -2.0)
            printf(", %+.2f%% over its significant blocks%s%s%s", 100 * row->bias, row->where[0] ? " (" : "", row->where, row->where[0] ? ")" : "");
        else {
            if (row->channel[0] && row->bias_se < 0.0) printf(", %+.2f%% on the whole image's plain mean", 100 * row->bias);
            else if (row->channel[0]) printf(", %s in %s over the whole image", pct_pm(pm, sizeof pm, row->bias, row->bias_se), row->channel);
            if (!strcmp(row->where, "too noisy to judge")) printf("; %s", row->where);
            else if (row->where[0]) printf("; %s: %s", strcmp(row->where, "spread over the image") ? "significant in" : "the bias", row->where);
        }
        printf("%s%s", row->mistake[0] ? "; likely: " : "", shown(row->mistake));
    }
    printf("%s%s\n", row->flagged ? "; FLAGGED: " : row->remark[0] ? "; " : "", shown(row->remark));
}

void grade_bias_text(char *out, size_t cap, const grade_row *r)
{
    char pm[64];
    out[0] = '\0';
    if (r->status == 2 || !r->channel[0]) return;
    if (r->bias_se == -2.0) snprintf(out, cap, "%+.2f%% (over the significant blocks)", 100 * r->bias);
    else if (r->bias_se < 0.0) snprintf(out, cap, "%+.2f%% (the whole image's plain mean)", 100 * r->bias);
    else snprintf(out, cap, "%s (%s, the whole image)", pct_pm(pm, sizeof pm, r->bias, r->bias_se), r->channel);
}
