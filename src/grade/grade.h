/* grade.h — `pathlab grade IMAGE.pfm... --ref REF.pfm`: is the difference from a reference noise or
 * bias? The verdict a teacher needs, with where and how much when it is bias. The statistics are
 * described at the top of grade.c; the likely mistakes in grade_diagnose.h; the command in cmd/grade.c. */
#ifndef PATHLAB_GRADE_H
#define PATHLAB_GRADE_H
#include "image/image.h"

typedef struct {
    double alpha;        /* family-wise level of the verdict (default 0.01) */
    int block;           /* block side in pixels; 0: chosen from the image size */
    int spp, ref_spp;    /* the image's and the reference's samples per pixel; 0 if not given */
    int ref_var_dof;     /* degrees of freedom of the reference's variance (its sidecar's variance-dof); 0: many */
    const image *step;   /* the image's quantisation step per pixel-channel (an RGBE file: grade_rgbe_steps), or
                            NULL: a uniform error of one step, variance step^2 / 12, is added to its noise and
                            half a step to the tolerance of the exact pixels */
} grade_opts;

/* A group of pixels tested together: a block of the image, or a level (the pixels whose reference
 * luminance lies in [lum_lo, lum_hi), wherever they are). Exact pixels are left out of both. */
typedef struct {
    int x0, y0, x1, y1;      /* block: the pixels [x0, x1) x [y0, y1); level: the box around its pixels */
    double lum_lo, lum_hi;   /* level only */
    long n;                  /* noisy pixels in the group */
    double diff[3], ref[3];  /* mean of image - ref and mean of ref, per channel */
    double var[3], round[3]; /* sample variance of d over the group; rounding bound of its mean */
    double skew[3];          /* sample skewness of d over the group (see skewed_limit in grade.c) */
    double floor[3];         /* the least variance of its mean d: k x the reference's (see grade.c) */
    double quant[3];         /* the variance of its mean d from the image's quantisation (grade_opts.step) */
    double noise[3];         /* the variance of its mean d used by the tests */
    long nzero;              /* pixels black in the image where the reference is not */
    int rare;                /* 1: mostly black there, rare-event noise: not judged */
    double t[3];             /* Student's t of the mean difference, per channel */
    int df;                  /* its degrees of freedom: n - 1 */
    int sign;                /* +1 significantly brighter, -1 darker, 0 consistent with noise */
    int channel;             /* the channel that decided the sign */
} grade_block;

/* A PASS needs evidence: the plain mean of d known to within this much of the reference's mean
 * (one standard error), else the image is too noisy to judge (a FAIL). An image black but for one
 * pixel that holds all the light has no other test (its blocks are rare-event noise, its t is about
 * 1 whatever that pixel): its standard error is about 100% of the mean. Honest 64x64 renders at 1
 * spp: 5-9% on the Cornell boxes, up to 90% on mis-plates (a firefly holds most of the light). */
#define GRADE_MAX_REL_SE 0.5

/* Blocks at a coarser scale: side 2, 4, 8... times the finest, down to 2 x 2 blocks. */
typedef struct {
    int side, nbx, nby, nblocks;
    grade_block *blocks;
    double level, excess;        /* per-test level; largest |t| / critical |t| */
    int brighter, darker;
} grade_scale;

#define GRADE_MAX_COARSE 8

typedef struct {
    double alpha;
    int w, h, block, nbx, nby, nblocks;  /* nblocks = nbx * nby, each tested in 3 channels */
    grade_block *blocks;                 /* row-major, nby rows of nbx */
    double block_level, block_tcrit, block_tmax;  /* per-test level, critical |t| of a full block */
    double block_excess, level_excess;   /* largest |t| / its critical |t| in each family */
    int nbrighter, ndarker;
    grade_scale coarse[GRADE_MAX_COARSE];  /* the blocks at coarser scales, finest first */
    int ncoarse;
    grade_block *levels;                 /* nlevels groups by the reference's luminance */
    int nlevels, nlevels_tested, level_brighter, level_darker;
    double level_level, level_tmax, level_min_lum;  /* levels hold the pixels above the mean luminance */
    double image_diff[3], image_ref[3];  /* plain means of d and of ref */
    double image_eps[3], image_eps_se[3], image_z[3], image_level, image_zcrit;  /* relative-bias fit */
    double image_zlimit[3];              /* image_zcrit widened by the skewness, per channel */
    double plain_t[3], plain_limit[3];   /* the unweighted mean of d over the noisy pixels */
    double plain_rel_se;                 /* its standard error over the reference's mean there, the largest channel */
    int too_noisy;                       /* 1: plain_rel_se over GRADE_MAX_REL_SE: too noisy to judge (a FAIL) */
    int image_fail, image_nfit;          /* image_nfit: block-channels with a weight in the fit */
    double floor_k[3];                   /* the noise floor's scale, per channel (0 without REF_var) */
    unsigned char *exact;                /* per pixel: 1 if the reference is noise-free there */
    int exact_from_var;                  /* 1: told by the reference's variance; 0: guessed */
    long nexact, exact_fail;             /* exact pixels, and those the image misses */
    long black_rare;                     /* black and flat in the reference, yet light may be rare there: not exact */
    int exact_x, exact_y;                /* the worst miss */
    long exact_side[2];                  /* misses darker (0) and brighter (1) than the reference */
    int exact_box[2][4];                 /* the box around each: x0, y0, x1, y1 (exclusive) */
    double exact_img[3], exact_ref[3];
    const image *step;                   /* the image's quantisation step (grade_opts.step), or NULL */
    int pixel_test;                      /* 1 when the per-pixel Z-test ran (--var, --spp, --ref-spp) */
    long pixel_n, pixel_fail;
    double pixel_zcrit;
} grade_report;

/* Runs the tests: ref_var (may be NULL) is the reference's variance of the pixel mean; where it is
 * 0 the reference is exact. Returns 0, or 1 when the sizes differ or memory runs out. The images
 * must be finite (cmd/grade.c checks). Free the report with grade_free. */
int grade_compute(grade_report *r, const image *img, const image *ref, const image *ref_var, const grade_opts *o);
void grade_free(grade_report *r);
/* The RGBE step of each pixel of an image read from an .hdr: 2^(e - 136) for the exponent e of its
 * largest channel, told from the decoded value (its mantissa in [128, 256)); 0 for a black pixel.
 * Replicated in R, G, B. 0, or 1 when out of memory. */
int grade_rgbe_steps(image *steps, const image *img);
/* 1 when a test finds bias: a missed exact pixel, a significant block or level, or the whole image. */
int grade_biased(const grade_report *r);
/* 1 when the image fails: biased, or too noisy to judge (too_noisy). */
int grade_failed(const grade_report *r);
/* How far the worst statistic is beyond its limit: <= 1 passes the tests with a level (a missed
 * exact pixel counts as 1e9). The diagnosis compares hypotheses with it. */
double grade_excess(const grade_report *r);
/* How much bias the image holds, in units of its noise: the sum over the finest blocks and channels
 * of t^2 - 1 (0 on average without bias: a chi-square's excess), and its standard deviation without
 * bias in *sd. The diagnosis asks that a mistake remove 99% of it. */
double grade_bias_energy(const grade_report *r, double *sd);
/* The heatmap: the reference in grey, tone-mapped Y / (Y + mid) (mid = grade_heatmap_mid: its mean
 * luminance shows as mid-grey, so a dark scene stays visible), each finest block tinted by its
 * signed t (red brighter, blue darker): lightly below the limit (|t| / limit x 0.35), from 0.6 at
 * the limit to full colour at twice it; the coarser scales' significant blocks in light tints. */
double grade_heatmap_mid(const image *ref);
int grade_heatmap(image *out, const grade_report *r, const image *ref);
#endif
