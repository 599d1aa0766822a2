/* compare_outputs.c — the heatmaps, notes, mosaic, tables and page of pathlab compare (compare_outputs.h). */
#include "compare/compare_outputs.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "compare/compare_files.h"
#include "compare/compare_page.h"
#include "image/heatmap.h"
#include "image/mosaic.h"
#include "sys/output_path.h"

/* What the outputs share as they are made. */
typedef struct {
    const compare_outputs *o;
    double heat_scale;             /* the heatmaps' white: --scale, or 3 x the largest RMSE */
    char notes[4096];              /* under the table: how the numbers were made */
    int mosaic_w, mosaic_h;
} outputs;

/* |image - reference| on one scale for all, written as DIR/heat-SLUG.png. */
static int write_heatmaps(outputs *w)
{
    const compare_outputs *o = w->o;
    double worst = 0.0;
    int i;
    for (i = 0; i < o->n; i++)
        if (o->est[i].row.rmse > worst) worst = o->est[i].row.rmse;
    w->heat_scale = o->scale > 0.0f ? o->scale : worst > 0.0 ? 3.0 * worst : 1.0;
    for (i = 0; i < o->n; i++) {
        compare_estimator *e = &o->est[i];
        if (img_heatmap(&e->heat, &e->img, &o->ref->img, w->heat_scale, NULL)) return 1;
        if (compare_save_image(o->dir, "heat-", e->slug, ".png", &e->heat, 0.0f)) return 1;
    }
    return 0;
}

/* Appends a line to the notes. */
static void note(outputs *w, const char *fmt, ...)
{
    size_t used = strlen(w->notes);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->notes + used, sizeof w->notes - used, fmt, ap);
    va_end(ap);
}

/* The notes under the table: the reference, MSE, equal samples or time, the heatmaps' scale. */
static void write_notes(outputs *w)
{
    const compare_outputs *o = w->o;
    const compare_reference *ref = o->ref;
    int has_var = ref->var.px != NULL;
    if (o->ref_path)
        note(w, "- reference: %s (given)%s%s.\n", o->ref_path, has_var ? ", its variance " : "", has_var ? o->ref_var_path : "");
    else
        note(w, "- reference: rendered with `%s` at %d spp (%s), seed %llu, in %.2f s; written as reference.pfm "
                "(its variance: reference_var.pfm).\n", o->ref_flags, ref->spp, o->ref_spp_given ? "--ref-spp" : "16 x the largest spp",
             (unsigned long long)ref->seed, ref->secs);
    if (has_var)
        note(w, "- MSE = RMSE^2 - %.4g, the mean variance of the reference's pixels: its own noise, which adds to every squared "
                "error; efficiency = 1/(MSE * time). RMSE, relMSE and MAE are raw (as pathlab diff prints them).\n", ref->mean_var);
    else
        note(w, "- MSE = RMSE^2: the reference's variance is unknown (--ref-var), so its noise counts as error.\n");
    if (o->time > 0.0f)
        note(w, "- equal time: %g s each; spp = SEC / (seconds per spp measured on calibration renders of 1, 2, 4... spp "
                "lasting %.3g s); time = the final render's wall-clock time, %d threads.\n", o->time, o->calib_secs, o->threads);
    else
        note(w, "- equal samples: %d spp each; time = wall-clock time of the render, %d threads.\n", o->spp, o->threads);
    note(w, "- heatmaps (heat-LABEL.png): |image - reference| averaged over RGB, black 0 to white %.4g.\n", w->heat_scale);
}

static mosaic_panel panel(const image *im, const char *label, float gain)
{
    mosaic_panel p;
    p.im = im;
    p.label = label;
    p.gain = gain;
    return p;
}

/* Row 0: the reference and each estimator's image; row 1: the heatmaps' colour scale, then each
 * heatmap. Written as DIR/mosaic.ppm and .png. */
static int write_mosaic(outputs *w)
{
    const compare_outputs *o = w->o;
    mosaic_panel p[2 * (COMPARE_MAX_EST + 1)];
    char rmse[COMPARE_MAX_EST][32], scale[64];
    image legend = {0, 0, NULL}, m = {0, 0, NULL};
    int i, n = o->n + 1, err;
    float gain = exp2f(o->exposure);
    snprintf(scale, sizeof scale, "error 0 to %.3g", w->heat_scale);
    p[0] = panel(&o->ref->img, o->ref->label, gain);
    p[n] = panel(&legend, scale, 1.0f);
    for (i = 0; i < o->n; i++) {
        snprintf(rmse[i], sizeof rmse[i], "RMSE %.3g", o->est[i].row.rmse);
        p[1 + i] = panel(&o->est[i].img, o->est[i].row.label, gain);
        p[n + 1 + i] = panel(&o->est[i].heat, rmse[i], 1.0f);
    }
    err = img_heatmap_legend(&legend, o->ref->img.w, o->ref->img.h);
    if (!err && (err = mosaic_make(&m, p, 2, n))) fprintf(stderr, "pathlab: compare: out of memory for the mosaic\n");
    err = err || compare_save_image(o->dir, "", "mosaic", ".ppm", &m, 0.0f) || compare_save_image(o->dir, "", "mosaic", ".png", &m, 0.0f);
    w->mosaic_w = m.w;
    w->mosaic_h = m.h;
    img_free(&legend);
    img_free(&m);
    return err;
}

/* DIR/table.md (with the notes) and DIR/table.csv, then the table and the notes on stdout. */
static int write_tables(const outputs *w)
{
    const compare_outputs *o = w->o;
    compare_row rows[COMPARE_MAX_EST];
    char md[PATH_CAP], csv[PATH_CAP];
    int i;
    for (i = 0; i < o->n; i++) rows[i] = o->est[i].row;
    if (compare_out_path(md, o->dir, "", "table", ".md") || compare_out_path(csv, o->dir, "", "table", ".csv")) return 1;
    if (compare_write_md(md, rows, o->n, w->notes) || compare_write_csv(csv, rows, o->n)) return 1;
    compare_print_table(stdout, rows, o->n);
    printf("\n%s", w->notes);
    printf("(mosaic %dx%d in %s/mosaic.png; images, heatmaps and table.md, table.csv in %s; the page %s/index.html)\n",
           w->mosaic_w, w->mosaic_h, o->dir, o->dir, o->dir);
    return 0;
}

/* DIR/index.html: the images in the viewer, the table and its notes, the error against time. */
static int write_page(const outputs *w)
{
    const compare_outputs *o = w->o;
    compare_row rows[COMPARE_MAX_EST];
    image img[COMPARE_MAX_EST], var[COMPARE_MAX_EST];
    const char *slugs[COMPARE_MAX_EST];
    char path[PATH_CAP], title[PATH_CAP];
    compare_page p;
    int i;
    for (i = 0; i < o->n; i++) rows[i] = o->est[i].row, img[i] = o->est[i].img, var[i] = o->est[i].var, slugs[i] = o->est[i].slug;
    snprintf(title, sizeof title, "pathlab compare: %s", o->scene);
    p.title = title, p.rows = rows, p.img = img, p.var = var, p.slugs = slugs, p.n = o->n;
    p.ref = &o->ref->img, p.ref_var = o->ref->var.px ? &o->ref->var : NULL, p.ref_label = o->ref->label, p.notes = w->notes;
    return compare_out_path(path, o->dir, "", "index", ".html") || compare_write_page(path, &p);
}

int compare_write_outputs(const compare_outputs *o)
{
    outputs w;
    memset(&w, 0, sizeof w);
    w.o = o;
    if (write_heatmaps(&w)) return 1;
    write_notes(&w);
    return write_mosaic(&w) || write_tables(&w) || write_page(&w);
}
