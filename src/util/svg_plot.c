/* svg_plot.c — log-log error-against-time panels in SVG (see svg_plot.h). Moved out of bench/plot.c
 * so that pathlab compare draws its plot with the same code as the benchmark's docs/bench.svg. */
#include "util/svg_plot.h"
#include <math.h>

/* panel layout, in SVG units: the plot area's margins inside a panel */
#define PL 60.0
#define PR 14.0
#define PT 28.0
#define PB 42.0

/* Okabe-Ito colours (told apart with colour-blindness), yellow replaced by brown on white */
static const char *palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000",
                                "#8C564B", "#999999"};
#define NPAL (int)(sizeof palette / sizeof *palette)

/* The k-th curve's colour. */
static const char *svg_colour(int k) { return palette[k % NPAL]; }

void svg_text(FILE *o, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '<': fputs("&lt;", o); break;
        case '>': fputs("&gt;", o); break;
        case '&': fputs("&amp;", o); break;
        case '"': fputs("&quot;", o); break;
        default: fputc(*s, o);
        }
}

/* Marker k (circle, square, triangle, diamond, again) at (x, y). */
static void svg_marker(FILE *o, int k, double x, double y, const char *colour)
{
    switch (k % 4) {
    case 0: fprintf(o, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"2.8\" fill=\"%s\"/>", x, y, colour); break;
    case 1: fprintf(o, "<rect x=\"%.2f\" y=\"%.2f\" width=\"5\" height=\"5\" fill=\"%s\"/>", x - 2.5, y - 2.5, colour); break;
    case 2: fprintf(o, "<path d=\"M%.2f %.2fL%.2f %.2fL%.2f %.2fZ\" fill=\"%s\"/>", x, y - 3.3, x + 3, y + 2.2, x - 3, y + 2.2, colour); break;
    default: fprintf(o, "<path d=\"M%.2f %.2fL%.2f %.2fL%.2f %.2fL%.2f %.2fZ\" fill=\"%s\"/>", x, y - 3.4, x + 3.2, y, x, y + 3.4, x - 3.2, y, colour); break;
    }
}

/* a decade's label: 0.001 ... 1000 written out, beyond that 1e-5 */
static void decade_label(char *buf, size_t n, int k)
{
    if (k >= -3 && k <= 3) snprintf(buf, n, "%g", pow(10.0, k));
    else snprintf(buf, n, "1e%d", k);
}

/* The plot area and its decades: [xlo, xhi] x [ylo, yhi] in log10, the area's corner and size. */
typedef struct { int xlo, xhi, ylo, yhi; double left, top, w, h; } frame;

static double fx(const frame *f, double t) { return f->left + (log10(t) - f->xlo) / (f->xhi - f->xlo) * f->w; }
static double fy(const frame *f, double v) { return f->top + (f->yhi - log10(v)) / (f->yhi - f->ylo) * f->h; }

/* The decades around the curves' positive points; 0 if there is none. */
static int fit_frame(frame *f, const svg_curve *c, int n, double pad)
{
    double tmin = INFINITY, tmax = 0, rmin = INFINITY, rmax = 0;
    int e, i, any = 0;
    for (e = 0; e < n; e++)
        for (i = 0; i < c[e].n; i++) {
            const svg_point *q = &c[e].p[i];
            if (!(q->err > 0) || !(q->t > 0)) continue;
            any = 1;
            tmin = fmin(tmin, q->t), tmax = fmax(tmax, q->t), rmin = fmin(rmin, q->err), rmax = fmax(rmax, q->err);
        }
    if (!any) return 0;
    tmin *= pow(10.0, -pad), tmax *= pow(10.0, pad), rmin *= pow(10.0, -pad), rmax *= pow(10.0, pad);
    f->xlo = (int)floor(log10(tmin) + 1e-9); f->xhi = (int)ceil(log10(tmax) - 1e-9); if (f->xhi <= f->xlo) f->xhi = f->xlo + 1;
    f->ylo = (int)floor(log10(rmin) + 1e-9); f->yhi = (int)ceil(log10(rmax) - 1e-9); if (f->yhi <= f->ylo) f->yhi = f->ylo + 1;
    return 1;
}

/* Grid lines and labels at the decades, minor ticks at 2..9, the axes' names. */
static void axes(FILE *o, const frame *f, const svg_panel *p)
{
    char lab[32];
    int k, i;
    fprintf(o, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"white\" stroke=\"#444\"/>\n", f->left, f->top, f->w, f->h);
    for (k = f->xlo; k <= f->xhi; k++) {
        double x = f->left + (double)(k - f->xlo) / (f->xhi - f->xlo) * f->w;
        decade_label(lab, sizeof lab, k);
        fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#ddd\"/>", x, f->top, x, f->top + f->h);
        fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" font-size=\"11\">%s</text>\n", x, f->top + f->h + 14, lab);
        for (i = 2; k < f->xhi && i <= 9; i++) {
            double xm = x + log10((double)i) / (f->xhi - f->xlo) * f->w;
            fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#444\"/>", xm, f->top + f->h, xm, f->top + f->h - 3);
        }
    }
    for (k = f->ylo; k <= f->yhi; k++) {
        double y = f->top + (double)(f->yhi - k) / (f->yhi - f->ylo) * f->h;
        decade_label(lab, sizeof lab, k);
        fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#ddd\"/>", f->left, y, f->left + f->w, y);
        fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\" font-size=\"11\">%s</text>\n", f->left - 4, y + 4, lab);
        for (i = 2; k < f->yhi && i <= 9; i++) {
            double ym = y - log10((double)i) / (f->yhi - f->ylo) * f->h;
            fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#444\"/>", f->left, ym, f->left + 3, ym);
        }
    }
    fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" font-size=\"11\">render time (s)</text>\n", f->left + f->w / 2, f->top + f->h + 30);
    fprintf(o, "<text transform=\"translate(%.2f %.2f) rotate(-90)\" text-anchor=\"middle\" font-size=\"11\">", p->x0 + 14, f->top + f->h / 2);
    svg_text(o, p->ylabel);
    fprintf(o, "</text>\n");
}

/* A dashed line of slope -1/2 through (t, err), across the frame. */
static void guide(FILE *o, const frame *f, double t, double err, const char *colour)
{
    double ta = pow(10.0, f->xlo), tb = pow(10.0, f->xhi);
    fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"1.2\" stroke-dasharray=\"6 4\"/>\n",
            fx(f, ta), fy(f, err * sqrt(t / ta)), fx(f, tb), fy(f, err * sqrt(t / tb)), colour);
}

/* Each curve: its polyline, its markers, its own guide when asked. */
static void curves(FILE *o, const frame *f, const svg_curve *c, int n)
{
    int e, i, started, last;
    for (e = 0; e < n; e++) {
        const char *col = svg_colour(e);
        if (!c[e].n) continue;
        fprintf(o, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
        for (i = 0, started = 0, last = -1; i < c[e].n; i++)
            if (c[e].p[i].err > 0 && c[e].p[i].t > 0) {
                fprintf(o, "%s%.2f,%.2f", started ? " " : "", fx(f, c[e].p[i].t), fy(f, c[e].p[i].err));
                started = 1, last = i;
            }
        fprintf(o, "\"/>\n");
        for (i = 0; i < c[e].n; i++)
            if (c[e].p[i].err > 0 && c[e].p[i].t > 0) svg_marker(o, e, fx(f, c[e].p[i].t), fy(f, c[e].p[i].err), col);
        fprintf(o, "\n");
        if (c[e].guide && last >= 0) guide(o, f, c[e].p[last].t, c[e].p[last].err, col);
    }
}

void svg_loglog_panel(FILE *o, const svg_panel *p, const svg_curve *c, int n)
{
    frame f;
    f.left = p->x0 + PL, f.top = p->y0 + PT, f.w = SVG_PANEL_W - PL - PR, f.h = SVG_PANEL_H - PT - PB;
    fprintf(o, "<g>\n<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">", f.left + f.w / 2, p->y0 + 18);
    svg_text(o, p->title);
    fprintf(o, "</text>\n");
    if (!fit_frame(&f, c, n, p->pad)) {
        fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">no positive error</text>\n</g>\n", f.left + f.w / 2, f.top + f.h / 2);
        return;
    }
    fprintf(o, "<clipPath id=\"clip%d\"><rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/></clipPath>\n", p->id, f.left, f.top, f.w, f.h);
    axes(o, &f, p);
    fprintf(o, "<g clip-path=\"url(#clip%d)\">\n", p->id);
    if (p->tstar > 0) {
        double x = fx(&f, p->tstar);
        fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#888\" stroke-dasharray=\"1 3\"/>\n", x, f.top, x, f.top + f.h);
        fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"10\" fill=\"#666\">T*</text>\n", x + 3, f.top + 11);
    }
    if (p->guide_t > 0 && p->guide_err > 0) guide(o, &f, p->guide_t, p->guide_err, "#666");
    curves(o, &f, c, n);
    fprintf(o, "</g>\n</g>\n");
}

double svg_legend(FILE *o, const svg_curve *c, int n, const char *guide_text, double x0, double y0, double width, int per_row)
{
    int i, k = 0;
    for (i = 0; i <= n; i++) {
        double x = x0 + (k % per_row) * (width / per_row), y = y0 + (k / per_row) * 20 + 10;
        if (i < n && !c[i].n) continue;
        if (i == n && !guide_text) break;
        k++;
        if (i < n) {
            fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"1.5\"/>", x, y, x + 24, y, svg_colour(i));
            svg_marker(o, i, x + 12, y, svg_colour(i));
            fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"12\">", x + 30, y + 4);
            svg_text(o, c[i].name);
        } else {
            fprintf(o, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#666\" stroke-width=\"1.2\" stroke-dasharray=\"6 4\"/>", x, y, x + 24, y);
            fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"12\">", x + 30, y + 4);
            svg_text(o, guide_text);
        }
        fprintf(o, "</text>\n");
    }
    return ((k + per_row - 1) / per_row) * 20;
}
