/* svg_plot.h — log-log plots of error against render time in SVG, drawn by bench-plot (docs/bench.svg,
 * bench/plot.c) and by pathlab compare (DIR/index.html): one panel with decades, minor ticks and a
 * clip, one line of markers per curve (Okabe-Ito colours, four marker shapes), dashed guides of
 * slope -1/2 (what an unbiased Monte Carlo estimator follows), and a legend. Text is escaped. */
#ifndef PATHLAB_SVG_PLOT_H
#define PATHLAB_SVG_PLOT_H
#include <stdio.h>

#define SVG_PANEL_W 330.0
#define SVG_PANEL_H 270.0

typedef struct { double t, err; } svg_point;   /* seconds, error; points with err <= 0 are left out */

typedef struct {
    const char *name;        /* in the legend */
    const svg_point *p;      /* joined in this order; n = 0: not drawn (its colour kept for its index) */
    int n;
    int guide;               /* 1: a dashed line of slope -1/2 through its last point, in its colour */
} svg_curve;

typedef struct {
    double x0, y0;           /* the panel's top-left corner in the figure */
    const char *title, *ylabel;
    double tstar;            /* > 0: a dotted vertical line labelled T* there */
    double guide_t, guide_err;   /* > 0: a grey dashed line of slope -1/2 through this point */
    double pad;              /* decades of room around the points before the axes round out to decades (0: none) */
    int id;                  /* unique in the figure: names its clip path */
} svg_panel;

/* s with < > & " escaped. */
void svg_text(FILE *o, const char *s);
/* One panel of SVG_PANEL_W x SVG_PANEL_H: axes over the curves' range (decades), then the curves. */
void svg_loglog_panel(FILE *o, const svg_panel *p, const svg_curve *c, int n);
/* The legend at (x, y): per_row entries a row over width, one per curve with points, then the guide's
 * entry when guide_text is not NULL. Returns its height. */
double svg_legend(FILE *o, const svg_curve *c, int n, const char *guide_text, double x, double y, double width, int per_row);
#endif
