/* convert.c — pathlab convert: reads a PFM, prints its figures, writes it by extension. */
#include "cmd/convert.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "files/sidecar.h"
#include "image/exposure.h"
#include "image/image.h"
#include "image/rgbe.h"
#include "util/cli.h"
#include "util/path.h"
#include <errno.h>
#include "sys/output_path.h"

#define CONVERT_USAGE "usage: pathlab convert IN.pfm|IN.hdr OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS|auto]\n"

/* --exposure STOPS: a number strictly between -100 and 100, or auto (image/exposure.h: NAN until the image is read) */
static int parse_exposure(void *ctx, const char *flag, const char *v)
{
    float *exposure = ctx;
    const cli_flag f = {flag, CLI_FLOAT, exposure, 0, 0, NULL, NULL, NULL};
    if (!strcmp(v, "auto")) { *exposure = NAN; return 0; }
    if (cli_parse_value("convert", &f, v, NULL)) return 1;
    if (*exposure > -100.0f && *exposure < 100.0f) return 0;
    return cli_fail("convert", flag, "a number of stops between -100 and 100, or auto", v);
}

/* The size, then each channel's mean, min and max over its finite values. */
static void print_figures(const image *im, const char *path)
{
    double sum[3] = {0, 0, 0}, lo[3], hi[3];
    size_t i, n = (size_t)im->w * im->h, finite[3] = {0, 0, 0};
    int ch;
    for (ch = 0; ch < 3; ch++) lo[ch] = HUGE_VAL, hi[ch] = -HUGE_VAL;
    for (i = 0; i < 3 * n; i++) {
        double v = im->px[i];
        if (!isfinite(v)) continue;
        finite[i % 3]++;
        sum[i % 3] += v;
        if (v < lo[i % 3]) lo[i % 3] = v;
        if (v > hi[i % 3]) hi[i % 3] = v;
    }
    printf("%s: %d x %d\n", shown(path), im->w, im->h);
    for (ch = 0; ch < 3; ch++)
        printf("  %-5s mean %.6g  min %.6g  max %.6g%s\n", ch == 0 ? "red" : ch == 1 ? "green" : "blue",
               finite[ch] ? sum[ch] / (double)finite[ch] : 0.0, finite[ch] ? lo[ch] : 0.0, finite[ch] ? hi[ch] : 0.0,
               finite[ch] < n ? " (of its finite values)" : "");
}

/* A warning naming the first NaN or infinite value of im, and how many there are: convert still
 * shows such an image (the student looks for them; the picture shows them black), but says so. */
static void warn_not_finite(const image *im, const char *path)
{
    size_t i, n = 3 * (size_t)im->w * (size_t)im->h, bad = 0, first = 0;
    for (i = 0; i < n; i++)
        if (!isfinite(im->px[i]) && bad++ == 0) first = i;
    if (!bad) return;
    fprintf(stderr, "pathlab convert: warning: %s: %zu %s NaN or infinite, the first at x %zu, y %zu (%s, %g; y = 0 is the "
            "top row): in a PNG or PPM a NaN shows black, an infinity as 0 or 1; a PFM keeps them\n",
            shown(path), bad, bad == 1 ? "value is" : "values are", first / 3 % (size_t)im->w, first / 3 / (size_t)im->w,
            first % 3 == 0 ? "red" : first % 3 == 1 ? "green" : "blue", (double)im->px[first]);
}

/* A PFM written: m, the input's sidecar (has), beside it (the same pixels, made the same
 * way; the input's variance and sample counts are not copied, so the sidecar names none); if it has
 * none, the output's old sidecar removed (it told --resume that a converted grey image was 2 samples
 * of a Cornell box). 0, or 1 after saying why. */
static int write_sidecar(sidecar *m, int has, const char *out)
{
    char meta[PATH_CAP];
    if (img_format_of(out) != IMG_PFM) return 0;
    sidecar_path(meta, sizeof meta, out);
    if (!has) {
        if (remove(meta) == 0 || errno == ENOENT) return 0;
        fprintf(stderr, "pathlab convert: %s: cannot remove the sidecar of the file replaced: %s\n", shown(meta), strerror(errno));
        return 1;
    }
    m->variance[0] = m->sample_count[0] = '\0';
    m->layers_n = 0;
    return sidecar_write_to(m, out, meta);
}

/* 1 (said) if the output is the input (convert r.pfm r.pfm rewrote r.pfm's sidecar without its
 * variance), or its sidecar cannot be written (a folder there: the image was written, then exit 2). */
static int check_output(const char *in, const char *out)
{
    char meta[PATH_CAP];
    if (path_same_file(in, out)) {
        fprintf(stderr, "pathlab convert: the output %s is the input: write to a new file\n", shown(out));
        return 1;
    }
    sidecar_path(meta, sizeof meta, out);
    return img_format_of(out) == IMG_PFM && output_path_check("convert", "output's sidecar", meta, NULL);
}

int convert_main(int argc, char **argv)
{
    float exposure = 0.0f;
    const cli_flag flags[] = {{"--exposure", CLI_CUSTOM, NULL, 0, 0, NULL, parse_exposure, NULL},
                              {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    const char *path[2];
    image im;
    sidecar m;
    int n, err = -1, has = 0;
    if (cli_parse("convert", argc, argv, tables, &exposure, path, 2, &n)) return 2;
    if (n != 2) { fprintf(stderr, "pathlab convert: needs an input and an output\n" CONVERT_USAGE); return 2; }
    if (img_format_of(path[1]) == IMG_UNKNOWN || img_format_of(path[1]) == IMG_HDR) {
        fprintf(stderr, "pathlab convert: %s: unknown image format (use .pfm, .ppm or .png)\n", shown(path[1]));
        return 2;
    }
    if (output_path_check("convert", "output", path[1], IMG_EXTENSIONS) || check_output(path[0], path[1])) return 2;
    /* the input's sidecar first: a malformed one stops here, before the image is written (after, the
     * output kept the old render's sidecar) */
    if (img_format_of(path[1]) == IMG_PFM && (err = sidecar_read(&m, path[0])) > 0) return 2;
    has = img_format_of(path[1]) == IMG_PFM && err == 0;
    if (img_format_of(path[0]) == IMG_HDR ? img_read_hdr(&im, path[0]) : img_read_pfm(&im, path[0])) return 2;
    print_figures(&im, path[0]);
    warn_not_finite(&im, path[0]);
    if (isnan(exposure)) {
        exposure = img_auto_exposure(&im);
        printf("exposure auto: %+.1f stops (the median luminance of the pixels that are not black to mid-grey, %g)\n", exposure,
               EXPOSURE_MID_GREY);
    }
    err = img_write(&im, path[1], exposure) || write_sidecar(&m, has, path[1]);
    if (!err) fprintf(stderr, "pathlab convert: wrote %s\n", shown(path[1]));
    img_free(&im);
    return err ? 2 : 0;   /* a failed write: said, with the file and the system's reason */
}
