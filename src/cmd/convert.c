/* convert.c — pathlab convert: reads a PFM, prints its figures, writes it by extension. */
#include "cmd/convert.h"
#include <math.h>
#include <stdio.h>
#include "image/image.h"
#include "image/rgbe.h"
#include "util/cli.h"
#include "sys/output_path.h"

#define CONVERT_USAGE "usage: pathlab convert IN.pfm|IN.hdr OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS]\n"

/* --exposure STOPS: a number strictly between -100 and 100 */
static int parse_exposure(void *ctx, const char *flag, const char *v)
{
    float *exposure = ctx;
    const cli_flag f = {flag, CLI_FLOAT, exposure, 0, 0, NULL, NULL, NULL};
    if (cli_parse_value("convert", &f, v, NULL)) return 1;
    if (*exposure > -100.0f && *exposure < 100.0f) return 0;
    return cli_fail("convert", flag, "a number of stops between -100 and 100", v);
}

/* The size, then each channel's mean, min and max. */
static void print_figures(const image *im, const char *path)
{
    double sum[3] = {0, 0, 0}, lo[3], hi[3];
    size_t i, n = (size_t)im->w * im->h;
    int ch;
    for (ch = 0; ch < 3; ch++) lo[ch] = HUGE_VAL, hi[ch] = -HUGE_VAL;
    for (i = 0; i < 3 * n; i++) {
        double v = im->px[i];
        sum[i % 3] += v;
        if (v < lo[i % 3]) lo[i % 3] = v;
        if (v > hi[i % 3]) hi[i % 3] = v;
    }
    printf("%s: %d x %d\n", path, im->w, im->h);
    for (ch = 0; ch < 3; ch++)
        printf("  %-5s mean %.6g  min %.6g  max %.6g\n", ch == 0 ? "red" : ch == 1 ? "green" : "blue", sum[ch] / (double)n, lo[ch], hi[ch]);
}

int convert_main(int argc, char **argv)
{
    float exposure = 0.0f;
    const cli_flag flags[] = {{"--exposure", CLI_CUSTOM, NULL, 0, 0, NULL, parse_exposure, NULL},
                              {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    const char *path[2];
    image im;
    int n, err;
    if (cli_parse("convert", argc, argv, tables, &exposure, path, 2, &n)) return 2;
    if (n != 2) { fprintf(stderr, "pathlab convert: needs an input and an output\n" CONVERT_USAGE); return 2; }
    if (img_format_of(path[1]) == IMG_UNKNOWN || img_format_of(path[1]) == IMG_HDR) {
        fprintf(stderr, "pathlab convert: %s: unknown image format (use .pfm, .ppm or .png)\n", path[1]);
        return 2;
    }
    if (output_path_check("convert", "output", path[1], IMG_EXTENSIONS)) return 2;
    if (img_format_of(path[0]) == IMG_HDR ? img_read_hdr(&im, path[0]) : img_read_pfm(&im, path[0])) return 2;
    print_figures(&im, path[0]);
    err = img_write(&im, path[1], exposure);
    img_free(&im);
    return err ? 1 : 0;
}
