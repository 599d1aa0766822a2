/* diff.c — error metrics between two images, and a heatmap of where they differ. */
#include "cmd/diff.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "util/cli.h"

int diff_compute(diff_stats *s, const image *a, const image *ref)
{
    long i;
    double se = 0.0, rel = 0.0, ae = 0.0, sum = 0.0, peak = 0.0;
    memset(s, 0, sizeof *s);
    if (a->w != ref->w || a->h != ref->h) return 1;
    s->n = 3L * a->w * a->h;
    for (i = 0; i < s->n; i++) {
        double b = ref->px[i], d = (double)a->px[i] - b;
        se += d * d;
        rel += d * d / (b * b + DIFF_REL_EPS);
        ae += fabs(d);
        sum += d;
        if (fabs(d) > s->max) s->max = fabs(d);
        if (b > peak) peak = b;
    }
    s->rmse = sqrt(se / s->n);
    s->relmse = rel / s->n;
    s->mae = ae / s->n;
    s->mean = sum / s->n;
    /* sample variance of d from its moments, then the standard error of its mean */
    s->mean_se = s->n > 1 ? sqrt(fmax(0.0, (se - s->n * s->mean * s->mean) / (s->n - 1)) / s->n) : 0.0;
    s->psnr = se > 0.0 && peak > 0.0 ? 10.0 * log10(peak * peak / (se / s->n)) : INFINITY;
    return 0;
}

/* black -> red -> yellow -> white as t goes 0 -> 1 */
static vec3 ramp(double t)
{
    float x = (float)(t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t) * 3.0f;
    return v3(fminf(x, 1.0f), fminf(fmaxf(x - 1.0f, 0.0f), 1.0f), fminf(fmaxf(x - 2.0f, 0.0f), 1.0f));
}

int diff_heatmap(image *out, const image *a, const image *ref, double scale)
{
    long i, n = (long)a->w * a->h;
    double max = 0.0;
    if (a->w != ref->w || a->h != ref->h || img_alloc(out, a->w, a->h)) return 1;
    for (i = 0; i < 3 * n; i++) max = fmax(max, fabs((double)a->px[i] - ref->px[i]));
    if (scale <= 0.0) scale = max > 0.0 ? max : 1.0;
    for (i = 0; i < n; i++) {
        const float *p = a->px + 3 * i, *q = ref->px + 3 * i;
        double d = (fabs((double)p[0] - q[0]) + fabs((double)p[1] - q[1]) + fabs((double)p[2] - q[2])) / 3.0;
        vec3 c = ramp(d / scale);
        out->px[3 * i] = c.x;
        out->px[3 * i + 1] = c.y;
        out->px[3 * i + 2] = c.z;
    }
    return 0;
}

int diff_main(int argc, char **argv)
{
    const char *path[2] = {NULL, NULL}, *heat = NULL;
    image im[2], hm;
    diff_stats s;
    int i, n = 0, rc = 0;
    float scale = 0.0f;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--heatmap")) { if (!(heat = cli_value(argc, argv, &i))) return 2; }
        else if (!strcmp(argv[i], "--scale")) { const char *v = cli_value(argc, argv, &i); if (!v || cli_float("--scale", v, &scale)) return 2; }
        else if (n < 2 && argv[i][0] != '-') path[n++] = argv[i];
        else { fprintf(stderr, "pathlab: diff: unexpected '%s'\nusage: pathlab diff A.pfm REF.pfm [--heatmap OUT.ppm|OUT.png] [--scale S]\n", argv[i]); return 2; }
    }
    if (n != 2) { fprintf(stderr, "usage: pathlab diff A.pfm REF.pfm [--heatmap OUT.ppm|OUT.png] [--scale S]\n"); return 2; }
    if (img_read_pfm(&im[0], path[0])) return 2;
    if (img_read_pfm(&im[1], path[1])) { img_free(&im[0]); return 2; }
    if (diff_compute(&s, &im[0], &im[1])) {
        fprintf(stderr, "pathlab: diff: %s is %dx%d but %s is %dx%d\n", path[0], im[0].w, im[0].h, path[1], im[1].w, im[1].h);
        rc = 2;
    } else {
        printf("RMSE    %.6g\nrelMSE  %.6g\nMAE     %.6g\nmax     %.6g\nPSNR    %.2f dB\nmean    %+.6g +- %.2g (a - ref, standard error)\n",
               s.rmse, s.relmse, s.mae, s.max, s.psnr, s.mean, s.mean_se);
        if (heat && (diff_heatmap(&hm, &im[0], &im[1], scale) || img_write(&hm, heat, 0.0f))) rc = 1;
        if (heat && !rc) img_free(&hm);
    }
    img_free(&im[0]);
    img_free(&im[1]);
    return rc;
}
