/* html_page.h — one self-contained HTML page that shows linear images in pathlab's viewer: the
 * viewer's script and style (web/viewer.js, web/viewer.css) are embedded into the binary at build
 * time and into the page when it is written, the images travel inside the page as linear half floats
 * and are tone-mapped there. No network, no external file: the page works offline in any browser.
 * The viewer offers exposure and gamma, zoom and pan, the pixel under the mouse (value, reference,
 * difference, z-score with a variance), a split view and a signed difference against the reference,
 * the images cycled with the keyboard, a scanline plot, channel toggles, and layers as a strip. */
#ifndef PATHLAB_HTML_PAGE_H
#define PATHLAB_HTML_PAGE_H
#include <stddef.h>
#include <stdio.h>
#include "image/image.h"

typedef struct {
    const char *name;    /* its label in the page: "alice.pfm", "mis-power", "L1" */
    const image *img;    /* linear RGB */
    const image *var;    /* the variance of each pixel's mean (for z-scores), or NULL */
    const char *link;    /* a page the label links to (e.g. a student's own page), or NULL */
} html_image;

typedef struct {
    int x, y, w, h;      /* a region in pixels, row 0 = the top row */
    const char *label;   /* what is there, e.g. "too bright: +4.2 sigma" */
} html_mark;

typedef struct {
    const char *title;
    const html_image *images; int nimages;   /* cycled with the keyboard; at least one */
    const html_image *ref;                   /* the reference, or NULL */
    const html_image *strip; int nstrip;     /* --split layers (L0, L1, ...), each at its own exposure */
    const html_mark *marks; int nmarks;      /* regions outlined over the images */
    const char *before_html;                 /* trusted HTML above the viewer (verdict, tables), or NULL */
    const char *after_html;                  /* trusted HTML below it (plots, notes), or NULL */
    size_t max_bytes;                        /* 0, or: when the images in half floats would take more, they
                                                go as RGBE (8-bit mantissas, one exponent a pixel: 0.2-0.4%
                                                of the largest channel) in base 85, variances left out:
                                                5 bytes a pixel instead of 8 an image and 8 a variance */
} html_page;

/* Writes the page atomically (sys/atomic_file.h). 0 on success; else "path: reason" on stderr. */
int html_page_write(const char *path, const html_page *page);
/* A copy of text with & < > " ' escaped for HTML, to free; NULL when out of memory. Control and
 * bidirectional characters first become visible escapes, as on the terminal (sys/shown.h): a name
 * can neither reorder nor hide what the page shows. The page's JSON strings (names, labels) too. */
char *html_escape(const char *text);
/* text escaped into f (for the pages' own HTML: tables, verdicts); 1 when out of memory. */
int html_put_escaped(FILE *f, const char *text);
/* "data:MIME;base64,..." of n bytes, to free; NULL when out of memory. The page's Content-Security-
 * Policy lets images load from data: URIs only (no file, no network): a PNG heatmap or an SVG plot in
 * before_html/after_html goes in as <img src="data:image/png;base64,...">. */
char *html_data_uri(const char *mime, const void *bytes, size_t n);
#endif
