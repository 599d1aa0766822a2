/* pfmtool — test tool for PFM images (this OpenImageIO build reads PFM but cannot write it):
 *   pfmtool const W H R G B OUT.pfm     a constant image
 *   pfmtool scale IN.pfm F OUT.pfm      every value times F
 *   pfmtool sum OUT.pfm IN.pfm...       the pixelwise sum
 *   pfmtool rmse A.pfm B.pfm [B_VAR.pfm]  how far A is from B, over all pixel-channels, on one line:
 *       rmse R relrmse R/mean(B) relmse mean((A-B)^2 / (B^2 + 0.01)) mean_a M mean_b M
 *       and, given B's variance of the pixel mean (pathlab --variance), var_b mean(B_VAR) and
 *       rmse_ref sqrt(max(0, rmse^2 - var_b)): the RMSE against B's expectation, B's own noise removed
 *   pfmtool close A.pfm B.pfm REL    every value of A within REL x max(|a|, |b|) of B's (float rounding);
 *       prints the worst relative difference; exit 1 if one is farther
 *   pfmtool varratio K A_1..A_K V_1..V_K   K renders of one scene with different seeds (A_i, each with
 *       its variance of the pixel mean V_i): is the mean of the V_i the variance between the A_i? Per
 *       pixel-channel, s2 = the sample variance of the K values, v = the mean of the K variances;
 *       prints "ratio R se S z Z ..." with R = sum v / sum s2 and S its jackknife standard error
 *       over the K renders (no normality assumed; K >= 3)
 *   pfmtool seeds OUT.pfm OUT_VAR.pfm IN_1..IN_K   K >= 2 renders with different seeds (independent
 *       estimates): their mean, and the variance of that mean from their spread (s2 / K, K - 1 dof),
 *       for samplers whose own --variance is missing (sobol1)
 * Exit 0 on success, 2 on bad input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/image.h"

static int constant(char **a)
{
    image im;
    int i, w = atoi(a[0]), h = atoi(a[1]), rc;
    if (img_alloc(&im, w, h)) return 2;
    for (i = 0; i < 3 * w * h; i++) im.px[i] = (float)atof(a[2 + i % 3]);
    rc = img_write_pfm(&im, a[5]) ? 2 : 0;
    img_free(&im);
    return rc;
}

static int scale(char **a)
{
    image im;
    int i, rc;
    float f = (float)atof(a[1]);
    if (img_read_pfm(&im, a[0])) return 2;
    for (i = 0; i < 3 * im.w * im.h; i++) im.px[i] *= f;
    rc = img_write_pfm(&im, a[2]) ? 2 : 0;
    img_free(&im);
    return rc;
}

static int sum(int n, char **a)
{
    image acc, im;
    int k, i, rc;
    if (img_read_pfm(&acc, a[1])) return 2;
    for (k = 2; k < n; k++) {
        if (img_read_pfm(&im, a[k])) { img_free(&acc); return 2; }
        if (im.w != acc.w || im.h != acc.h) { fprintf(stderr, "pfmtool: %s: size differs\n", a[k]); return 2; }
        for (i = 0; i < 3 * im.w * im.h; i++) acc.px[i] += im.px[i];
        img_free(&im);
    }
    rc = img_write_pfm(&acc, a[0]) ? 2 : 0;
    img_free(&acc);
    return rc;
}

static int rmse(int n, char **a)
{
    image im[3];
    int k, i, m;
    double d, se = 0.0, rel = 0.0, sa = 0.0, sb = 0.0, sv = 0.0, mse;
    for (k = 0; k < n; k++) {
        if (img_read_pfm(&im[k], a[k])) { while (k--) img_free(&im[k]); return 2; }
        if (k > 0 && (im[k].w != im[0].w || im[k].h != im[0].h)) {
            fprintf(stderr, "pfmtool: %s: size differs\n", a[k]);
            while (k >= 0) img_free(&im[k--]);
            return 2;
        }
    }
    m = 3 * im[0].w * im[0].h;
    for (i = 0; i < m; i++) {
        d = (double)im[0].px[i] - im[1].px[i];
        se += d * d;
        rel += d * d / ((double)im[1].px[i] * im[1].px[i] + 0.01);
        sa += im[0].px[i];
        sb += im[1].px[i];
        if (n == 3) sv += im[2].px[i];
    }
    mse = se / m;
    printf("rmse %.6g relrmse %.6g relmse %.6g mean_a %.6g mean_b %.6g", sqrt(mse), sqrt(mse) / (sb / m), rel / m, sa / m, sb / m);
    if (n == 3) printf(" var_b %.6g rmse_ref %.6g", sv / m, sqrt(mse > sv / m ? mse - sv / m : 0.0));
    printf("\n");
    for (k = 0; k < n; k++) img_free(&im[k]);
    return isfinite(mse) ? 0 : 2;
}

static int close_to(char **a)
{
    image x, y;
    double rel = atof(a[2]), worst = 0.0;
    size_t i, n;
    if (img_read_pfm(&x, a[0])) return 2;
    if (img_read_pfm(&y, a[1]) || x.w != y.w || x.h != y.h) { img_free(&x); return 2; }
    n = 3 * (size_t)x.w * (size_t)x.h;
    for (i = 0; i < n; i++) {
        double d = fabs((double)x.px[i] - y.px[i]), m = fmax(fabs(x.px[i]), fabs(y.px[i]));
        if (d > 0 && d / m > worst) worst = d / m;
    }
    printf("worst relative difference %.3g\n", worst);
    img_free(&x);
    img_free(&y);
    return worst <= rel ? 0 : 1;
}

/* Reads the K images of names[0..K-1] into im (same size); 0, or 2. */
static int read_all(image *im, char **names, int k)
{
    int i;
    for (i = 0; i < k; i++)
        if (img_read_pfm(&im[i], names[i]) || im[i].w != im[0].w || im[i].h != im[0].h) return 2;
    return 0;
}

/* sum v / sum s2 over the pixel-channels of the K renders, render `out` left out (-1: none). */
static double ratio_without(const image *im, int k, int out)
{
    double sv = 0, ss = 0;
    int i, c, n = 3 * im[0].w * im[0].h, kk = out >= 0 ? k - 1 : k;
    for (c = 0; c < n; c++) {
        double m = 0, q = 0;
        for (i = 0; i < k; i++)
            if (i != out) m += im[i].px[c] / (double)kk;
        for (i = 0; i < k; i++)
            if (i != out) {
                q += (im[i].px[c] - m) * (im[i].px[c] - m);
                sv += im[k + i].px[c] / (double)kk;
            }
        ss += q / (kk - 1);
    }
    return ss > 0 ? sv / ss : 0;
}

/* The ratio, and its standard error by the jackknife over the K renders (the seeds are the
 * independent units: a render that drew a rare large sample moves both sums together). */
static int varratio(int argc, char **a)
{
    int k = atoi(a[0]), i;
    image *im;
    double r, jm = 0, j2 = 0, *rj, se;
    if (k < 3 || argc != 1 + 2 * k || !(im = calloc((size_t)(2 * k), sizeof *im)) || !(rj = calloc((size_t)k, sizeof *rj))) return 2;
    if (read_all(im, a + 1, 2 * k)) return 2;
    r = ratio_without(im, k, -1);
    for (i = 0; i < k; i++) jm += (rj[i] = ratio_without(im, k, i)) / k;
    for (i = 0; i < k; i++) j2 += (rj[i] - jm) * (rj[i] - jm);
    se = sqrt(j2 * (k - 1) / k);
    printf("ratio %.4f se %.4f z %.2f renders %d pixel-channels %d\n", r, se, se > 0 ? (r - 1.0) / se : r == 1.0 ? 0.0 : r > 1.0 ? 1e9 : -1e9, k, 3 * im[0].w * im[0].h);
    for (i = 0; i < 2 * k; i++) img_free(&im[i]);
    free(im);
    free(rj);
    return 0;
}

/* The mean of K independent renders and the variance of that mean, from the spread between them. */
static int seeds(int k, char **a)
{
    image *im, m, v;
    int i, c, rc = 2;
    if (k < 2 || !(im = calloc((size_t)k, sizeof *im))) return 2;
    if (!read_all(im, a + 2, k) && !img_alloc(&m, im[0].w, im[0].h)) {
        if (!img_alloc(&v, im[0].w, im[0].h)) {
            for (c = 0; c < 3 * im[0].w * im[0].h; c++) {
                double mean = 0, q = 0;
                for (i = 0; i < k; i++) mean += im[i].px[c] / (double)k;
                for (i = 0; i < k; i++) q += (im[i].px[c] - mean) * (im[i].px[c] - mean);
                m.px[c] = (float)mean;
                v.px[c] = (float)(q / (k - 1) / k);
            }
            rc = img_write_pfm(&m, a[0]) || img_write_pfm(&v, a[1]) ? 2 : 0;
            img_free(&v);
        }
        img_free(&m);
    }
    for (i = 0; i < k; i++) img_free(&im[i]);
    free(im);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc >= 6 && !strcmp(argv[1], "seeds")) return seeds(argc - 4, argv + 2);
    if (argc >= 3 && !strcmp(argv[1], "varratio")) return varratio(argc - 2, argv + 2);
    if (argc == 5 && !strcmp(argv[1], "close")) return close_to(argv + 2);
    if (argc == 8 && !strcmp(argv[1], "const")) return constant(argv + 2);
    if (argc == 5 && !strcmp(argv[1], "scale")) return scale(argv + 2);
    if (argc >= 4 && !strcmp(argv[1], "sum")) return sum(argc - 2, argv + 2);
    if ((argc == 4 || argc == 5) && !strcmp(argv[1], "rmse")) return rmse(argc - 2, argv + 2);
    fprintf(stderr, "usage: pfmtool const W H R G B OUT | scale IN F OUT | sum OUT IN... | rmse A B [B_VAR] | varratio K A.. V.. | seeds OUT OUT_VAR IN...\n");
    return 2;
}
