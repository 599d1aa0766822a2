/* grade.h — `pathlab grade IMAGE.pfm --ref REF.pfm`: is the difference from a reference noise or
 * bias? The verdict a teacher needs, with where and how much when it is bias.
 * The statistics are described at the top of grade.c. */
#ifndef PATHLAB_GRADE_H
#define PATHLAB_GRADE_H
#include "image/image.h"

typedef struct {
    double alpha;        /* family-wise level of the verdict (default 0.01) */
    int block;           /* block side in pixels; 0: chosen from the image size */
    int spp, ref_spp;    /* the image's and the reference's samples per pixel; 0 if not given */
} grade_opts;

typedef struct {
    int x0, y0, x1, y1;      /* the pixels [x0, x1) x [y0, y1) */
    double diff[3], ref[3];  /* mean of image - ref and mean of ref, per channel */
    double var[3], round[3]; /* sample variance of d over the block; rounding bound of its mean */
    double noise[3];         /* the variance of its mean d used by the tests */
    double t[3];             /* Student's t of the mean difference, per channel */
    int df;                  /* its degrees of freedom: pixels - 1 */
    int sign;                /* +1 significantly brighter, -1 darker, 0 consistent with noise */
} grade_block;

typedef struct {
    double alpha;
    int w, h, block, nbx, nby, nblocks;  /* nblocks = nbx * nby, each tested in 3 channels */
    grade_block *blocks;                 /* row-major, nby rows of nbx */
    double block_level, block_tcrit, block_tmax;  /* per-test level, critical |t| of a full block */
    int nbrighter, ndarker;
    double image_diff[3], image_ref[3];  /* plain means of d and of ref */
    double image_eps[3], image_eps_se[3], image_z[3], image_level, image_zcrit;  /* relative-bias fit */
    int image_fail, image_nfit;          /* image_nfit: block-channels with a weight in the fit */
    long nonfinite;                      /* NaN or infinite pixel-channels in the image */
    int pixel_test;                      /* 1 when the per-pixel Z-test ran (--var) */
    long pixel_n, pixel_fail;
    double pixel_zcrit;
} grade_report;

/* Runs the tests: ref_var (may be NULL) is the reference's variance of the pixel mean. Returns 0,
 * or 1 when the sizes differ. Free the report with grade_free. */
int grade_compute(grade_report *r, const image *img, const image *ref, const image *ref_var, const grade_opts *o);
void grade_free(grade_report *r);
/* 1 when the image fails: a significant block, the whole-image mean, or NaN/infinite pixels. */
int grade_failed(const grade_report *r);
/* The reference in grey, with significantly brighter blocks in red and darker ones in blue. */
int grade_heatmap(image *out, const grade_report *r, const image *ref);
/* The command; exit status 0 pass, 1 fail, 2 bad input. */
int grade_main(int argc, char **argv);
#endif
