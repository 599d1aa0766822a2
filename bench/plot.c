/* bench/plot.c — the numbers of the time-to-error benchmark (bench/sweep.sh), built as build/bench-plot:
 *
 *   bench-plot error IMAGE.pfm REF.pfm [REF_VAR.pfm]
 *       one line "rmse R rmse_raw R0 relmse X mae M mean_image A mean_ref B var_ref V":
 *       rmse_raw = sqrt(mean (a-b)^2) over all pixel-channels; the reference is itself noisy, with
 *       E[(a-b)^2] = (E a - E b)^2 + Var a + Var b, so given its variance of the pixel mean (pathlab
 *       --variance) rmse = sqrt(max(0, mean (a-b)^2 - mean var_b)) is the RMSE against the
 *       reference's expectation (without this the curves flatten where the image's noise falls to the
 *       reference's). relmse = mean(((a-b)^2 - var_b) / (b^2 + 0.01)), corrected the same way (pathlab
 *       diff's relMSE, same 0.01); mae = mean |a-b|, raw (its noise part cannot be removed).
 *
 *   bench-plot report RESULTS.csv OUT.svg [--metric rmse|relmse] [--fit-min SPP] [--caption TEXT]...
 *       reads the sweep's CSV (lines starting with '#' are comments; a header line names the columns,
 *       of which scene, estimator, spp, seconds and rmse are used, flags too when present; with
 *       --metric relmse, the column relmse instead of rmse, and the error is sqrt(relmse)), writes
 *       OUT.svg (one log-log panel of RMSE against time per scene, one curve per estimator) and prints
 *       a Markdown table on stdout, per scene:
 *       - slopes: least squares of log RMSE against log seconds and against log spp over the points
 *         with spp >= SPP (default 4: at 1 or 2 spp the time is too short to measure well); -0.5
 *         is what an unbiased Monte Carlo estimator gives;
 *       - ranking by efficiency 1/(MSE x time) at one common time T*, the longest time that every
 *         curve of the scene reached (so no curve is extended beyond its last point): each curve's
 *         RMSE at T* is interpolated in log-log between its two points around T* (below its first
 *         point: extended from it along time^-1/2, marked); "x the best" = the best's efficiency /
 *         this one's = how many times the best's time this estimator needs for the same error.
 *
 * Exit 0, or 2 with a message naming the file (and line) on bad input; OUT.svg is written to a
 * temporary file and renamed, so a failed run leaves no partial SVG. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "image/image.h"
#include "util/svg_plot.h"

#define MAX_SCENES 32
#define MAX_EST 16
#define NAME_LEN 64
#define FLAGS_LEN 160
#define MAX_CAPTION 8

typedef struct { double spp, t, rmse; } point;
typedef struct {
    point *p;
    int n, cap;
    double slope_t, slope_s;   /* NAN when fewer than two usable points */
    double r_star, eff, ratio; /* RMSE at the scene's T*, 1/(MSE T*), best eff / eff */
    int extrap, rank;
} curve;

typedef struct {
    const char *metric;        /* the error column: "rmse", or "relmse" (then error = sqrt(relmse)) */
    char scene[MAX_SCENES][NAME_LEN], est[MAX_EST][NAME_LEN], flags[MAX_EST][FLAGS_LEN];
    int nscenes, nest;
    curve c[MAX_SCENES][MAX_EST];
    double tstar[MAX_SCENES];
} results;

/* ---------- error of an image against a noisy reference ---------- */

static int error_cmd(int argc, char **argv)
{
    image im[3];
    int k, i, m, n = argc;
    double d, se = 0, rel = 0, ae = 0, sa = 0, sb = 0, sv = 0, mse, msv;
    if (n < 2 || n > 3) {
        fprintf(stderr, "usage: bench-plot error IMAGE.pfm REF.pfm [REF_VAR.pfm]\n");
        return 2;
    }
    for (k = 0; k < n; k++) {
        if (img_read_pfm(&im[k], argv[k])) { while (k--) img_free(&im[k]); return 2; }
        if (k > 0 && (im[k].w != im[0].w || im[k].h != im[0].h)) {
            fprintf(stderr, "bench-plot: %s is %dx%d, %s is %dx%d\n", argv[k], im[k].w, im[k].h, argv[0], im[0].w, im[0].h);
            while (k >= 0) img_free(&im[k--]);
            return 2;
        }
    }
    m = 3 * im[0].w * im[0].h;
    for (i = 0; i < m; i++) {
        double a = im[0].px[i], b = im[1].px[i], v = n == 3 ? im[2].px[i] : 0.0;
        if (!isfinite(a) || !isfinite(b) || !isfinite(v)) {
            fprintf(stderr, "bench-plot: non-finite value at pixel %d, channel %d of %s\n", i / 3, i % 3,
                    !isfinite(a) ? argv[0] : !isfinite(b) ? argv[1] : argv[2]);
            for (k = 0; k < n; k++) img_free(&im[k]);
            return 2;
        }
        d = a - b;
        se += d * d;
        rel += (d * d - v) / (b * b + 0.01);
        ae += fabs(d);
        sa += a;
        sb += b;
        sv += v;
    }
    mse = se / m;
    msv = sv / m;
    printf("rmse %.6g rmse_raw %.6g relmse %.6g mae %.6g mean_image %.6g mean_ref %.6g var_ref %.6g\n",
           sqrt(mse > msv ? mse - msv : 0.0), sqrt(mse), rel / m, ae / m, sa / m, sb / m, msv);
    for (k = 0; k < n; k++) img_free(&im[k]);
    return 0;
}

/* ---------- fits and ranking (also what tests/test_bench_plot.sh checks) ---------- */

/* Least squares slope of log y against log x over the points with spp >= fit_min and rmse > 0;
 * by_time selects x = seconds, else x = spp. NAN if fewer than two distinct x. */
static double loglog_slope(const curve *c, int by_time, double fit_min)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, x, y, den;
    int i, m = 0;
    for (i = 0; i < c->n; i++) {
        if (c->p[i].spp < fit_min || !(c->p[i].rmse > 0)) continue;
        x = log(by_time ? c->p[i].t : c->p[i].spp);
        y = log(c->p[i].rmse);
        sx += x; sy += y; sxx += x * x; sxy += x * y; m++;
    }
    den = m * sxx - sx * sx;
    if (m < 2 || !(den > 1e-12 * m * m)) return NAN;
    return (m * sxy - sx * sy) / den;
}

/* The longest time with a positive RMSE on the curve (0 if none). */
static double curve_tmax(const curve *c)
{
    double t = 0;
    int i;
    for (i = 0; i < c->n; i++)
        if (c->p[i].rmse > 0 && c->p[i].t > t) t = c->p[i].t;
    return t;
}

/* RMSE at time T: log-log interpolation between consecutive points (in spp order) whose times
 * bracket T; otherwise extended along time^-1/2 from the point nearest in time (*extrap set). */
static double rmse_at(const curve *c, double T, int *extrap)
{
    int i, near = -1;
    *extrap = 0;
    for (i = 0; i + 1 < c->n; i++) {
        const point *a = &c->p[i], *b = &c->p[i + 1];
        if (!(a->rmse > 0) || !(b->rmse > 0)) continue;
        if ((a->t <= T && T <= b->t) || (b->t <= T && T <= a->t)) {
            double f = a->t == b->t ? 0.0 : log(T / a->t) / log(b->t / a->t);
            return exp(log(a->rmse) + f * log(b->rmse / a->rmse));
        }
    }
    for (i = 0; i < c->n; i++)
        if (c->p[i].rmse > 0 && (near < 0 || fabs(log(c->p[i].t / T)) < fabs(log(c->p[near].t / T)))) near = i;
    if (near < 0) return NAN;
    if (c->p[near].t != T) *extrap = 1;
    return c->p[near].rmse * sqrt(c->p[near].t / T);
}

static int cmp_spp(const void *a, const void *b)
{
    double x = ((const point *)a)->spp, y = ((const point *)b)->spp;
    return (x > y) - (x < y);
}

static void analyse(results *r, double fit_min)
{
    int s, e, k, better;
    for (s = 0; s < r->nscenes; s++) {
        double tstar = INFINITY, best = 0;
        for (e = 0; e < r->nest; e++) {
            curve *c = &r->c[s][e];
            if (!c->n) continue;
            qsort(c->p, (size_t)c->n, sizeof *c->p, cmp_spp);
            c->slope_t = loglog_slope(c, 1, fit_min);
            c->slope_s = loglog_slope(c, 0, fit_min);
            if (curve_tmax(c) > 0 && curve_tmax(c) < tstar) tstar = curve_tmax(c);
        }
        r->tstar[s] = isfinite(tstar) ? tstar : NAN;
        for (e = 0; e < r->nest; e++) {
            curve *c = &r->c[s][e];
            if (!c->n) continue;
            c->r_star = isfinite(tstar) ? rmse_at(c, tstar, &c->extrap) : NAN;
            c->eff = c->r_star > 0 ? 1.0 / (c->r_star * c->r_star * tstar) : NAN;
            if (c->eff > best) best = c->eff;
        }
        for (e = 0; e < r->nest; e++) {
            curve *c = &r->c[s][e];
            if (!c->n) continue;
            c->ratio = best / c->eff;
            /* rank: 1 + the number of curves strictly more efficient (ties share a rank; NAN last) */
            better = 0;
            for (k = 0; k < r->nest; k++)
                if (r->c[s][k].n && (r->c[s][k].eff > c->eff || (!(c->eff > 0) && r->c[s][k].eff > 0))) better++;
            c->rank = 1 + better;
        }
    }
}

/* ---------- the CSV ---------- */

static int name_index(char names[][NAME_LEN], int *n, int max, const char *name, const char *what,
                      const char *path, int line)
{
    int i;
    for (i = 0; i < *n; i++)
        if (!strcmp(names[i], name)) return i;
    if (*n == max || strlen(name) >= NAME_LEN || !*name) {
        fprintf(stderr, "%s:%d: %s '%s': empty, too long (max %d characters) or too many (max %d)\n",
                path, line, what, name, NAME_LEN - 1, max);
        return -1;
    }
    strcpy(names[*n], name);
    return (*n)++;
}

/* Splits s at commas in place; returns the number of fields (at most max). */
static int split(char *s, char **f, int max)
{
    int n = 0;
    f[n++] = s;
    for (; *s; s++)
        if (*s == ',') {
            *s = '\0';
            if (n == max) return max + 1;
            f[n++] = s + 1;
        }
    return n;
}

static int parse_num(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && errno == 0 && isfinite(*v);
}

#define MAX_COLS 32
static int read_csv(results *r, const char *path)
{
    const char *need[] = {"scene", "estimator", "spp", "seconds", "rmse"};
    int rel = !strcmp(r->metric, "relmse");
    char buf[4096], *f[MAX_COLS + 1];
    int col[5], col_flags = -1, ncols = 0, line = 0, i, k, s, e, rows = 0;
    FILE *fp = fopen(path, "r");
    need[4] = r->metric;
    if (!fp) { fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno)); return 1; }
    while (fgets(buf, sizeof buf, fp)) {
        size_t len = strlen(buf);
        line++;
        if (len == sizeof buf - 1 && buf[len - 1] != '\n') {
            fprintf(stderr, "%s:%d: line too long (max %d characters)\n", path, line, (int)sizeof buf - 2);
            goto bad;
        }
        while (len && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) buf[--len] = '\0';
        if (!len || buf[0] == '#') continue;
        k = split(buf, f, MAX_COLS);
        if (!ncols) {                                   /* the header */
            if (k > MAX_COLS) { fprintf(stderr, "%s:%d: more than %d columns\n", path, line, MAX_COLS); goto bad; }
            ncols = k;
            for (i = 0; i < 5; i++) {
                col[i] = -1;
                for (s = 0; s < k; s++) if (!strcmp(f[s], need[i])) col[i] = s;
                if (col[i] < 0) { fprintf(stderr, "%s:%d: no column '%s' in the header\n", path, line, need[i]); goto bad; }
            }
            for (s = 0; s < k; s++) if (!strcmp(f[s], "flags")) col_flags = s;
            continue;
        }
        if (k != ncols) { fprintf(stderr, "%s:%d: %d fields, the header has %d\n", path, line, k, ncols); goto bad; }
        {
            double spp, t, rmse;
            curve *c;
            if (!parse_num(f[col[2]], &spp) || spp < 1) { fprintf(stderr, "%s:%d: spp '%s' is not a number >= 1\n", path, line, f[col[2]]); goto bad; }
            if (!parse_num(f[col[3]], &t) || !(t > 0)) { fprintf(stderr, "%s:%d: seconds '%s' is not a number > 0\n", path, line, f[col[3]]); goto bad; }
            /* relmse has the reference's noise subtracted: slightly negative is possible, and means 0 */
            if (!parse_num(f[col[4]], &rmse) || (!rel && rmse < 0)) { fprintf(stderr, "%s:%d: %s '%s' is not a number%s\n", path, line, r->metric, f[col[4]], rel ? "" : " >= 0"); goto bad; }
            if (rel) rmse = rmse > 0 ? sqrt(rmse) : 0.0;
            if ((s = name_index(r->scene, &r->nscenes, MAX_SCENES, f[col[0]], "scene", path, line)) < 0) goto bad;
            if ((e = name_index(r->est, &r->nest, MAX_EST, f[col[1]], "estimator", path, line)) < 0) goto bad;
            if (col_flags >= 0 && !r->flags[e][0]) {
                strncpy(r->flags[e], f[col_flags], FLAGS_LEN - 1);
                r->flags[e][FLAGS_LEN - 1] = '\0';
            }
            c = &r->c[s][e];
            for (i = 0; i < c->n; i++)
                if (c->p[i].spp == spp) { fprintf(stderr, "%s:%d: %s, %s at %g spp: a second time\n", path, line, f[col[0]], f[col[1]], spp); goto bad; }
            if (c->n == c->cap) {
                int cap = c->cap ? 2 * c->cap : 16;
                point *p = realloc(c->p, (size_t)cap * sizeof *p);
                if (!p) { fprintf(stderr, "%s: out of memory\n", path); goto bad; }
                c->p = p;
                c->cap = cap;
            }
            c->p[c->n].spp = spp; c->p[c->n].t = t; c->p[c->n].rmse = rmse;
            c->n++;
            rows++;
        }
    }
    if (ferror(fp)) { fprintf(stderr, "%s: read error\n", path); goto bad; }
    if (!rows) { fprintf(stderr, "%s: no data rows%s\n", path, ncols ? "" : " (and no header)"); goto bad; }
    fclose(fp);
    return 0;
bad:
    fclose(fp);
    return 1;
}

/* ---------- the SVG ---------- */

/* The SVG's panels and legend: src/util/svg_plot.c (shared with pathlab compare's plot). */
#define PANEL_W SVG_PANEL_W
#define PANEL_H SVG_PANEL_H
#define HEAD 34.0 /* figure title */

/* Scene s's panel at (x0, y0): one curve per estimator, T*, the slope -1/2 guide through the best
 * curve's RMSE at T*. */
static void panel(FILE *o, const results *r, int s, double x0, double y0)
{
    svg_curve c[MAX_EST];
    svg_point *pts[MAX_EST];
    svg_panel p;
    int e, i, best = -1;
    memset(&p, 0, sizeof p);
    p.x0 = x0, p.y0 = y0, p.title = r->scene[s], p.id = s;
    p.ylabel = strcmp(r->metric, "relmse") ? "RMSE" : "\xe2\x88\x9arelMSE";
    for (e = 0; e < r->nest; e++) {
        const curve *k = &r->c[s][e];
        pts[e] = malloc((size_t)(k->n ? k->n : 1) * sizeof *pts[e]);
        c[e].name = r->est[e], c[e].p = pts[e], c[e].n = pts[e] ? k->n : 0, c[e].guide = 0;
        for (i = 0; i < c[e].n; i++) pts[e][i].t = k->p[i].t, pts[e][i].err = k->p[i].rmse;
        if (k->n && k->rank == 1 && best < 0) best = e;
    }
    if (isfinite(r->tstar[s])) {
        p.tstar = r->tstar[s];
        if (best >= 0) p.guide_t = r->tstar[s], p.guide_err = r->c[s][best].r_star;
    }
    svg_loglog_panel(o, &p, c, r->nest);
    for (e = 0; e < r->nest; e++) free(pts[e]);
}

static int write_svg(const results *r, const char *path, char **caption, int ncap)
{
    int ncols = r->nscenes < 3 ? r->nscenes : 3, nrows = (r->nscenes + ncols - 1) / ncols;
    int per_row = 4, nleg = r->nest + 1, legrows = (nleg + per_row - 1) / per_row, s, e, i, fd, ok;
    double figw = ncols * PANEL_W + 20, legy = HEAD + nrows * PANEL_H + 10, figh = legy + legrows * 20 + 8 + ncap * 15 + 8;
    size_t n = strlen(path);
    char *tmp = malloc(n + 16);
    svg_curve legend[MAX_EST];
    mode_t mask;
    FILE *o;
    if (!tmp) { fprintf(stderr, "%s: out of memory\n", path); return 1; }
    snprintf(tmp, n + 16, "%s.tmp.XXXXXX", path);
    fd = mkstemp(tmp);
    mask = umask(022);            /* mkstemp makes 0600: give the SVG fopen's 0666 minus the umask */
    umask(mask);
    if (fd < 0 || fchmod(fd, 0666 & ~mask) != 0 || !(o = fdopen(fd, "w"))) {
        fprintf(stderr, "%s: cannot create a temporary file: %s\n", path, strerror(errno));
        if (fd >= 0) { close(fd); unlink(tmp); }
        free(tmp);
        return 1;
    }
    fprintf(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(o, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\">\n",
            figw, figh, figw, figh);
    fprintf(o, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(o, "<text x=\"%.2f\" y=\"22\" text-anchor=\"middle\" font-size=\"16\">%s against render time (log-log)</text>\n",
            figw / 2, strcmp(r->metric, "relmse") ? "RMSE" : "\xe2\x88\x9arelMSE (relative RMSE)");
    for (s = 0; s < r->nscenes; s++)
        panel(o, r, s, 10 + (s % ncols) * PANEL_W, HEAD + (s / ncols) * PANEL_H);
    /* legend: one entry per estimator, then the guide line */
    for (e = 0; e < r->nest; e++) legend[e].name = r->est[e], legend[e].p = NULL, legend[e].n = 1, legend[e].guide = 0;
    svg_legend(o, legend, r->nest, "slope \xe2\x88\x92" "1/2 through the best at T*", 20, legy, figw - 40, per_row);
    for (i = 0; i < ncap; i++) {
        fprintf(o, "<text x=\"20\" y=\"%.2f\" font-size=\"10\" fill=\"#333\">", legy + legrows * 20 + 8 + (i + 1) * 15 - 3);
        svg_text(o, caption[i]);
        fprintf(o, "</text>\n");
    }
    fprintf(o, "</svg>\n");
    ok = !ferror(o);
    ok = (fclose(o) == 0) && ok;
    if (!ok || rename(tmp, path) != 0) {
        fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
        unlink(tmp);
        free(tmp);
        return 1;
    }
    free(tmp);
    return 0;
}

/* ---------- the report ---------- */

static void print_num(double v, const char *fmt)
{
    if (isfinite(v)) printf(fmt, v);
    else printf("—");
}

static void print_report(const results *r, double fit_min)
{
    int s, e, rank;
    const char *err = strcmp(r->metric, "relmse") ? "RMSE" : "√relMSE", *sq = strcmp(r->metric, "relmse") ? "MSE" : "relMSE";
    printf("Estimators:\n\n");
    for (e = 0; e < r->nest; e++) printf("- `%s`: `%s`\n", r->est[e], r->flags[e][0] ? r->flags[e] : "?");
    printf("\n| scene | T* (s) | rank | estimator | %s at T* | efficiency 1/(%s·T*) | × the best's time | slope vs time | slope vs spp | spp |\n", err, sq);
    printf("|---|--:|--:|---|--:|--:|--:|--:|--:|--:|\n");
    for (s = 0; s < r->nscenes; s++)
        for (rank = 1; rank <= r->nest + 1; rank++)
            for (e = 0; e < r->nest; e++) {
                const curve *c = &r->c[s][e];
                if (!c->n || c->rank != rank) continue;
                printf("| %s | ", r->scene[s]);
                print_num(r->tstar[s], "%.3g");
                printf(" | %d | %s | ", rank, r->est[e]);
                print_num(c->r_star, "%.3g");
                printf("%s | ", c->extrap ? " (extrap.)" : "");
                print_num(c->eff, "%.3g");
                printf(" | ");
                print_num(c->ratio, c->ratio < 10 ? "%.2f" : "%.0f");
                printf(" | ");
                print_num(c->slope_t, "%.2f");
                printf(" | ");
                print_num(c->slope_s, "%.2f");
                printf(" | %g–%g |\n", c->p[0].spp, c->p[c->n - 1].spp);
            }
    printf("\nSlopes: least squares of log %s against log time and log spp over spp ≥ %g. "
           "T*: the longest time every curve of the scene reached; RMSE at T* interpolated in log-log. "
           "× the best's time = the best's efficiency / this one's.\n", err, fit_min);
}

static int report_cmd(int argc, char **argv)
{
    static results r;
    char *caption[MAX_CAPTION];
    int i, ncap = 0, s, e, rc = 0;
    double fit_min = 4;
    r.metric = "rmse";
    if (argc < 2) {
        fprintf(stderr, "usage: bench-plot report RESULTS.csv OUT.svg [--metric rmse|relmse] [--fit-min SPP] [--caption TEXT]...\n");
        return 2;
    }
    for (i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--fit-min") && i + 1 < argc) {
            if (!parse_num(argv[++i], &fit_min) || fit_min < 1) { fprintf(stderr, "bench-plot: --fit-min '%s': a number >= 1\n", argv[i]); return 2; }
        } else if (!strcmp(argv[i], "--metric") && i + 1 < argc) {
            r.metric = argv[++i];
            if (strcmp(r.metric, "rmse") && strcmp(r.metric, "relmse")) { fprintf(stderr, "bench-plot: --metric '%s': rmse or relmse\n", r.metric); return 2; }
        } else if (!strcmp(argv[i], "--caption") && i + 1 < argc) {
            if (ncap == MAX_CAPTION) { fprintf(stderr, "bench-plot: at most %d --caption lines\n", MAX_CAPTION); return 2; }
            caption[ncap++] = argv[++i];
        } else {
            fprintf(stderr, "bench-plot: unknown or incomplete option '%s'\n", argv[i]);
            return 2;
        }
    }
    if (read_csv(&r, argv[0])) rc = 2;
    if (!rc) {
        analyse(&r, fit_min);
        if (write_svg(&r, argv[1], caption, ncap)) rc = 2;
        else print_report(&r, fit_min);
    }
    for (s = 0; s < MAX_SCENES; s++)
        for (e = 0; e < MAX_EST; e++) free(r.c[s][e].p);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "error")) return error_cmd(argc - 2, argv + 2);
    if (argc >= 2 && !strcmp(argv[1], "report")) return report_cmd(argc - 2, argv + 2);
    fprintf(stderr, "usage: bench-plot error IMAGE.pfm REF.pfm [REF_VAR.pfm]\n"
                    "       bench-plot report RESULTS.csv OUT.svg [--metric rmse|relmse] [--fit-min SPP] [--caption TEXT]...\n");
    return 2;
}
