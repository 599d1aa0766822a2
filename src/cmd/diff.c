/* diff.c — the `pathlab diff` command: reads the images, prints their errors (stats/image_diff.h)
 * and writes the heatmap if asked (image/heatmap.h). */
#include "cmd/diff.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "image/heatmap.h"
#include "image/linear_file.h"
#include "image/radiance.h"
#include "stats/image_diff.h"
#include "util/cli.h"
#include "sys/output_path.h"

#define DIFF_USAGE "usage: pathlab diff A.pfm REF.pfm [--heatmap OUT.ppm|OUT.png] [--scale S]\n" \
                   "       pathlab diff A.pfm [B.pfm ...] --ref REF.pfm   (the arguments as grade takes them)\n"

/* The metrics of stats/image_diff.h, one per line. */
static void print_stats(const image_diff *s)
{
    printf("RMSE    %.6g\nrelMSE  %.6g\nMAE     %.6g\nmax     %.6g\n", s->rmse, s->relmse, s->mae, s->max);
    if (isnan(s->psnr)) printf("PSNR    n/a (the reference is black: no peak)\n");
    else printf("PSNR    %.2f dB\n", s->psnr);
    printf("mean    %+.6g +- %.2g (a - ref, standard error over the pixels)\n", s->mean, s->mean_se);
}

static const char *kind_of(const img_pfm_info *info)
{
    return info->channels == 1 ? "greyscale (\"Pf\", 1 channel)" : "colour (\"PF\", 3 channels)";
}

/* Reads A and REF, refusing a greyscale image against a colour one (or the other way round) and
 * an A that is not radiance (NaN, infinite or negative values: image/radiance.h). 0 or 1. */
static int read_pair(image im[2], const char *const path[2])
{
    img_pfm_info info[2];
    if (img_read_linear(&im[0], path[0], &info[0])) return 1;
    if (img_read_linear(&im[1], path[1], &info[1])) { img_free(&im[0]); return 1; }
    if (info[0].channels != info[1].channels)
        fprintf(stderr, "pathlab diff: %s is %s but %s is %s: compare images of the same kind\n", shown(path[0]),
                shown(kind_of(&info[0])), shown(path[1]), shown(kind_of(&info[1])));
    else if (img_check_radiance(&im[0], path[0], 5) == 0 && img_check_radiance(&im[1], path[1], 5) == 0)
        return 0;   /* the reference too: a NaN one gave "RMSE nan, PSNR inf dB", exit 0 */
    img_free(&im[0]);
    img_free(&im[1]);
    return 1;
}

/* One image against the reference: the metrics and, if asked, the heatmap; 0, or 2 (bad input, or
 * the heatmap not written: said why). */
static int diff_one(const char *image_path, const char *ref_path, const char *heat, float scale)
{
    const char *path[2];
    image im[2], hm;
    image_diff s;
    int rc = 0;
    path[0] = image_path;
    path[1] = ref_path;
    if (read_pair(im, path)) return 2;
    if (image_diff_compute(&s, &im[0], &im[1])) {
        fprintf(stderr, "pathlab diff: %s is %dx%d but %s is %dx%d\n", shown(path[0]), im[0].w, im[0].h, shown(path[1]), im[1].w, im[1].h);
        rc = 2;
    } else {
        double used = 0.0;
        print_stats(&s);
        if (heat && img_heatmap(&hm, &im[0], &im[1], scale, &used)) rc = 2;
        else if (heat) {
            if (img_write(&hm, heat, 0.0f)) rc = 2;
            else fprintf(stderr, "pathlab diff: wrote the heatmap %s: |a - ref| averaged over RGB, black 0 to white %.4g%s\n",
                         shown(heat), used, scale > 0.0f ? " (--scale)" : " (the largest: give --scale S to compare heatmaps)");
            img_free(&hm);
        }
    }
    img_free(&im[0]);
    img_free(&im[1]);
    return rc;
}

/* `diff A.pfm REF.pfm`, or as grade takes them: `diff A.pfm [B.pfm ...] --ref REF.pfm`. */
int diff_main(int argc, char **argv)
{
    const char *ref = NULL, *heat = NULL, **words = calloc((size_t)argc + 1, sizeof *words);
    float scale = 0.0f;
    int scale_given = 0;
    const cli_flag flags[] = {{"--heatmap", CLI_STRING, &heat, 0, 0, NULL, NULL, NULL},
                              {"--scale", CLI_FLOAT, &scale, 0, 0, NULL, NULL, &scale_given},
                              {"--ref", CLI_STRING, &ref, 0, 0, NULL, NULL, NULL},
                              {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    int n, k, rc = 0;
    if (!words || cli_parse("diff", argc, argv, tables, NULL, words, argc, &n)) { free(words); return 2; }
    if (scale_given && scale < 0.0f) {   /* was taken for 0, "the largest difference" */
        char v[32];
        snprintf(v, sizeof v, "%g", scale);
        free(words);
        return 2 * cli_fail("diff", "--scale", "a number >= 0 (the heatmap's white; 0: the largest difference)", v);
    }
    if (scale_given && !heat) {
        fprintf(stderr, "pathlab diff: --scale is the heatmap's white: it goes with --heatmap\n");
        free(words);
        return 2;
    }
    if (!ref && n == 2) ref = words[--n];
    if (!ref && n > 2) {
        fprintf(stderr, "pathlab diff: %d images and no --ref: which one is the reference?\n" DIFF_USAGE, n);
        free(words);
        return 2;
    }
    if (!ref || n < 1) { fprintf(stderr, "pathlab diff: needs an image and a reference\n" DIFF_USAGE); free(words); return 2; }
    if (heat && (!img_is_picture(heat) || n > 1)) {
        fprintf(stderr, n > 1 ? "pathlab diff: --heatmap %s: with one image only\n"
                              : "pathlab diff: --heatmap %s: a heatmap is a picture: use .png or .ppm\n", shown(heat));
        free(words);
        return 2;
    }
    if (heat && n == 1 && output_path_check("diff", "--heatmap", heat, IMG_PICTURE_EXTENSIONS)) { free(words); return 2; }
    for (k = 0; k < n; k++) {
        int one;
        if (n > 1) printf("%s%s:\n", k ? "\n" : "", shown(words[k]));
        one = diff_one(words[k], ref, heat, scale);
        if (one > rc) rc = one;
    }
    free(words);
    return rc;
}
