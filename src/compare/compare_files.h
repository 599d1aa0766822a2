/* compare_files.h — the files of pathlab compare one by one: DIR made, DIR/PRE SLUG EXT written
 * (DIR/heat-light.png), and the reference given with --ref (and --ref-var) read at the renders' size. */
#ifndef PATHLAB_COMPARE_FILES_H
#define PATHLAB_COMPARE_FILES_H
#include "compare/compare_results.h"

/* Each estimator writes DIR/SLUG.*: not one of compare's own files (reference, mosaic, table, index),
 * nor another estimator's. 0, or 1 after saying which and how to label it. */
int compare_check_names(const compare_estimator *est, int n);
/* Makes DIR if missing; 0, or 1 after saying why. */
int compare_make_dir(const char *dir);
/* DIR/PRE SLUG EXT into path[PATH_CAP]; 0, or 1 when too long (said). */
int compare_out_path(char *path, const char *dir, const char *pre, const char *slug, const char *ext);
/* Writes im as DIR/PRE SLUG EXT (exposure for PPM and PNG); 0, or 1 after saying why. */
int compare_save_image(const char *dir, const char *pre, const char *slug, const char *ext, const image *im, float exposure);
/* Reads the reference at path and, if var_path is not NULL, its variance: both w x h. 0, or 1 after
 * saying why. */
int compare_read_reference(compare_reference *ref, const char *path, const char *var_path, int w, int h);
#endif
