/* compare_outputs.h — what pathlab compare writes once every estimator is rendered and measured:
 * the heatmaps |image - reference| on one scale for all (3 x the largest RMSE, or --scale) so that
 * their colours compare, the notes that say how the numbers were made, the labelled mosaic, the
 * table (table.md with the notes, table.csv, and on stdout) and the page index.html. */
#ifndef PATHLAB_COMPARE_OUTPUTS_H
#define PATHLAB_COMPARE_OUTPUTS_H
#include "compare/compare_results.h"

typedef struct {
    const char *dir;                /* -o DIR: every file goes there */
    const char *scene;              /* in the page's title */
    float exposure;                 /* of the PNGs (--exposure) */
    float scale;                    /* --scale: the heatmaps' white; 0 none given */
    int n;
    compare_estimator *est;         /* [n], rendered and measured, slugs and labels set */
    const compare_reference *ref;
    /* how the numbers were made, for the notes */
    const char *ref_path, *ref_var_path;   /* --ref, --ref-var; ref_path NULL: rendered with ref_flags */
    const char *ref_flags;
    int ref_spp_given;              /* 1: its spp was --ref-spp, not 16 x the largest */
    float time;                     /* --time SEC (equal time), or 0: equal samples of spp each */
    double calib_secs;              /* equal time: the length of the last calibration render */
    int spp, threads;
} compare_outputs;

/* Writes the heatmaps (DIR/heat-SLUG.png), the mosaic (DIR/mosaic.ppm, .png), the tables (DIR/table.md,
 * .csv) and the page (DIR/index.html), and prints the table and the notes. 0, or 1 after saying why. */
int compare_write_outputs(const compare_outputs *o);
#endif
