/* compare.c — pathlab compare: several estimators of one scene side by side, with their errors.
 * run() is the procedure, one named step per line. The estimators' language is in estimators.c,
 * the table in compare_report.c, the layout of the mosaic in image/mosaic.c.
 *
 * Choices (summed up in COMPARE_HELP, compare.h):
 * - An estimator is a list of render flags and names (estimators.h). Flags outside --estimators
 *   apply to all; each estimator's flags are parsed after them, so they win. --spp, -o, --variance
 *   and --split are refused inside an estimator: the comparison fixes the samples (or the time) and
 *   the files.
 * - Equal time (--time SEC): each estimator is first rendered at 1, 2, 4 ... spp until one
 *   calibration render takes a fifth of SEC, which measures its seconds per sample; it is then
 *   rendered at round(SEC / that) spp. Fixed costs (threads, tiles) and a cold cache make the
 *   estimate pessimistic, so the final time is often under SEC; the table shows the time measured.
 * - The reference, when not given, is rendered first with the best estimator (--direct mis-power
 *   --light solid-angle --dir brdf) at 16 x the largest spp (--ref-spp to change), with a different
 *   seed so that its noise is independent of the estimators'. It is written as DIR/reference.pfm.
 * - The reference's own noise adds its variance to every MSE: E|I - R|^2 = E|I - L|^2 + Var R for
 *   independent I and R. When its per-pixel variance is known (rendered, or --ref-var), the table's
 *   MSE column is RMSE^2 minus the mean of that variance, and efficiency = 1 / (MSE x time) uses it;
 *   RMSE, relMSE and MAE stay raw (what pathlab diff prints on the written images).
 * - Heatmaps share one scale, 3 x the largest RMSE, so that their colours compare. */
#include "cmd/compare.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "compare/compare_page.h"
#include "compare/compare_report.h"
#include "cmd/diff.h"
#include "cmd/estimators.h"
#include "cmd/help.h"
#include "cmd/render_args.h"
#include "image/mosaic.h"
#include "render/render.h"
#include "util/cli.h"
#include "sys/output_path.h"

#define MAX_EST 16
#define CALIB_FRACTION 0.2    /* of --time: the length of the last calibration render */

/* The best estimator of the course, for the reference. */
static const char REFERENCE_FLAGS[] = "--direct mis-power --light solid-angle --dir brdf";
/* Render flags that compare refuses: it names its files itself. */
static const char *const RENDER_ONLY[] = {"--split", "--variance", NULL};
/* compare's own files, DIR/NAME.*, which no estimator may write over. */
static const char *const RESERVED[] = {"reference", "mosaic", "table", "index", NULL};

/* One estimator's results: its render, its error heatmap and its line of the table. */
typedef struct {
    image img, var, heat;    /* var: the variance of each pixel's mean, for the page's z-scores */
    compare_row row;         /* spp, time, errors, efficiency */
} estimator;

/* The reference: given (--ref, --ref-var) or rendered with REFERENCE_FLAGS. */
typedef struct {
    image img, var;          /* var.px is NULL when its variance is unknown */
    double mean_var;         /* the mean of var: the reference's own noise in every MSE (0 if unknown) */
    int spp;                 /* the samples, seed and time of a rendered reference */
    uint64_t seed;
    double secs;
    char label[160];         /* over its panel in the mosaic */
} reference;

/* The flags, then what run() finds step by step. */
typedef struct {
    render_args base;                      /* the render flags outside --estimators: shared */
    const char *list, *dir, *ref, *ref_var;
    int spp, spp_given, ref_spp;
    float time, scale;                     /* --time (0: equal spp), --scale (0: none given) */
    int nest;
    estimator_spec spec[MAX_EST];          /* each estimator's label, file name and render flags */
    estimator est[MAX_EST];                /* and its results */
    camera cam;                            /* one view for all */
    double heat_scale;                     /* the heatmaps' white: --scale, or 3 x the largest RMSE */
    char notes[4096];                      /* under the table: how the numbers were made */
    int mosaic_w, mosaic_h;
} comparison;

/* ---- the command line ---- */

/* --time SEC: seconds in (0, 86400]. */
static int parse_time(void *ctx, const char *flag, const char *v)
{
    comparison *c = ctx;
    cli_flag as_float = {NULL, CLI_FLOAT, NULL, 0, 0, NULL, NULL, NULL};
    as_float.name = flag, as_float.dest = &c->time;
    if (cli_parse_value("compare", &as_float, v, NULL)) return 1;
    if (!(c->time > 0.0f && c->time <= 86400.0f)) return cli_fail("compare", flag, "seconds in (0, 86400]", v);
    return 0;
}

/* Sorts argv[1..] in two, in their order: the flags of table `own` with their values into mine,
 * every other word (the scene, the render flags and their values) into rest. */
static int split_args(int argc, char **argv, const cli_flag *own, char **mine, int *nmine, char **rest, int *nrest)
{
    int i, k;
    for (i = 1; i < argc; i++) {
        for (k = 0; RENDER_ONLY[k]; k++)
            if (cli_flag_is(argv[i], RENDER_ONLY[k])) {
                fprintf(stderr, "pathlab: compare: %s is a flag of render only\n", argv[i]);
                return 1;
            }
        for (k = 0; own[k].name && !cli_flag_is(argv[i], own[k].name); k++) continue;
        if (!own[k].name) { rest[(*nrest)++] = argv[i]; continue; }
        mine[(*nmine)++] = argv[i];   /* --flag=value carries its value */
        if (own[k].kind != CLI_SWITCH && !strchr(argv[i], '=') && i + 1 < argc) mine[(*nmine)++] = argv[++i];
    }
    return 0;
}

/* compare's own flags (cli_parse), then the scene and the render flags shared by the estimators. */
static int parse_flags(comparison *c, int argc, char **argv)
{
    cli_flag own[] = {
        {"--estimators", CLI_STRING, &c->list, 0, 0, NULL, NULL, NULL},
        {"-o", CLI_STRING, &c->dir, 0, 0, NULL, NULL, NULL},
        {"--ref", CLI_STRING, &c->ref, 0, 0, NULL, NULL, NULL},
        {"--ref-var", CLI_STRING, &c->ref_var, 0, 0, NULL, NULL, NULL},
        {"--ref-spp", CLI_INT, &c->ref_spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--spp", CLI_INT, &c->spp, 1, 1 << 30, NULL, NULL, &c->spp_given},
        {"--time", CLI_CUSTOM, NULL, 0, 0, NULL, parse_time, NULL},
        {"--scale", CLI_FLOAT, &c->scale, 0, 0, NULL, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {own, NULL};
    char **mine = malloc(2 * (size_t)argc * sizeof *mine), **rest = mine + argc;
    int nmine = 1, nrest = 1, nwords, i, err;
    if (!mine) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    mine[0] = rest[0] = argv[0];
    err = split_args(argc, argv, own, mine, &nmine, rest, &nrest)
          || cli_parse("compare", nmine, mine, tables, c, NULL, 0, &nwords);
    c->base.cmd = "compare";
    c->base.more_flags = own;
    for (i = 1; !err && i < nrest; i++) err = render_parse_flag(&c->base, nrest, rest, &i);
    c->base.more_flags = NULL;   /* own[] ends here */
    free(mine);
    return err;
}

static int check_flags(const comparison *c)
{
    if (!c->base.scene || !c->list || !c->dir) {
        help_print(stderr, "pathlab: compare needs a scene, --estimators and -o DIR\nusage:\n" COMPARE_USAGE COMPARE_HELP);
        return 1;
    }
    if (c->base.samples_given || c->base.resume) {
        fprintf(stderr, "pathlab: compare: --samples and --resume are for pathlab render (compare renders each estimator whole)\n");
        return 1;
    }
    if (c->spp_given && c->time > 0.0f) { fprintf(stderr, "pathlab: compare: --spp (equal samples) or --time (equal time), not both\n"); return 1; }
    if (c->ref_var && !c->ref) { fprintf(stderr, "pathlab: compare: --ref-var goes with --ref\n"); return 1; }
    if (c->ref && c->ref_spp) { fprintf(stderr, "pathlab: compare: --ref-spp is for a rendered reference, not with --ref\n"); return 1; }
    return render_check_camera_flags(&c->base) || output_dir_check("compare", "-o", c->dir);
}

/* Each estimator writes DIR/SLUG.*: not one of compare's own files, nor another estimator's. */
static int check_file_names(const comparison *c)
{
    int i, j;
    for (i = 0; i < c->nest; i++) {
        const estimator_spec *e = &c->spec[i];
        for (j = 0; RESERVED[j]; j++)
            if (!strcmp(e->slug, RESERVED[j])) {
                fprintf(stderr, "pathlab: compare: label '%s' would write over DIR/%s.*: name it, e.g. \"my %s=%s\"\n",
                        e->label, RESERVED[j], e->label, e->flags);
                return 1;
            }
        for (j = 0; j < i; j++)
            if (!strcmp(e->slug, c->spec[j].slug)) {
                fprintf(stderr, "pathlab: compare: estimators '%s' and '%s' would both write DIR/%s.pfm: label one (LABEL=FLAGS)\n",
                        c->spec[j].label, e->label, e->slug);
                return 1;
            }
    }
    return 0;
}

static int parse_args(comparison *c, int argc, char **argv)
{
    render_args_init(&c->base);
    c->spp = 16;
    if (parse_flags(c, argc, argv) || check_flags(c)) return 1;
    return estimators_parse(c->list, &c->base, c->spec, MAX_EST, &c->nest) || check_file_names(c);
}

/* ---- the steps of run() ---- */

static int load_scene(const comparison *c, scene *s)
{
    if (scene_load(s, c->base.scene, c->base.ro.threads, 1)) return 1;
    if (s->lights.n == 0) fprintf(stderr, "pathlab: warning: %s has no emitters: every image is black\n", c->base.scene);
    return 0;
}

static int same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* One camera for all, since one reference serves all: each estimator's view must be the first's. */
static int make_camera(comparison *c, const scene *s)
{
    camera cam;
    int i;
    for (i = 0; i < c->nest; i++) {
        const char *label = c->spec[i].label, *first = c->spec[0].label;
        if (render_make_camera(&c->spec[i].a, s, i ? &cam : &c->cam)) return 1;
        if (i && (cam.width != c->cam.width || cam.height != c->cam.height)) {
            fprintf(stderr, "pathlab: compare: estimator '%s' renders %dx%d but '%s' %dx%d: one size for all\n",
                    label, cam.width, cam.height, first, c->cam.width, c->cam.height);
            return 1;
        }
        if (i && !(same_vec(cam.eye, c->cam.eye) && same_vec(cam.w, c->cam.w) && same_vec(cam.u, c->cam.u) && same_vec(cam.v, c->cam.v))) {
            fprintf(stderr, "pathlab: compare: estimator '%s' sees the scene from another camera than '%s': one view for all\n", label, first);
            return 1;
        }
    }
    return 0;
}

/* --ref, and --ref-var if given: images of the renders' size. */
static int read_reference(const comparison *c, reference *ref)
{
    int w = c->cam.width, h = c->cam.height;
    if (img_read_pfm(&ref->img, c->ref)) return 1;
    if (ref->img.w != w || ref->img.h != h) {
        fprintf(stderr, "pathlab: compare: the reference %s is %dx%d but the renders are %dx%d (use --size %dx%d, or another reference)\n",
                c->ref, ref->img.w, ref->img.h, w, h, ref->img.w, ref->img.h);
        return 1;
    }
    if (c->ref_var && img_read_pfm(&ref->var, c->ref_var)) return 1;
    if (c->ref_var && (ref->var.w != w || ref->var.h != h)) {
        fprintf(stderr, "pathlab: compare: --ref-var %s is %dx%d but the reference is %dx%d\n", c->ref_var, ref->var.w, ref->var.h, w, h);
        return 1;
    }
    snprintf(ref->label, sizeof ref->label, "reference");
    return 0;
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) && errno != EEXIST) {
        fprintf(stderr, "pathlab: compare: cannot create %s: %s\n", dir, strerror(errno));
        return 1;
    }
    return 0;
}

/* Renders the total image; its variance too if var is not NULL. */
static int render_image(const scene *s, const camera *cam, const render_opts *ro, image *mean, image *var, double *secs)
{
    render_result r;
    if (render(s, cam, ro, &r)) return 1;
    *mean = r.mean[0];
    r.mean[0].px = NULL;
    if (var) { *var = r.var[0]; r.var[0].px = NULL; }
    *secs = r.seconds;
    render_result_free(&r);
    return 0;
}

/* Seconds per sample with options ro: renders at 1, 2, 4 ... spp until a render lasts target seconds. */
static int calibrate(const scene *s, const camera *cam, render_opts ro, double target, double *sec_per_spp)
{
    image im;
    double t = 0.0;
    for (ro.spp = 1;; ro.spp *= 2) {
        if (render_image(s, cam, &ro, &im, NULL, &t)) return 1;
        img_free(&im);
        if (t >= target || ro.spp >= (1 << 20)) break;
    }
    *sec_per_spp = t / ro.spp;
    return 0;
}

/* The samples of each estimator: --spp, or as many as its calibrated speed fits in --time. */
static int choose_spp(comparison *c, const scene *s)
{
    double sec_per_spp;
    int i;
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        if (c->time > 0.0f) {
            if (calibrate(s, &c->cam, c->spec[i].a.ro, CALIB_FRACTION * c->time, &sec_per_spp)) return 1;
            e->row.spp = (int)fmin(1 << 30, fmax(1.0, floor(c->time / sec_per_spp + 0.5)));
            if (!c->base.ro.quiet)
                fprintf(stderr, "compare: %s: %.3g ms per spp -> %d spp for %g s\n", c->spec[i].label, 1e3 * sec_per_spp, e->row.spp, c->time);
        } else {
            e->row.spp = c->spp;
        }
    }
    return 0;
}

/* DIR/PRE SLUG EXT, e.g. DIR/heat-light.png, into path[PATH_CAP]. */
static int out_path(char *path, const comparison *c, const char *pre, const char *slug, const char *ext)
{
    if (snprintf(path, PATH_CAP, "%s/%s%s%s", c->dir, pre, slug, ext) >= PATH_CAP) {
        fprintf(stderr, "pathlab: compare: path too long in %s\n", c->dir);
        return 1;
    }
    return 0;
}

static int save_image(const comparison *c, const char *pre, const char *slug, const char *ext, const image *im, float exposure)
{
    char path[PATH_CAP];
    return out_path(path, c, pre, slug, ext) || img_write(im, path, exposure);
}

/* The best estimator, 16 x the largest spp (or --ref-spp), its own seed; written as DIR/reference.*. */
static int render_reference(const comparison *c, const scene *s, reference *ref)
{
    estimator_spec best;
    int i, n, max_spp = 0;
    if (estimators_parse(REFERENCE_FLAGS, &c->base, &best, 1, &n)) return 1;
    for (i = 0; i < c->nest; i++)
        if (c->est[i].row.spp > max_spp) max_spp = c->est[i].row.spp;
    ref->spp = best.a.ro.spp = c->ref_spp ? c->ref_spp : (int)fmin(1 << 30, 16.0 * max_spp);
    ref->seed = best.a.ro.seed = c->base.ro.seed ^ 0x9e3779b97f4a7c15ULL;
    best.a.ro.quiet = c->base.ro.quiet;
    snprintf(ref->label, sizeof ref->label, "reference %d spp", ref->spp);
    if (!c->base.ro.quiet) fprintf(stderr, "compare: rendering the reference: %d spp of %s\n", ref->spp, REFERENCE_FLAGS);
    return render_image(s, &c->cam, &best.a.ro, &ref->img, &ref->var, &ref->secs)
           || save_image(c, "", "reference", ".pfm", &ref->img, 0.0f)
           || save_image(c, "", "reference-var", ".pfm", &ref->var, 0.0f)
           || save_image(c, "", "reference", ".png", &ref->img, c->base.exposure);
}

static double mean_of(const image *im)
{
    long i, n = 3L * im->w * im->h;
    double sum = 0.0;
    for (i = 0; i < n; i++) sum += im->px[i];
    return sum / n;
}

/* The errors of img against the reference, and the efficiency 1 / (MSE x time). */
static void measure(compare_row *r, const image *img, const reference *ref)
{
    diff_stats ds;
    diff_compute(&ds, img, &ref->img);
    r->rmse = ds.rmse;
    r->relmse = ds.relmse;
    r->mae = ds.mae;
    r->mse = ds.rmse * ds.rmse - ref->mean_var;
    if (!(r->mse > 0.0)) r->mse = 1e-30;   /* below the reference's noise: efficiency is then meaningless */
    r->eff = 1.0 / (r->mse * fmax(r->secs, 1e-9));
}

/* Each estimator at its spp, written as DIR/SLUG.pfm and .png, and measured. */
static int render_estimators(comparison *c, const scene *s, const reference *ref)
{
    int i;
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        const estimator_spec *sp = &c->spec[i];
        render_opts ro = sp->a.ro;
        ro.spp = e->row.spp;
        if (render_image(s, &c->cam, &ro, &e->img, &e->var, &e->row.secs)) return 1;
        measure(&e->row, &e->img, ref);
        if (!c->base.ro.quiet) fprintf(stderr, "compare: %s: %d spp in %.3f s, RMSE %.4g\n", sp->label, e->row.spp, e->row.secs, e->row.rmse);
        if (save_image(c, "", sp->slug, ".pfm", &e->img, 0.0f) || save_image(c, "", sp->slug, ".png", &e->img, c->base.exposure)) return 1;
    }
    return 0;
}

/* |image - reference| on one scale for all, written as DIR/heat-SLUG.png. */
static int write_heatmaps(comparison *c, const reference *ref)
{
    double worst = 0.0;
    int i;
    for (i = 0; i < c->nest; i++)
        if (c->est[i].row.rmse > worst) worst = c->est[i].row.rmse;
    c->heat_scale = c->scale > 0.0f ? c->scale : worst > 0.0 ? 3.0 * worst : 1.0;
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        if (diff_heatmap(&e->heat, &e->img, &ref->img, c->heat_scale)) return 1;
        if (save_image(c, "heat-", c->spec[i].slug, ".png", &e->heat, 0.0f)) return 1;
    }
    return 0;
}

/* Appends a line to the notes. */
static void note(comparison *c, const char *fmt, ...)
{
    size_t used = strlen(c->notes);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->notes + used, sizeof c->notes - used, fmt, ap);
    va_end(ap);
}

/* The notes under the table: the reference, MSE, equal samples or time, the heatmaps' scale. */
static void write_notes(comparison *c, const reference *ref)
{
    int has_var = ref->var.px != NULL;
    if (c->ref)
        note(c, "- reference: %s (given)%s%s.\n", c->ref, has_var ? ", its variance " : "", has_var ? c->ref_var : "");
    else
        note(c, "- reference: rendered with `%s` at %d spp (%s), seed %llu, in %.2f s; written as reference.pfm "
                "(its variance: reference-var.pfm).\n", REFERENCE_FLAGS, ref->spp, c->ref_spp ? "--ref-spp" : "16 x the largest spp",
             (unsigned long long)ref->seed, ref->secs);
    if (has_var)
        note(c, "- MSE = RMSE^2 - %.4g, the mean variance of the reference's pixels: its own noise, which adds to every squared "
                "error; efficiency = 1/(MSE * time). RMSE, relMSE and MAE are raw (as pathlab diff prints them).\n", ref->mean_var);
    else
        note(c, "- MSE = RMSE^2: the reference's variance is unknown (--ref-var), so its noise counts as error.\n");
    if (c->time > 0.0f)
        note(c, "- equal time: %g s each; spp = SEC / (seconds per spp measured on calibration renders of 1, 2, 4... spp "
                "lasting %.3g s); time = the final render's wall-clock time, %d threads.\n", c->time, CALIB_FRACTION * c->time,
             c->base.ro.threads);
    else
        note(c, "- equal samples: %d spp each; time = wall-clock time of the render, %d threads.\n", c->spp, c->base.ro.threads);
    note(c, "- heatmaps (heat-LABEL.png): |image - reference| averaged over RGB, black 0 to white %.4g.\n", c->heat_scale);
}

/* The heatmap's colour ramp, 0 at the left to the scale at the right: diff_heatmap of a gradient. */
static int make_legend(image *legend, int w, int h)
{
    image grad, zero;
    int x, y, err;
    if (img_alloc(&grad, w, h)) return 1;
    if (img_alloc(&zero, w, h)) { img_free(&grad); return 1; }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float t = w > 1 ? (float)x / (float)(w - 1) : 1.0f;
            grad.px[3 * (y * w + x)] = grad.px[3 * (y * w + x) + 1] = grad.px[3 * (y * w + x) + 2] = t;
        }
    err = diff_heatmap(legend, &grad, &zero, 1.0);
    img_free(&grad);
    img_free(&zero);
    return err;
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
static int write_mosaic(comparison *c, const reference *ref)
{
    mosaic_panel p[2 * (MAX_EST + 1)];
    char rmse[MAX_EST][32], scale[64];
    image legend = {0, 0, NULL}, m = {0, 0, NULL};
    int i, n = c->nest + 1, err;
    float gain = exp2f(c->base.exposure);
    snprintf(scale, sizeof scale, "error 0 to %.3g", c->heat_scale);
    p[0] = panel(&ref->img, ref->label, gain);
    p[n] = panel(&legend, scale, 1.0f);
    for (i = 0; i < c->nest; i++) {
        snprintf(rmse[i], sizeof rmse[i], "RMSE %.3g", c->est[i].row.rmse);
        p[1 + i] = panel(&c->est[i].img, c->spec[i].label, gain);
        p[n + 1 + i] = panel(&c->est[i].heat, rmse[i], 1.0f);
    }
    err = make_legend(&legend, c->cam.width, c->cam.height);
    if (!err && (err = mosaic_make(&m, p, 2, n))) fprintf(stderr, "pathlab: compare: out of memory for the mosaic\n");
    err = err || save_image(c, "", "mosaic", ".ppm", &m, 0.0f) || save_image(c, "", "mosaic", ".png", &m, 0.0f);
    c->mosaic_w = m.w;
    c->mosaic_h = m.h;
    img_free(&legend);
    img_free(&m);
    return err;
}

/* DIR/table.md (with the notes) and DIR/table.csv, then the table and the notes on stdout. */
static int write_tables(const comparison *c)
{
    compare_row rows[MAX_EST];
    char md[PATH_CAP], csv[PATH_CAP];
    int i;
    for (i = 0; i < c->nest; i++) {
        rows[i] = c->est[i].row;
        rows[i].label = c->spec[i].label;
        rows[i].flags = c->spec[i].flags;
    }
    if (out_path(md, c, "", "table", ".md") || out_path(csv, c, "", "table", ".csv")) return 1;
    if (compare_write_md(md, rows, c->nest, c->notes) || compare_write_csv(csv, rows, c->nest)) return 1;
    compare_print_table(stdout, rows, c->nest);
    printf("\n%s", c->notes);
    printf("(mosaic %dx%d in %s/mosaic.png; images, heatmaps and table.md, table.csv in %s; the page %s/index.html)\n",
           c->mosaic_w, c->mosaic_h, c->dir, c->dir, c->dir);
    return 0;
}

/* DIR/index.html: the images in the viewer, the table and its notes, the error against time. */
static int write_page(const comparison *c, const reference *ref)
{
    compare_row rows[MAX_EST];
    image img[MAX_EST], var[MAX_EST];
    const char *slugs[MAX_EST];
    char path[PATH_CAP], title[PATH_CAP];
    compare_page p;
    int i;
    for (i = 0; i < c->nest; i++) {
        rows[i] = c->est[i].row;
        rows[i].label = c->spec[i].label, rows[i].flags = c->spec[i].flags;
        img[i] = c->est[i].img, var[i] = c->est[i].var, slugs[i] = c->spec[i].slug;
    }
    snprintf(title, sizeof title, "pathlab compare: %s", c->base.scene);
    p.title = title, p.rows = rows, p.img = img, p.var = var, p.slugs = slugs, p.n = c->nest;
    p.ref = &ref->img, p.ref_var = ref->var.px ? &ref->var : NULL, p.ref_label = ref->label, p.notes = c->notes;
    return out_path(path, c, "", "index", ".html") || compare_write_page(path, &p);
}

/* ---- the command ---- */

/* The procedure. 0 done, 1 a render or a write failed, 2 bad input (nothing written). */
static int run(comparison *c)
{
    scene s;
    reference ref;
    int rc = 2;
    memset(&ref, 0, sizeof ref);
    if (load_scene(c, &s)) return 2;
    /* the inputs, checked before anything is written */
    if (make_camera(c, &s) || (c->ref && read_reference(c, &ref)) || make_dir(c->dir)) goto done;
    rc = 1;
    /* the renders: how many samples each, the reference unless given, then each estimator */
    if (choose_spp(c, &s) || (!c->ref && render_reference(c, &s, &ref))) goto done;
    ref.mean_var = ref.var.px ? mean_of(&ref.var) : 0.0;   /* its own noise, taken off each MSE */
    if (render_estimators(c, &s, &ref)) goto done;
    /* the outputs */
    if (write_heatmaps(c, &ref)) goto done;
    write_notes(c, &ref);
    if (write_mosaic(c, &ref) || write_tables(c) || write_page(c, &ref)) goto done;
    rc = 0;
done:
    img_free(&ref.img);
    img_free(&ref.var);
    scene_free(&s);
    return rc;
}

int compare_main(int argc, char **argv)
{
    comparison *c = calloc(1, sizeof *c);
    int rc, i;
    if (!c) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    rc = parse_args(c, argc, argv) ? 2 : run(c);
    for (i = 0; i < MAX_EST; i++) {
        img_free(&c->est[i].img);
        img_free(&c->est[i].var);
        img_free(&c->est[i].heat);
    }
    free(c);
    return rc;
}
