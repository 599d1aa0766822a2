/* grade_page.h — grade's pages (image/html_page.h): one per graded image, with the image, the
 * reference (and its variance), the significant regions outlined as marks ("too dark: -5.1 sigma")
 * and the verdict with the likely mistakes above; and the class report as a page (--report X.html):
 * the class's images against the reference in the viewer and the class's table above it, each row
 * and each image linked to its image's page. */
#ifndef PATHLAB_GRADE_PAGE_H
#define PATHLAB_GRADE_PAGE_H
#include "grade/grade_diagnose.h"
#include "grade/grade_print.h"
#include "image/html_page.h"

#define GRADE_MAX_MARKS 256

/* The marks and their labels' storage. */
typedef struct {
    html_mark m[GRADE_MAX_MARKS];
    char label[GRADE_MAX_MARKS][96];
    int n;
} grade_marks;


typedef struct {
    const char *path;                     /* the page to write */
    const char *ref_path, *var_path;      /* as given (var_path NULL: none) */
    const image *img;
    const grade_refs *refs;
    const grade_report *r;
    const grade_row *row;                 /* verdict, bias, where */
    const grade_hypothesis *h;            /* the likely mistakes, best first */
    int nh;
    const char *back;                     /* a link to the class report, or NULL */
} grade_page;

/* 0, or 1 after saying why. */
int grade_write_page(const grade_page *p);
/* The class report as a page: the table of the rows (row.page links) above the viewer, which shows
 * the graded images imgs[k] (px NULL: left out; imgs NULL: none), each labelled with a link to its
 * page, against the reference (the reference alone when no image was graded). */
int grade_write_class_page(const char *path, const grade_row *rows, int n, const grade_opts *o, const char *ref_path,
                           const grade_refs *refs, const image *imgs);
#endif
