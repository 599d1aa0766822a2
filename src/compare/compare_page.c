/* compare_page.c — pathlab compare's DIR/index.html (see compare_page.h). The HTML around the viewer
 * is built in memory streams (open_memstream) and handed to html_page_write as before_html and
 * after_html; every text from the command line (labels, flags, paths) is escaped. */
#include "compare/compare_page.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/html_page.h"
#include "util/svg_plot.h"

#define MAX_IMAGES 64

/* The table of table.md, one row per estimator. */
static int put_table(FILE *f, const compare_page *p)
{
    double best = compare_best_eff(p->rows, p->n);
    int k, err = 0;
    fputs("<table class=\"compare\">\n<tr><th>estimator</th><th>flags</th><th>spp</th><th>time (s)</th><th>RMSE</th><th>relMSE</th>"
          "<th>MAE</th><th>MSE</th><th>efficiency 1/(MSE&middot;time)</th><th>ratio to best</th></tr>\n", f);
    for (k = 0; k < p->n; k++) {
        const compare_row *r = &p->rows[k];
        fputs("<tr><td>", f);
        err |= html_put_escaped(f, r->label);
        fputs("</td><td><code>", f);
        err |= html_put_escaped(f, r->flags);
        fprintf(f, "</code></td><td>%d</td><td>%.3f</td><td>%.4g</td><td>%.4g</td><td>%.4g</td><td>%.4g</td><td>%.4g</td><td>%.3f</td></tr>\n",
                r->spp, r->secs, r->rmse, r->relmse, r->mae, r->mse, r->eff, best > 0.0 ? r->eff / best : NAN);
    }
    fputs("</table>\n", f);
    return err;
}

/* A line of Markdown's notes: `code` spans as <code>, the rest escaped. Cuts line. */
static int put_code(FILE *f, char *line)
{
    char *tick;
    int err = 0, code = 0;
    for (; (tick = strchr(line, '`')) != NULL; line = tick + 1, code = !code) {
        *tick = '\0';
        err |= html_put_escaped(f, line);
        fputs(code ? "</code>" : "<code>", f);
    }
    err |= html_put_escaped(f, line);
    if (code) fputs("</code>", f);
    return err;
}

/* The notes, "- ...\n" lines, as a list. */
static int put_notes(FILE *f, const char *notes)
{
    const char *s = notes, *end;
    int err = 0;
    fputs("<ul class=\"notes\">\n", f);
    for (; *s; s = *end ? end + 1 : end) {
        char line[2048];
        const char *start = s[0] == '-' && s[1] == ' ' ? s + 2 : s;
        end = strchr(s, '\n');
        if (!end) end = s + strlen(s);
        snprintf(line, sizeof line, "%.*s", (int)(end - start), start);
        if (!line[0]) continue;
        fputs("<li>", f);
        err |= put_code(f, line);
        fputs("</li>\n", f);
    }
    fputs("</ul>\n", f);
    return err;
}

/* Each estimator's error against its render time, one point each, with the slope -1/2 line through
 * it: where an unbiased estimator goes with more or fewer samples, so a lower line is more efficient
 * at every time. The error is sqrt(MSE): the table's MSE, the reference's noise taken off. */
static void put_plot(FILE *f, const compare_page *p)
{
    svg_curve c[MAX_IMAGES];
    svg_point pt[MAX_IMAGES];
    svg_panel panel;
    double w = SVG_PANEL_W + 240, h;
    int k, n = p->n < MAX_IMAGES ? p->n : MAX_IMAGES;
    memset(&panel, 0, sizeof panel);
    panel.x0 = 10, panel.y0 = 4, panel.title = "error against render time (log-log)", panel.ylabel = "\xe2\x88\x9aMSE", panel.pad = 0.1;
    for (k = 0; k < n; k++) {
        pt[k].t = p->rows[k].secs, pt[k].err = sqrt(p->rows[k].mse);
        c[k].name = p->rows[k].label, c[k].p = &pt[k], c[k].n = 1, c[k].guide = 1;
    }
    h = fmax(SVG_PANEL_H + 8, 20.0 * n + 60);
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
               "font-family=\"sans-serif\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", w, h, w, h);
    svg_loglog_panel(f, &panel, c, n);
    svg_legend(f, c, n, "slope \xe2\x88\x92" "1/2: same efficiency", SVG_PANEL_W + 20, 30, 220, 1);
    fputs("</svg>\n<p>Each estimator's render is a point; the dashed line of slope &minus;1/2 through it is where an unbiased "
          "estimator goes with more or fewer samples (MSE &prop; 1/time), so the lowest line is the most efficient at every time.</p>\n", f);
}

/* Links to the other files of DIR. */
static int put_files(FILE *f, const compare_page *p)
{
    int k, err = 0;
    fputs("<p>Files: <a href=\"mosaic.png\">mosaic.png</a>, <a href=\"table.md\">table.md</a>, <a href=\"table.csv\">table.csv</a>", f);
    for (k = 0; k < p->n; k++) {
        fputs(", <a href=\"", f);
        err |= html_put_escaped(f, p->slugs[k]);
        fputs(".pfm\">", f);
        err |= html_put_escaped(f, p->slugs[k]);
        fputs(".pfm</a> (<a href=\"heat-", f);
        err |= html_put_escaped(f, p->slugs[k]);
        fputs(".png\">heatmap</a>)", f);
    }
    fputs("</p>\n", f);
    return err;
}

/* before_html and after_html into *before and *after (to free); 1 when out of memory. */
static int make_html(const compare_page *p, char **before, char **after)
{
    size_t nb, na;
    FILE *fb = open_memstream(before, &nb), *fa = fb ? open_memstream(after, &na) : NULL;
    int err = !fa;
    if (!err) {
        err |= put_table(fb, p);
        err |= put_notes(fb, p->notes);
        put_plot(fa, p);
        err |= put_files(fa, p);
    }
    if (fa) err |= fclose(fa) != 0;
    if (fb) err |= fclose(fb) != 0;
    return err;
}

int compare_write_page(const char *path, const compare_page *p)
{
    html_image im[MAX_IMAGES], ref;
    html_page page;
    char *before = NULL, *after = NULL;
    int k, n = p->n < MAX_IMAGES ? p->n : MAX_IMAGES, err;
    memset(&page, 0, sizeof page);
    for (k = 0; k < n; k++) {
        im[k].name = p->rows[k].label, im[k].img = &p->img[k], im[k].link = NULL;
        im[k].var = p->var[k].px ? &p->var[k] : NULL;
    }
    ref.name = p->ref_label, ref.img = p->ref, ref.var = p->ref_var, ref.link = NULL;
    page.title = p->title, page.images = im, page.nimages = n, page.ref = &ref;
    if (make_html(p, &before, &after)) {
        fprintf(stderr, "%s: out of memory\n", shown(path));
        err = 1;
    } else {
        page.before_html = before, page.after_html = after;
        err = html_page_write(path, &page);
    }
    free(before);
    free(after);
    return err;
}
