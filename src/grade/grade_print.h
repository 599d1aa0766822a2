/* grade_print.h — grade's words: the tests and the verdict of one image in full, and the one-line
 * summary (a row) that the class report and the class's lines share. */
#ifndef PATHLAB_GRADE_PRINT_H
#define PATHLAB_GRADE_PRINT_H
#include <stddef.h>
#include "grade/grade.h"
#include "grade/grade_diagnose.h"
#include "sys/output_path.h"

/* One graded image, as a row of the class report. */
typedef struct {
    const char *path;
    int status;              /* 0 pass, 1 fail, 2 could not be read */
    int w, h;
    double bias, bias_se;    /* relative bias of the channel furthest from 0 (whole-image fit); when the
                                fit passes, the plain mean's relative difference (se -1) if that test
                                failed, else the difference where the groups are significant (se -2) */
    char channel[8];         /* that channel's name, "mean", "groups", or "" for no figure */
    char where[160];         /* where the significant groups are; "" if none */
    char mistake[1024];      /* the likely mistakes, "; " between them; the input error for status 2 */
    char page[PATH_CAP];     /* its page (grade_page.h) as the class report links it; "" if none */
    char remark[640];        /* flagged (grade/integrity.h: a copy of the reference or of another image, made
                                from the reference) or an output not written and why; "" if none */
    unsigned char sha[32];   /* the SHA-256 of its pixels, when hashed */
    int hashed;
    int flagged;             /* 1: the remark holds an integrity flag (a copy, or made from the reference) */
    int output_failed;       /* 1: its page or heatmap could not be written (the remark says why): exit 2 */
} grade_row;

/* The tests that ran, their levels and counts, then the verdict with where and how much. */
void grade_print_report(const grade_report *r, const char *image, const char *ref, const grade_opts *o);
/* The likely mistakes, one per line ("likely: ..."), or a line saying none of the catalogue fits. */
void grade_print_hypotheses(const grade_hypothesis *h, int n);
/* Fills the row's bias and where from a report. */
void grade_fill_row(grade_row *row, const grade_report *r);
/* The row's bias as the report writes it: "+1.20% +- 0.30% (green)", "-5.00% (plain mean)",
 * "+2.00% (where significant)", or "" when there is none. */
void grade_bias_text(char *out, size_t cap, const grade_row *row);
/* Where the box [x0, x1) x [y0, y1) lies in a w x h image, in words: "the top-left", "most of the image"... */
void grade_describe_box(char *s, size_t cap, int x0, int y0, int x1, int y1, int w, int h);
/* "A.pfm: FAIL, darker -54.4% +- 0.6% in green (the top-centre); likely: no L0 ..." */
void grade_print_row(const grade_row *row);
#endif
