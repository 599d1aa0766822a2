/* compare_results.h — what pathlab compare measures: each estimator's render (with the variance of
 * its pixels' means, for the page's z-scores), its error heatmap and its row of the table; and the
 * reference, whose own noise (the mean variance of its pixels, when known) adds to every squared
 * error: E|I - R|^2 = E|I - L|^2 + Var R for independent I and R. */
#ifndef PATHLAB_COMPARE_RESULTS_H
#define PATHLAB_COMPARE_RESULTS_H
#include <stdint.h>
#include "compare/compare_report.h"
#include "image/image.h"

#define COMPARE_MAX_EST 16

/* One estimator's results: its render, its error heatmap and its line of the table. */
typedef struct {
    const char *slug;        /* its files: DIR/SLUG.pfm, DIR/heat-SLUG.png */
    image img, var, heat;
    compare_row row;         /* label, flags, spp, time, errors, efficiency */
} compare_estimator;

/* The reference: given (--ref, --ref-var) or rendered. */
typedef struct {
    image img, var;          /* var.px is NULL when its variance is unknown */
    double mean_var;         /* the mean of var: the reference's own noise in every MSE (0 if unknown) */
    int spp;                 /* the samples, seed and time of a rendered reference */
    uint64_t seed;
    double secs;
    char label[160];         /* over its panel in the mosaic */
} compare_reference;

/* Frees the images of est[0..n). */
void compare_estimators_free(compare_estimator *est, int n);
/* Sets ref->mean_var from its variance (0 when unknown). */
void compare_reference_noise(compare_reference *ref);
/* The errors of img against the reference (RMSE, relMSE, MAE raw; MSE less the reference's noise),
 * and the efficiency 1 / (MSE x r->secs). */
void compare_measure(compare_row *r, const image *img, const compare_reference *ref);
#endif
