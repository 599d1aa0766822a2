/* compare_files.c — DIR, its files, and the reference given (compare_files.h). */
#include "compare/compare_files.h"
#include "sys/shown.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "sys/output_path.h"
#include "image/radiance.h"

/* compare's own files, DIR/NAME.*, which no estimator may write over. */
static const char *const RESERVED[] = {"reference", "mosaic", "table", "index", NULL};

int compare_check_names(const compare_estimator *est, int n)
{
    int i, j;
    for (i = 0; i < n; i++) {
        const compare_estimator *e = &est[i];
        const char *label = e->row.label;
        for (j = 0; RESERVED[j]; j++)
            if (!strcmp(e->slug, RESERVED[j])) {
                fprintf(stderr, "pathlab: compare: label '%s' would write over DIR/%s.*: name it, e.g. \"my %s=%s\"\n",
                        shown(label), shown(RESERVED[j]), shown(label), shown(e->row.flags));
                return 1;
            }
        if (!strncmp(e->slug, "heat-", 5)) {   /* its picture DIR/heat-X.png would be estimator X's heatmap */
            fprintf(stderr, "pathlab: compare: label '%s' would write DIR/%s.png, a heatmap's name (heat-LABEL.png): name it "
                    "otherwise\n", shown(label), shown(e->slug));
            return 1;
        }
        for (j = 0; j < i; j++)
            if (!strcmp(e->slug, est[j].slug)) {
                fprintf(stderr, "pathlab: compare: estimators '%s' and '%s' would both write DIR/%s.pfm: label one (LABEL=FLAGS)\n",
                        shown(est[j].row.label), shown(label), shown(e->slug));
                return 1;
            }
    }
    return 0;
}

int compare_make_dir(const char *dir)
{
    if (mkdir(dir, 0777) && errno != EEXIST) {
        fprintf(stderr, "pathlab: compare: cannot create %s: %s\n", shown(dir), strerror(errno));
        return 1;
    }
    return 0;
}

int compare_out_path(char *path, const char *dir, const char *pre, const char *slug, const char *ext)
{
    if (snprintf(path, PATH_CAP, "%s/%s%s%s", dir, pre, slug, ext) >= PATH_CAP) {
        fprintf(stderr, "pathlab: compare: path too long in %s\n", shown(dir));
        return 1;
    }
    return 0;
}

int compare_save_image(const char *dir, const char *pre, const char *slug, const char *ext, const image *im, float exposure)
{
    char path[PATH_CAP];
    return compare_out_path(path, dir, pre, slug, ext) || img_write(im, path, exposure);
}

int compare_read_reference(compare_reference *ref, const char *path, const char *var_path, int w, int h)
{
    image *img = &ref->img, *var = &ref->var;
    if (img_read_pfm(img, path)) return 1;
    /* a NaN made every RMSE nan, a negative variance an error below zero: each is said, and stops */
    if (img_check_radiance(img, path, 4)) return 1;
    if (img->w != w || img->h != h) {
        fprintf(stderr, "pathlab: compare: the reference %s is %dx%d but the renders are %dx%d (use --size %dx%d, or another reference)\n",
                shown(path), img->w, img->h, w, h, img->w, img->h);
        return 1;
    }
    if (var_path && (img_read_pfm(var, var_path) || img_check_radiance(var, var_path, 4))) return 1;
    if (var_path && (var->w != w || var->h != h)) {
        fprintf(stderr, "pathlab: compare: --ref-var %s is %dx%d but the reference is %dx%d\n", shown(var_path), var->w, var->h, w, h);
        return 1;
    }
    snprintf(ref->label, sizeof ref->label, "reference");
    return 0;
}
