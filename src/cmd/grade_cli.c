/* grade_cli.c — the `pathlab grade` command: reads the images, runs grade.c's tests, prints the
 * verdict (where, how much, brighter or darker) and writes the heatmap. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "util/cli.h"
#include "cmd/grade.h"

#define GRADE_USAGE "usage: pathlab grade IMAGE.pfm --ref REF.pfm [--alpha A] [--block B] [--heatmap OUT.ppm|OUT.png]\n" \
                    "                     [--spp N] [--var REF_VAR.pfm --ref-spp M]\n"

static const char *const CHANNELS[3] = {"red", "green", "blue"};

typedef struct {
    const char *image, *ref, *var, *heatmap;
    grade_opts o;
} grade_args;

/* --alpha A: a float strictly between 0 and 0.5 */
static int parse_alpha(void *ctx, const char *flag, const char *v)
{
    float *alpha = ctx;
    const cli_flag f = {flag, CLI_FLOAT, alpha, 0, 0, NULL, NULL, NULL};
    if (cli_parse_value("grade", &f, v, NULL)) return 1;
    if (*alpha > 0.0f && *alpha < 0.5f) return 0;
    return cli_fail("grade", flag, "a level in (0, 0.5)", v);
}

static int parse_args(grade_args *a, int argc, char **argv)
{
    float alpha = 0.01f;
    const cli_flag flags[] = {
        {"--ref", CLI_STRING, &a->ref, 0, 0, NULL, NULL, NULL},
        {"--var", CLI_STRING, &a->var, 0, 0, NULL, NULL, NULL},
        {"--heatmap", CLI_STRING, &a->heatmap, 0, 0, NULL, NULL, NULL},
        {"--spp", CLI_INT, &a->o.spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--ref-spp", CLI_INT, &a->o.ref_spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--block", CLI_INT, &a->o.block, 2, 1 << 20, NULL, NULL, NULL},
        {"--alpha", CLI_CUSTOM, NULL, 0, 0, NULL, parse_alpha, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    const char *words[1];
    int n;
    memset(a, 0, sizeof *a);
    if (cli_parse("grade", argc, argv, tables, &alpha, words, 1, &n)) return 1;
    a->image = n ? words[0] : NULL;
    a->o.alpha = alpha;
    if (!a->image || !a->ref) { fprintf(stderr, "pathlab grade: needs an image and a reference\n" GRADE_USAGE); return 1; }
    if (a->heatmap && img_format_of(a->heatmap) == IMG_UNKNOWN) {
        fprintf(stderr, "pathlab grade: --heatmap %s: unknown image format (use .pfm, .ppm or .png)\n", a->heatmap);
        return 1;
    }
    if (a->var && !(a->o.spp && a->o.ref_spp)) {
        fprintf(stderr, "pathlab grade: --var needs --spp N (the image's samples per pixel) and --ref-spp M (the reference's)\n");
        return 1;
    }
    return 0;
}

/* Channel-averaged relative difference over the blocks of one sign (0: over the whole image). */
static double relative_diff(const grade_report *r, int sign)
{
    double d = 0.0, ref = 0.0;
    int b, ch;
    if (sign == 0) {
        ref = r->image_ref[0] + r->image_ref[1] + r->image_ref[2];
        return ref != 0.0 ? (r->image_diff[0] + r->image_diff[1] + r->image_diff[2]) / ref : 0.0;
    }
    for (b = 0; b < r->nblocks; b++) {
        const grade_block *k = &r->blocks[b];
        double m = (double)(k->x1 - k->x0) * (k->y1 - k->y0);
        if (k->sign != sign) continue;
        for (ch = 0; ch < 3; ch++) { d += m * k->diff[ch]; ref += m * k->ref[ch]; }
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

/* One line for the significant blocks of one sign: how many, where, by how much. */
static void print_region(const grade_report *r, int sign)
{
    int b, n = 0, x0 = r->w, y0 = r->h, x1 = 0, y1 = 0;
    long area = 0;
    char where[64];
    for (b = 0; b < r->nblocks; b++) {
        const grade_block *k = &r->blocks[b];
        if (k->sign != sign) continue;
        n++;
        area += (long)(k->x1 - k->x0) * (k->y1 - k->y0);
        if (k->x0 < x0) x0 = k->x0;
        if (k->y0 < y0) y0 = k->y0;
        if (k->x1 > x1) x1 = k->x1;
        if (k->y1 > y1) y1 = k->y1;
    }
    if (n == 0) return;
    describe_box(where, sizeof where, x0, y0, x1, y1, r->w, r->h);
    printf("  %s in %d of %d blocks (%.0f%% of the image), within x %d..%d, y %d..%d (%s; y = 0 is the top row): %+.2f%% there\n",
           sign > 0 ? "brighter" : "darker", n, r->nblocks, 100.0 * area / ((double)r->w * r->h), x0, x1 - 1, y0, y1 - 1,
           where, 100.0 * relative_diff(r, sign));
}

/* The whole-image line: the fitted relative bias per channel, and the plain mean difference. */
static void print_image_test(const grade_report *r)
{
    int ch;
    if (!r->image_nfit) {
        printf("whole image: no relative-bias fit (no block has noise to weigh it: exact pixels are judged by the block test)\n");
    } else {
        printf("whole image: relative bias fitted to the block means (weights ref / noise):");
        for (ch = 0; ch < 3; ch++) printf(" %c %+.2f%% +- %.2f%%", "RGB"[ch], 100 * r->image_eps[ch], 100 * r->image_eps_se[ch]);
        printf("; z %+.2f %+.2f %+.2f, limit |z| %.2f\n", r->image_z[0], r->image_z[1], r->image_z[2], r->image_zcrit);
    }
    printf("             (plain mean of image - ref %+.4g %+.4g %+.4g, %+.2f%% of the reference's mean)\n",
           r->image_diff[0], r->image_diff[1], r->image_diff[2], 100.0 * relative_diff(r, 0));
}

static void print_tests(const grade_report *r, const grade_args *a)
{
    printf("pathlab grade: %s against %s, %dx%d pixels", a->image, a->ref, r->w, r->h);
    if (a->o.spp) printf(", %d spp", a->o.spp);
    if (a->o.ref_spp) printf(" (reference %d spp)", a->o.ref_spp);
    printf("\nalpha %g, family-wise: %g to the whole-image test (3 channels), %g to the block test (%d blocks x 3 channels), Sidak within each\n",
           r->alpha, r->alpha / 2, r->alpha / 2, r->nblocks);
    print_image_test(r);
    printf("blocks of %dx%d pixels: max |t| %.2f, limit |t| %.2f (Student, %d df, level %.2g per test): %d brighter, %d darker\n",
           r->blocks[0].x1 - r->blocks[0].x0, r->blocks[0].y1 - r->blocks[0].y0, r->block_tmax, r->block_tcrit, r->blocks[0].df, r->block_level, r->nbrighter, r->ndarker);
    if (r->pixel_test)
        printf("pixels (information only, not in the verdict; assumes the reference's estimator at %d spp): "
               "%ld of %ld pixel-channels beyond |z| %.2f\n", a->o.spp, r->pixel_fail, r->pixel_n, r->pixel_zcrit);
}

static void print_verdict(const grade_report *r, const grade_args *a)
{
    long n = 3L * r->w * r->h;
    char spp[32] = "";
    int ch, worst = 0;
    if (a->o.spp) snprintf(spp, sizeof spp, ", %d spp", a->o.spp);
    if (!grade_failed(r)) {
        printf("PASS: the difference is consistent with noise (alpha %g; %ld pixel-channels, %d block tests%s)\n",
               r->alpha, n, 3 * r->nblocks, spp);
        return;
    }
    printf("FAIL: biased (alpha %g; %ld pixel-channels, %d block tests%s)\n", r->alpha, n, 3 * r->nblocks, spp);
    if (r->nonfinite) printf("  %ld pixel-channels of the image are NaN or infinite\n", r->nonfinite);
    for (ch = 1; ch < 3; ch++) if (fabs(r->image_z[ch]) > fabs(r->image_z[worst])) worst = ch;
    if (r->image_fail)
        printf("  %s over the whole image: %+.2f%% +- %.2f%% in %s (|z| %.1f > %.2f)\n", r->image_z[worst] > 0 ? "brighter" : "darker",
               100 * r->image_eps[worst], 100 * r->image_eps_se[worst], CHANNELS[worst], fabs(r->image_z[worst]), r->image_zcrit);
    print_region(r, 1);
    print_region(r, -1);
    if (r->image_fail && !r->nbrighter && !r->ndarker)
        printf("  no block alone is significant: the bias is spread over the image\n");
}

/* Reads the images; 0, or 2 after naming the file at fault. */
static int read_inputs(const grade_args *a, image *img, image *ref, image *var)
{
    size_t i;
    memset(var, 0, sizeof *var);
    if (img_read_pfm(img, a->image)) return 2;
    if (img_read_pfm(ref, a->ref)) { img_free(img); return 2; }
    if (a->var && img_read_pfm(var, a->var)) { img_free(img); img_free(ref); return 2; }
    if (img->w != ref->w || img->h != ref->h || (a->var && (var->w != ref->w || var->h != ref->h))) {
        fprintf(stderr, "pathlab grade: sizes differ: %s is %dx%d, %s is %dx%d", a->image, img->w, img->h, a->ref, ref->w, ref->h);
        if (a->var) fprintf(stderr, ", %s is %dx%d", a->var, var->w, var->h);
        fprintf(stderr, "\n");
        goto bad;
    }
    for (i = 0; i < 3 * (size_t)ref->w * ref->h; i++)
        if (!isfinite(ref->px[i]) || (a->var && !(var->px[i] >= 0.0f && isfinite(var->px[i])))) {
            fprintf(stderr, "pathlab grade: %s has a NaN, infinite or negative value at pixel x %zu, y %zu (y = 0 is the top row)\n",
                    isfinite(ref->px[i]) ? a->var : a->ref, i / 3 % (size_t)ref->w, i / 3 / (size_t)ref->w);
            goto bad;
        }
    return 0;
bad:
    img_free(img);
    img_free(ref);
    img_free(var);
    return 2;
}

int grade_main(int argc, char **argv)
{
    grade_args a;
    grade_report r;
    image img, ref, var, heat;
    int rc;
    if (parse_args(&a, argc, argv)) return 2;
    if (read_inputs(&a, &img, &ref, &var)) return 2;
    if (grade_compute(&r, &img, &ref, a.var ? &var : NULL, &a.o)) {
        fprintf(stderr, "pathlab grade: out of memory\n");
        rc = 2;
    } else {
        print_tests(&r, &a);
        print_verdict(&r, &a);
        rc = grade_failed(&r) ? 1 : 0;
        if (a.heatmap) {
            if (grade_heatmap(&heat, &r, &ref) || img_write(&heat, a.heatmap, 0.0f)) rc = 2;
            else printf("heatmap: %s (red: significantly brighter blocks, blue: darker, grey: the reference)\n", a.heatmap);
            img_free(&heat);
        }
    }
    grade_free(&r);
    img_free(&img);
    img_free(&ref);
    img_free(&var);
    return rc;
}
