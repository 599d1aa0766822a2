/* compare.c — pathlab compare: several estimators of one scene side by side, with their errors.
 * run() is the procedure, one named step per line. The estimators' language is in estimators.c,
 * the table in compare/compare_report.c, the layout of the mosaic in image/mosaic.c.
 *
 * Choices (summed up in COMPARE_HELP, compare.h):
 * - An estimator is a list of render flags and names (estimators.h). Flags outside --estimators
 *   apply to all; each estimator's flags are parsed after them, so they win. --spp, -o, --variance
 *   and --split are refused inside an estimator: the comparison fixes the samples (or the time) and
 *   the files.
 * - Equal time (--time SEC): each estimator is rendered at round(SEC / its seconds per sample) spp,
 *   measured on calibration renders (compare/compare_render.h) until one takes a fifth of SEC; the
 *   estimate is pessimistic, so the final time is often under SEC; the table shows the time measured.
 * - The reference, when not given, is rendered first with the best estimator (--direct mis-power
 *   --light solid-angle --dir brdf) at 16 x the largest spp (--ref-spp to change), with a different
 *   seed so that its noise is independent of the estimators'. It is written as DIR/reference.pfm.
 * - What is measured (the reference's noise taken off each MSE) is compare/compare_results.h; what is
 *   written once all is rendered (heatmaps on one scale, notes, mosaic, tables, page) compare/compare_outputs.h. */
#include "cmd/compare.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "compare/compare_files.h"
#include "compare/compare_outputs.h"
#include "compare/compare_render.h"
#include "compare/view_images.h"
#include "image/exposure.h"
#include "cmd/estimators.h"
#include "cmd/help.h"
#include "cmd/render_args.h"
#include "cmd/version.h"
#include "files/render_files.h"
#include "files/render_meta.h"
#include "render/render.h"
#include "util/cli.h"
#include "sys/output_path.h"
#include "util/path.h"
#include "sys/input_file.h"

#define MAX_EST COMPARE_MAX_EST
#define CALIB_FRACTION 0.2    /* of --time: the length of the last calibration render */

/* The best estimator of the course, for the reference. */
static const char REFERENCE_FLAGS[] = "--direct mis-power --light solid-angle --dir brdf";
/* Render flags that compare refuses: it names its files itself. */
static const char *const RENDER_ONLY[] = {"--split", "--variance", NULL};

/* The flags, then what run() finds step by step. */
typedef struct {
    render_args base;                      /* the render flags outside --estimators: shared */
    const char *list, *dir, *ref, *ref_var;
    int spp, spp_given, ref_spp;
    float time, scale;                     /* --time (0: equal spp), --scale (0: none given) */
    int scale_given;
    int nest;
    estimator_spec spec[MAX_EST];          /* each estimator's label, file name and render flags */
    compare_estimator est[MAX_EST];        /* and its results */
    camera cam;                            /* one view for all */
    char ref_var_found[PATH_CAP];          /* --ref's variance when --ref-var is not given: REF_var.pfm or its sidecar's */
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
                fprintf(stderr, "pathlab: compare: %s is a flag of render only\n", shown(argv[i]));
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
        {"--scale", CLI_FLOAT, &c->scale, 0, 0, NULL, NULL, &c->scale_given},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {own, NULL};
    char **mine = malloc(2 * (size_t)argc * sizeof *mine), **rest = mine + argc;
    int nmine = 1, nrest = 1, nwords, i, err;
    if (!mine) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    mine[0] = rest[0] = argv[0];
    if (cli_listing()) {   /* the shell's completion: compare's flags and the render flags (util/cli.h) */
        char *dash[] = {argv[0], "--", NULL};
        i = 1, c->base.cmd = "compare", c->base.more_flags = own;
        render_parse_flag(&c->base, 2, dash, &i);
        free(mine);
        return 1;
    }
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
    if (c->scale_given && c->scale < 0.0f) {   /* -1 was taken for 0, "none given" */
        char v[32];
        snprintf(v, sizeof v, "%g", c->scale);
        return cli_fail("compare", "--scale", "a number >= 0 (the heatmaps' white; 0: 3x the largest RMSE)", v);
    }
    if (c->ref_var && !c->ref) { fprintf(stderr, "pathlab: compare: --ref-var goes with --ref\n"); return 1; }
    if (c->ref && c->ref_spp) { fprintf(stderr, "pathlab: compare: --ref-spp is for a rendered reference, not with --ref\n"); return 1; }
    return render_check_camera_flags(&c->base) || output_dir_check("compare", "-o", c->dir);
}

/* Each estimator's results are named after its spec: its files DIR/SLUG.*, its label and flags. */
static int name_results(comparison *c)
{
    int i;
    for (i = 0; i < c->nest; i++)
        c->est[i].slug = c->spec[i].slug, c->est[i].row.label = c->spec[i].label, c->est[i].row.flags = c->spec[i].flags;
    return compare_check_names(c->est, c->nest);
}

static int parse_args(comparison *c, int argc, char **argv)
{
    render_args_init(&c->base);
    c->spp = 16;
    if (parse_flags(c, argc, argv) || check_flags(c)) return 1;
    return estimators_parse(c->list, &c->base, c->spec, MAX_EST, &c->nest) || name_results(c);
}

/* ---- the steps of run() ---- */

static int load_scene(const comparison *c, scene *s)
{
    int i;
    if (scene_load(s, c->base.scene, &c->base.so, c->base.ro.threads, 1)) return 1;
    for (i = 0; i < c->nest; i++)   /* --write-view over a texture or an MTL of the scene */
        if (render_files_scene_clash("compare", &c->spec[i].a.cam.write_view, 1, &s->m)) { scene_free(s); return 1; }
    if (scene_add_sky(s, &c->base.ro.sky)) { scene_free(s); return 1; }
    if (!scene_has_light(s))
        fprintf(stderr, "pathlab: warning: %s has no emitters and %s: every image is black\n", shown(c->base.scene),
                c->base.ro.sky.kind == SKY_NONE ? "no --sky" : "the --sky given is black (every pixel 0)");
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
                    shown(label), cam.width, cam.height, shown(first), c->cam.width, c->cam.height);
            return 1;
        }
        if (i && !(same_vec(cam.eye, c->cam.eye) && same_vec(cam.w, c->cam.w) && same_vec(cam.u, c->cam.u) && same_vec(cam.v, c->cam.v))) {
            fprintf(stderr, "pathlab: compare: estimator '%s' sees the scene from another camera than '%s': one view for all\n", shown(label), shown(first));
            return 1;
        }
    }
    return 0;
}

/* The samples of each estimator: --spp, or as many as its calibrated speed fits in --time. */
static int choose_spp(comparison *c, const scene *s)
{
    double sec_per_spp;
    int i;
    for (i = 0; i < c->nest; i++) {
        compare_estimator *e = &c->est[i];
        if (c->time > 0.0f) {
            if (compare_calibrate(s, &c->cam, c->spec[i].a.ro, CALIB_FRACTION * c->time, &sec_per_spp)) return 1;
            e->row.spp = (int)fmin(1 << 30, fmax(1.0, floor(c->time / sec_per_spp + 0.5)));
            if (!c->base.ro.quiet)
                fprintf(stderr, "compare: %s: %.3g ms per spp -> %d spp for %g s\n", shown(c->spec[i].label), 1e3 * sec_per_spp, e->row.spp, c->time);
        } else {
            e->row.spp = c->spp;
        }
    }
    return 0;
}

/* DIR/SLUG.pfm and, if var has pixels, DIR/SLUG_var.pfm, each with its sidecar as render writes them
 * (scene, flags, camera, seed, samples: grade, merge and view find the variance and read what made
 * the image); then DIR/SLUG.png. 0, or 1 after printing why. */
static int save_render(comparison *c, const scene *s, const render_opts *ro, const char *slug, const image *img,
                       const image *var, int dof)
{
    char out[PATH_CAP], var_out[PATH_CAP];
    sidecar m;
    if (compare_out_path(out, c->dir, "", slug, ".pfm") || compare_out_path(var_out, c->dir, slug, "_var", ".pfm")) return 1;
    render_meta_describe(&m, ro, c->base.scene, s, &c->spec[0].a.cam.vw, pathlab_revision());
    render_meta_describe_scene(&m, &ro->io, &c->base.so);   /* --material, --normals ...: resume and merge compare them */
    m.nranges = 1;
    m.range[0][0] = ro->first;
    m.range[0][1] = ro->first + (uint64_t)ro->spp;
    m.variance_dof = dof;
    if (isnan(c->base.exposure)) c->base.exposure = img_auto_exposure(img);   /* --exposure auto: the first image's, for all */
    return render_files_write(out, var->px ? var_out : NULL, 0.0f, &m, img, var, 1, 0)
           || compare_save_image(c->dir, "", slug, ".png", img, c->base.exposure);
}

/* The best estimator, 16 x the largest spp (or --ref-spp), its own seed; written as DIR/reference.*. */
static int render_reference(comparison *c, const scene *s, compare_reference *ref)
{
    estimator_spec best;
    int i, n, max_spp = 0, dof = 0;
    if (estimators_parse(REFERENCE_FLAGS, &c->base, &best, 1, &n)) return 1;
    for (i = 0; i < c->nest; i++)
        if (c->est[i].row.spp > max_spp) max_spp = c->est[i].row.spp;
    ref->spp = best.a.ro.spp = c->ref_spp ? c->ref_spp : (int)fmin(1 << 30, 16.0 * max_spp);
    ref->seed = best.a.ro.seed = c->base.ro.seed ^ 0x9e3779b97f4a7c15ULL;
    best.a.ro.quiet = c->base.ro.quiet;
    snprintf(ref->label, sizeof ref->label, "reference %d spp", ref->spp);
    if (!c->base.ro.quiet) fprintf(stderr, "compare: rendering the reference: %d spp of %s\n", ref->spp, REFERENCE_FLAGS);
    return compare_render_image(s, &c->cam, &best.a.ro, &ref->img, &ref->var, &dof, &ref->secs)
           || save_render(c, s, &best.a.ro, "reference", &ref->img, &ref->var, dof);
}

/* Each estimator at its spp, written as DIR/SLUG.pfm and .png, and measured. */
static int render_estimators(comparison *c, const scene *s, const compare_reference *ref)
{
    int i, dof = 0;
    for (i = 0; i < c->nest; i++) {
        compare_estimator *e = &c->est[i];
        const estimator_spec *sp = &c->spec[i];
        render_opts ro = sp->a.ro;
        ro.spp = e->row.spp;
        if (compare_render_image(s, &c->cam, &ro, &e->img, &e->var, &dof, &e->row.secs)) return 1;
        compare_measure(&e->row, &e->img, ref);
        if (isnan(e->row.mse))
            fprintf(stderr, "pathlab compare: warning: %s: its squared error against the reference (%.4g) is below the reference's "
                    "own variance (%.4g): its MSE and efficiency cannot be measured (nan); use a reference of more samples "
                    "(--ref-spp, or --ref with its variance)\n", shown(sp->label), e->row.rmse * e->row.rmse, ref->mean_var);
        if (!c->base.ro.quiet) fprintf(stderr, "compare: %s: %d spp in %.3f s, RMSE %.4g\n", shown(sp->label), e->row.spp, e->row.secs, e->row.rmse);
        if (save_render(c, s, &ro, sp->slug, &e->img, &e->var, dof)) return 1;
    }
    return 0;
}

/* The heatmaps, notes, mosaic, tables and page (compare/compare_outputs.h). */
static int write_outputs(comparison *c, const compare_reference *ref)
{
    compare_outputs o;
    memset(&o, 0, sizeof o);
    o.dir = c->dir, o.scene = c->base.scene, o.exposure = c->base.exposure, o.scale = c->scale;
    o.n = c->nest, o.est = c->est, o.ref = ref;
    o.ref_path = c->ref, o.ref_var_path = c->ref_var, o.ref_flags = REFERENCE_FLAGS, o.ref_spp_given = c->ref_spp != 0;
    o.time = c->time, o.calib_secs = CALIB_FRACTION * c->time, o.spp = c->spp, o.threads = c->base.ro.threads;
    return compare_write_outputs(&o);
}

/* ---- the command ---- */

/* Every file compare writes in DIR, checked before any render (a folder named DIR/index.html or
 * DIR/brdf.pfm was found after the renders, 22 files written): 0, or 1 after printing why. */
static int check_outputs(const comparison *c)
{
    static const char *const shared[] = {"mosaic.ppm", "mosaic.png", "table.md", "table.csv", "index.html", "reference.pfm",
                                         "reference.pfm.meta", "reference_var.pfm", "reference_var.pfm.meta", "reference.png", NULL};
    static const char *const each[] = {"%s/%s.pfm", "%s/%s.pfm.meta", "%s/%s_var.pfm", "%s/%s_var.pfm.meta", "%s/%s.png",
                                       "%s/heat-%s.png", NULL};
    char path[PATH_CAP];
    struct stat st;
    int i, k;
    if (lstat(c->dir, &st) != 0) return 0;   /* not there yet: made empty, nothing in the way */
    if (stat(c->dir, &st) != 0 || !S_ISDIR(st.st_mode)) {   /* a file, or a dangling link given as -o */
        fprintf(stderr, "pathlab compare: -o %s: not a folder\n", shown(c->dir));
        return 1;
    }
    for (k = 0; shared[k]; k++)
        if (snprintf(path, sizeof path, "%s/%s", c->dir, shared[k]) >= (int)sizeof path || output_path_check("compare", "-o", path, NULL))
            return 1;
    for (i = 0; i < c->nest; i++)
        for (k = 0; each[k]; k++)
            if (snprintf(path, sizeof path, each[k], c->dir, c->spec[i].slug) >= (int)sizeof path || output_path_check("compare", "-o", path, NULL))
                return 1;
    return 0;
}

/* 1 if path is a file of the folder whose key (render_files_key, its real path and a slash) is dir. */
static int in_folder(const char *dir, const char *path)
{
    char b[PATH_CAP];
    render_files_key(b, sizeof b, path);
    return !strncmp(dir, b, strlen(dir)) && !strchr(b + strlen(dir), '/');
}

/* 1 (said) if an input lies in the folder -o, where compare writes its files (DIR/light.pfm over
 * --ref DIR/light.pfm replaced a reference of 256 spp by a render of 4; --sky DIR/light.pfm so), or
 * a --write-view is an input, in DIR, or not a view file's name (--write-view cam.orbiter over the
 * student's orbiter file). */
static int inputs_clash(const comparison *c)
{
    char probe[PATH_CAP], a[PATH_CAP];
    const char *in[6], *what[6] = {"--ref", "the reference's variance", "--sky", "--orbiter", "--mtl", "the scene"};
    int k, i;
    in[0] = c->ref, in[1] = c->ref_var, in[2] = c->base.ro.sky.kind == SKY_IMAGE ? c->base.ro.sky.path : NULL;
    in[3] = c->base.cam.orbiter, in[4] = c->base.so.obj.mtl, in[5] = c->base.scene;
    if (snprintf(probe, sizeof probe, "%s/x", c->dir) >= (int)sizeof probe) return 0;
    render_files_key(a, sizeof a, probe);
    a[strlen(a) - 1] = '\0';   /* DIR's real path and a slash */
    for (k = 0; k < 6; k++) {
        if (in[k] && in_folder(a, in[k])) {
            fprintf(stderr, "pathlab compare: %s %s is in the output folder %s, where compare writes its files: keep it "
                    "in another folder\n", what[k], shown(in[k]), shown(c->dir));
            return 1;
        }
    }
    for (i = 0; i < c->nest; i++) {
        const char *v = c->spec[i].a.cam.write_view, *orb = c->spec[i].a.cam.orbiter;
        if (!v) continue;
        if (render_files_view_name_bad("compare", v)) return 1;
        if (in_folder(a, v)) {
            fprintf(stderr, "pathlab compare: --write-view %s: in the output folder, where compare writes its files\n", shown(v));
            return 1;
        }
        for (k = 0; k < 6; k++) {
            const char *file = k == 3 && orb ? orb : in[k];   /* the estimator's own --orbiter, if it has one */
            if (file && path_same_file(v, file)) {
                fprintf(stderr, "pathlab compare: --write-view %s is %s: give it its own name\n", shown(v), what[k]);
                return 1;
            }
        }
    }
    return 0;
}

/* The procedure. 0 done, 1 a render or a write failed, 2 bad input (nothing written). */
static int run(comparison *c)
{
    scene s;
    compare_reference ref;
    int rc = 2, i;
    memset(&ref, 0, sizeof ref);
    if (load_scene(c, &s)) return 2;
    if (c->ref && !c->ref_var) {   /* --ref is the user's: links followed; beside it, else beside the file it leads to */
        char *real = input_file_resolved(c->ref);
        i = view_find_variance(c->ref, c->ref_var_found, sizeof c->ref_var_found, "compare",
                               FIND_VARIANCE_TRUSTED | (real && strcmp(real, c->ref) ? FIND_VARIANCE_QUIET : 0));
        if (i == 0 && real && strcmp(real, c->ref)) i = view_find_variance(real, c->ref_var_found, sizeof c->ref_var_found, "compare", FIND_VARIANCE_TRUSTED);
        free(real);
        if (i == 2) goto done;   /* refused, said: not a comparison without the noise it named */
        if (i == 1) c->ref_var = c->ref_var_found;
    }
    /* the inputs, checked before anything is written */
    if (inputs_clash(c) || make_camera(c, &s) || (c->ref && compare_read_reference(&ref, c->ref, c->ref_var, c->cam.width, c->cam.height))
        || check_outputs(c) || compare_make_dir(c->dir)) goto done;
    rc = 1;
    /* the renders: how many samples each, the reference unless given, then each estimator */
    if (c->ref && isnan(c->base.exposure)) c->base.exposure = img_auto_exposure(&ref.img);   /* --exposure auto */
    if (choose_spp(c, &s) || (!c->ref && render_reference(c, &s, &ref))) goto done;
    compare_reference_noise(&ref);   /* its own noise, taken off each MSE */
    if (render_estimators(c, &s, &ref)) goto done;
    if (write_outputs(c, &ref)) goto done;
    for (i = 0; i < c->nest; i++)   /* --write-view: the camera, written last (one for all: make_camera) */
        if (view_setup_write(&c->spec[i].a.cam, "compare", c->base.scene)) goto done;
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
    int rc;
    if (!c) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    rc = parse_args(c, argc, argv) ? 2 : run(c);
    compare_estimators_free(c->est, MAX_EST);
    free(c);
    return rc;
}
