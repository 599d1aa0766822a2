/* grade_diagnose.h — the likely mistake behind a failing image. Each hypothesis of a catalogue
 * (flipped, grey, sRGB curve, clamped, quantised, a global factor, bounces missing...) undoes the
 * mistake, on the image or on the reference, and grades again: a hypothesis that makes the image
 * pass explains the difference. A few are told by the image's values alone (every value a multiple
 * of 1/255, R = G = B everywhere): those are evidence without a grading. */
#ifndef PATHLAB_GRADE_DIAGNOSE_H
#define PATHLAB_GRADE_DIAGNOSE_H
#include "grade/grade.h"

#define GRADE_MAX_LAYERS 8

/* The reference and what was found beside it. */
typedef struct {
    const image *ref, *var;               /* var: REF_var.pfm, or NULL */
    const image *layer[GRADE_MAX_LAYERS]; /* L0, L1, ... of the same view (--split), or NULL */
    int nlayers;                          /* layers 0..nlayers-1 are all present */
    int channels;                         /* of the reference's file: 3 (PF) or 1 (Pf) */
    int pixel_center;                     /* its sidecar: 1 rendered with --pixel-center, 0 jittered, -1 unknown */
} grade_refs;

typedef struct {
    char what[160];       /* the mistake, e.g. "flipped vertically (rows written top to bottom?)" */
    char evidence[200];   /* why we think so, e.g. "grading the flipped image passes" */
    double excess;        /* grade_excess under the hypothesis; 0 for evidence from the values */
    int passes;           /* 1: grading under the hypothesis passes (or the values prove it) */
} grade_hypothesis;

/* Tries the catalogue on an image that failed with grade_excess excess0; fills out[0..max) with the
 * hypotheses that explain the difference (pass with the worst statistic below half excess0, or bring it below a tenth of
 * excess0 and below 3 times its limit: two mistakes at once, Jensen at low spp), best first, and returns how many. -1 when out of memory. */
int grade_diagnose(const image *img, const grade_refs *refs, const grade_opts *o, double excess0,
                   grade_hypothesis *out, int max);
#endif
