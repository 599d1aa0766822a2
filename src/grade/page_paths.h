/* page_paths.h — where grade's pages go and how they link: the pages' folder (--pages DIR, else
 * REPORT-pages beside the report, whose links are then relative and survive moving both), each
 * image's page in it (PAGES/NAME.html, NAME one-to-one with the image's name), the report's link to a page and the pages' link back to the report. */
#ifndef PATHLAB_GRADE_PAGE_PATHS_H
#define PATHLAB_GRADE_PAGE_PATHS_H
#include <stddef.h>
#include "sys/output_path.h"

typedef struct {
    const char *report;      /* --report, or NULL */
    char dir[PATH_CAP];      /* the pages' folder; "" none */
    char back[PATH_CAP];     /* the pages' link to the report, or "" */
} grade_pages;

/* Sets the folder and the link back from pages (--pages, or NULL) and report (or NULL), and makes
 * the folder if missing. 0, or 1 after saying why. */
int grade_pages_setup(grade_pages *p, const char *pages, const char *report);
/* The name of an image's outputs (its page NAME.html, its heatmap NAME.png), one-to-one with the
 * image's name: its file name without ".pfm" (skip < 0), or, when other images of the run have the
 * same file name, its path as given without its first skip bytes (the folders all of them share:
 * students/ana/render.pfm and students/ben/render.pfm are ana/render and ben/render); lowercase letters,
 * digits, '-' and '.' (not first) kept, every other byte written _XX (its hex: "a b.pfm" is a_20b,
 * "a_b.pfm" a_5fb, ana/render ana_2frender), "_" appended to a name without ".pfm"; a name that
 * would pass GRADE_NAME_LONG characters is cut there and ends with _h and 24 hex digits of its SHA-256. */
#define GRADE_NAME_LONG 160
#define GRADE_NAME_CAP (GRADE_NAME_LONG + 4 + 27 + 2)
void grade_output_name(char out[GRADE_NAME_CAP], const char *image, int skip);
/* The page of image into out[cap]: PAGES/NAME.html. 0, or 1 when it does not fit (said). */
int grade_page_path(char *out, size_t cap, const grade_pages *p, const char *image, int skip);
/* The link from the report to the page: relative when it lies under the report's folder, else absolute. */
void grade_page_link(char *out, size_t cap, const grade_pages *p, const char *page);
/* skip[k]: -1 when images[k]'s file name is its own in the run, else the length of the folders that
 * the images of that file name share (their outputs are named by the rest of their paths). 0, or 1
 * when out of memory. */
int grade_mark_same_names(const char *const *images, int n, int *skip);
#endif
