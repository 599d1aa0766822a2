/* pfmtool — test tool for PFM images (this OpenImageIO build reads PFM but cannot write it):
 *   pfmtool const W H R G B OUT.pfm     a constant image
 *   pfmtool scale IN.pfm F OUT.pfm      every value times F
 *   pfmtool sum OUT.pfm IN.pfm...       the pixelwise sum
 * Exit 0 on success, 2 on bad input. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image.h"

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

int main(int argc, char **argv)
{
    if (argc == 8 && !strcmp(argv[1], "const")) return constant(argv + 2);
    if (argc == 5 && !strcmp(argv[1], "scale")) return scale(argv + 2);
    if (argc >= 4 && !strcmp(argv[1], "sum")) return sum(argc - 2, argv + 2);
    fprintf(stderr, "usage: pfmtool const W H R G B OUT | scale IN F OUT | sum OUT IN...\n");
    return 2;
}
