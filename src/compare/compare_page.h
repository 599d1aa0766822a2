/* compare_page.h — DIR/index.html of pathlab compare: the estimators' images (with their variances)
 * and the reference in the viewer (image/html_page.h), the table above them as an HTML table with its
 * notes, and below them the error against render time as an inline SVG (util/svg_plot.h) with links
 * to the other files of DIR. */
#ifndef PATHLAB_COMPARE_PAGE_H
#define PATHLAB_COMPARE_PAGE_H
#include "compare/compare_report.h"
#include "image/image.h"

typedef struct {
    const char *title;            /* e.g. "compare: scenes/cornell.obj" */
    const compare_row *rows;      /* one per estimator, labels and flags set */
    const image *img, *var;       /* the estimators' images and variances (var[k].px NULL: unknown) */
    const char *const *slugs;     /* their file names in DIR: SLUG.pfm, heat-SLUG.png */
    int n;
    const image *ref, *ref_var;   /* the reference and its variance (ref_var NULL: unknown) */
    const char *ref_label;
    const char *notes;            /* the notes of table.md: lines "- ...\n" */
} compare_page;

/* Writes path atomically; 0, or 1 after saying why. */
int compare_write_page(const char *path, const compare_page *p);
#endif
