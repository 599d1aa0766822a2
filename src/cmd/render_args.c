/* render_args.c — the flags of pathlab render as a cli_flag table (most are plain kinds; the
 * custom ones store into an enum or a pair of fields, or check a range or a conflict), and the
 * camera they describe: a view file, a gKit orbiter file or framing, then the camera flags. */
#include "cmd/render_args.h"
#include "scene/orbiter.h"
#include "sys/output_path.h"
#include "sys/parallel.h"
#include "util/textfile.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Parses v as a plain kind of value (cli_parse_value), for a custom flag; 0, or 1 after printing why. */
static int parse_as(const render_args *a, const char *flag, const char *v, cli_kind kind, void *dest, double lo,
                    double hi, const char *const *choices)
{
    const cli_flag f = {flag, kind, dest, lo, hi, choices, NULL, NULL};
    return cli_parse_value(a->cmd, &f, v, NULL);
}

/* --bounces A:B, whole numbers with 0 <= A <= B <= BOUNCES_CAP, or B = inf (BOUNCES_NO_END) */
static int parse_bounces(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    const char *b;
    char *end, want[96];
    long lo = strtol(v, &end, 10), hi = BOUNCES_NO_END;
    int ok = end != v && *end == ':' && lo >= 0 && lo <= BOUNCES_CAP;
    if (ok && strcmp(end + 1, "inf")) {
        b = end + 1;
        hi = strtol(b, &end, 10);
        ok = end != b && !*end && lo <= hi && hi <= BOUNCES_CAP;
    }
    snprintf(want, sizeof want, "A:B with 0 <= A <= B <= %d, B a whole number or inf (e.g. 0:1, 2:inf)", BOUNCES_CAP);
    if (!ok) return cli_fail(a->cmd, flag, want, v);
    a->ro.io.bmin = (int)lo;
    a->ro.io.bmax = (int)hi;
    return 0;
}

/* --samples A:B, sample indices A..B-1: 0 <= A < B, at most 2^30 of them */
static int parse_samples(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    char *end, *b;
    long long lo = strtoll(v, &end, 10), hi;
    int ok = end != v && *end == ':' && lo >= 0;
    b = end + 1;
    hi = ok ? strtoll(b, &end, 10) : 0;
    ok = ok && end != b && !*end && hi > lo && hi - lo <= (1 << 30) && hi <= (1LL << 62);
    if (!ok) return cli_fail(a->cmd, flag, "A:B, the sample indices A to B-1 (0 <= A < B, at most 2^30 samples; e.g. 0:64, 64:128)", v);
    a->samples[0] = lo;
    a->samples[1] = hi;
    return 0;
}

/* --bounce K, the same as --bounces K:K */
static int parse_bounce(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    if (parse_as(a, flag, v, CLI_INT, &a->ro.io.bmin, 0, BOUNCES_CAP, NULL)) return 1;
    a->ro.io.bmax = a->ro.io.bmin;
    return 0;
}

/* --rr D|off: Russian roulette after D bounces, or never (-1) */
static int parse_rr(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    char *end;
    long d = strtol(v, &end, 10);
    if (!strcmp(v, "off")) { a->ro.io.rr_depth = -1; return 0; }
    if (end == v || *end || d < 0 || d > BOUNCES_CAP) {
        char want[64];
        snprintf(want, sizeof want, "a whole number from 0 to %d, or off", BOUNCES_CAP);
        return cli_fail(a->cmd, flag, want, v);
    }
    a->ro.io.rr_depth = (int)d;
    return 0;
}

/* --rr-below T: the roulette thins paths whose throughput is below T, p_survive = max(beta) / T */
static int parse_rr_below(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    double t;
    if (parse_as(a, flag, v, CLI_DOUBLE, &t, 0.01, 100.0, NULL)) return 1;
    a->ro.io.rr_below = (float)t;
    return 0;
}

static int parse_size(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int wh[2];
    if (parse_as(a, flag, v, CLI_SIZE, wh, 0, 0, NULL)) return 1;
    a->flags.width = wh[0];
    a->flags.height = wh[1];
    return 0;
}

/* --light, --dir, --direct: a name of the strategy's list, stored as its enum */
static int parse_light(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k;
    if (parse_as(a, flag, v, CLI_CHOICE, &k, 0, 0, LIGHT_STRATEGY_NAMES)) return 1;
    a->ro.io.light = (light_strategy)k;
    return 0;
}

static int parse_dir(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k;
    if (parse_as(a, flag, v, CLI_CHOICE, &k, 0, 0, DIR_STRATEGY_NAMES)) return 1;
    a->ro.io.dir = (dir_strategy)k;
    return 0;
}

static int parse_direct(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k;
    if (parse_as(a, flag, v, CLI_CHOICE, &k, 0, 0, DIRECT_STRATEGY_NAMES)) return 1;
    a->ro.io.direct = (direct_strategy)k;
    return 0;
}

/* --sampler independent|sobol|sobol1 */
static int parse_sampler(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k;
    if (parse_as(a, flag, v, CLI_CHOICE, &k, 0, 0, SAMPLER_NAMES)) return 1;
    a->ro.sampler = (sampler_kind)k;
    a->sampler_given = 1;
    return 0;
}

/* --orbiter FILE and --view FILE: two sources of the same view, so one only */
static int parse_camera_file(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int orb = !strcmp(flag, "--orbiter");
    if (orb ? a->view_file != NULL : a->orbiter != NULL) {
        fprintf(stderr, "pathlab %s: --orbiter and --view both give the camera: use one of them\n", a->cmd);
        return 1;
    }
    *(orb ? &a->orbiter : &a->view_file) = v;
    return 0;
}

/* --pixel-offset O: pixel (x, y) centred at (x + O, y + O), O in [0, 1) */
static int parse_pixel_offset(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    char *end;
    double o = strtod(v, &end);
    if (end == v || *end || !(o >= 0.0 && o < 1.0))
        return cli_fail(a->cmd, flag, "a number from 0 (gKit's Point(x, y, 0)) up to but not including 1; 0.5 is the pixel centre", v);
    a->ro.pixel_offset = (float)o;
    return 0;
}

void render_flag_table(render_args *a, cli_flag t[RENDER_NFLAGS])
{
    const cli_flag flags[RENDER_NFLAGS] = {
        {"-o", CLI_STRING, &a->out, 0, 0, NULL, NULL, NULL},
        {"--variance", CLI_STRING, &a->variance, 0, 0, NULL, NULL, NULL},
        {"--spp", CLI_INT, &a->spp, 1, 1 << 30, NULL, NULL, &a->spp_given},
        {"--samples", CLI_CUSTOM, NULL, 0, 0, NULL, parse_samples, &a->samples_given},
        {"--time", CLI_DOUBLE, &a->ro.time_limit, 1e-3, 1e9, NULL, NULL, NULL},
        {"--resume", CLI_SWITCH, &a->resume, 0, 0, NULL, NULL, NULL},
        {"--seed", CLI_U64, &a->ro.seed, 0, 0, NULL, NULL, NULL},
        {"--threads", CLI_INT, &a->ro.threads, 1, PARALLEL_MAX_THREADS, NULL, NULL, NULL},
        {"--quiet", CLI_SWITCH, &a->ro.quiet, 0, 0, NULL, NULL, NULL},
        {"--exposure", CLI_FLOAT, &a->exposure, 0, 0, NULL, NULL, NULL},
        {"--eye", CLI_VEC3, &a->flags.eye, 0, 0, NULL, NULL, &a->eye},
        {"--target", CLI_VEC3, &a->flags.target, 0, 0, NULL, NULL, &a->target},
        {"--up", CLI_VEC3, &a->flags.up, 0, 0, NULL, NULL, &a->up},
        {"--fov", CLI_FLOAT, &a->flags.fov, 0, 0, NULL, NULL, &a->fov},
        {"--size", CLI_CUSTOM, NULL, 0, 0, NULL, parse_size, &a->size},
        {"--pixel-center", CLI_SWITCH, &a->ro.pixel_center, 0, 0, NULL, NULL, NULL},
        {"--bounces", CLI_CUSTOM, NULL, 0, 0, NULL, parse_bounces, NULL},
        {"--bounce", CLI_CUSTOM, NULL, 0, 0, NULL, parse_bounce, NULL},
        {"--split", CLI_SWITCH, &a->ro.split, 0, 0, NULL, NULL, NULL},
        {"--light", CLI_CUSTOM, NULL, 0, 0, NULL, parse_light, NULL},
        {"--dir", CLI_CUSTOM, NULL, 0, 0, NULL, parse_dir, NULL},
        {"--direct", CLI_CUSTOM, NULL, 0, 0, NULL, parse_direct, NULL},
        {"--rr", CLI_CUSTOM, NULL, 0, 0, NULL, parse_rr, NULL},
        {"--rr-below", CLI_CUSTOM, NULL, 0, 0, NULL, parse_rr_below, NULL},
        {"--orbiter", CLI_CUSTOM, NULL, 0, 0, NULL, parse_camera_file, NULL},
        {"--view", CLI_CUSTOM, NULL, 0, 0, NULL, parse_camera_file, NULL},
        {"--write-view", CLI_STRING, &a->write_view, 0, 0, NULL, NULL, NULL},
        {"--pixel-offset", CLI_CUSTOM, NULL, 0, 0, NULL, parse_pixel_offset, NULL},
        {"--sampler", CLI_CUSTOM, NULL, 0, 0, NULL, parse_sampler, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    memcpy(t, flags, sizeof flags);
}

int render_parse_flag(render_args *a, int argc, char **argv, int *i)
{
    cli_flag t[RENDER_NFLAGS];
    const cli_flag *tables[3];
    if (cli_is_word(argv[*i])) {
        if (a->scene) {
            fprintf(stderr, "pathlab %s: one scene only, got '%s' and '%s'\n", a->cmd, a->scene, argv[*i]);
            return 1;
        }
        a->scene = argv[*i];
        return 0;
    }
    render_flag_table(a, t);
    tables[0] = t;
    tables[1] = a->more_flags;   /* a typo of compare's own flag gets its suggestion too */
    tables[2] = NULL;
    return cli_parse_flag(a->cmd, argc, argv, i, tables, a);
}

void render_args_init(render_args *a)
{
    memset(a, 0, sizeof *a);
    a->cmd = "render";
    a->spp = 16;
    a->ro.seed = 1;
    a->ro.pixel_offset = 0.5f;
    a->ro.threads = parallel_default_threads();
    a->ro.sampler = SAMPLER_INDEPENDENT;
    a->ro.io.light = LIGHT_AREA;
    a->ro.io.dir = DIR_BRDF;
    a->ro.io.direct = DIRECT_MIS_POWER;
    a->ro.io.bmin = 0;
    a->ro.io.bmax = BOUNCES_NO_END;
    a->ro.io.rr_depth = 3;
    adaptive_opts_init(&a->ao);
}

/* --orbiter FILE into a->vw; 0, or 1 after printing why. An old file without an f line leaves fov
 * and size to the flags or the defaults, which may not be what the student's program used. */
static int read_orbiter(render_args *a)
{
    orbiter o;
    if (orbiter_read(&o, a->orbiter)) return 1;
    orbiter_view(&o, &a->vw);
    if (!o.has_f && !(a->fov && a->size))
        fprintf(stderr, "pathlab %s: note: %s has no 'f fov width height' line (an older gKit file): rendering %dx%d "
                        "with a %g degree vertical fov; give the student's with --size and --fov\n",
                a->cmd, a->orbiter, a->size ? a->flags.width : a->vw.width, a->size ? a->flags.height : a->vw.height,
                a->fov ? a->flags.fov : a->vw.fov);
    return 0;
}

/* The view before the camera flags: --orbiter, --view, or SCENE.view if it exists; 0 or 1 after printing why. */
static int base_view(render_args *a)
{
    char path[PATH_CAP];
    size_t n = strlen(a->scene) - strlen(img_extension(a->scene));
    int rc;
    view_defaults(&a->vw);
    if (a->orbiter) return read_orbiter(a);
    if (a->view_file) {
        rc = view_read(&a->vw, a->view_file);
        if (rc < 0) fprintf(stderr, "pathlab %s: --view %s: no such file\n", a->cmd, a->view_file);
        return rc != 0;
    }
    if (n + 6 < sizeof path) {
        memcpy(path, a->scene, n);
        strcpy(path + n, ".view");
        if (view_read(&a->vw, path) > 0) return 1;
    }
    return 0;
}

/* --write-view FILE: the view the camera was made of, written atomically: a half-written file would
 * read back as another camera without a word */
static int write_view(const render_args *a)
{
    char tmp[PATH_CAP];
    FILE *f = textfile_open(a->write_view, tmp, sizeof tmp);
    if (!f) return 1;
    fprintf(f, "# the camera of pathlab %s %s%s%s: read it back with --view\n", a->cmd, a->scene,
            a->orbiter ? " --orbiter " : "", a->orbiter ? a->orbiter : "");
    view_print(f, &a->vw);
    return textfile_close(f, tmp, a->write_view);
}

int render_check_camera_flags(const render_args *a)
{
    const view *f = &a->flags;
    char v[64];
    if (a->fov && !(f->fov > 0.0f && f->fov < 180.0f)) {
        snprintf(v, sizeof v, "%g", f->fov);
        return cli_fail(a->cmd, "--fov", "a vertical field of view in degrees, more than 0 and less than 180 (e.g. 40)", v);
    }
    if (a->up && !(v3_length(f->up) > 0.0f)) return cli_fail(a->cmd, "--up", "a direction, not 0,0,0", "0,0,0");
    if (a->eye && a->target && !(v3_length(v3_sub(f->target, f->eye)) > 0.0f)) {
        fprintf(stderr, "pathlab %s: --eye and --target are the same point: the camera would look nowhere\n", a->cmd);
        return 1;
    }
    if (a->eye && a->target && a->up
        && !(v3_length(v3_cross(v3_sub(f->target, f->eye), f->up)) > 1e-6f * v3_length(v3_sub(f->target, f->eye)) * v3_length(f->up))) {
        fprintf(stderr, "pathlab %s: --up is parallel to the view direction (--target minus --eye): the image's up is undefined\n", a->cmd);
        return 1;
    }
    return 0;
}

int render_make_camera(render_args *a, const scene *s, camera *cam)
{
    vec3 lo, hi;
    if (base_view(a)) return 1;
    /* a flag overrides its key: camera errors then name the flag's value, not the view file's line */
    if (a->eye) { a->vw.eye = a->flags.eye; a->vw.has_eye = 1; a->vw.line_eye = 0; }
    if (a->target) { a->vw.target = a->flags.target; a->vw.has_target = 1; a->vw.line_target = 0; }
    if (a->up) { a->vw.up = a->flags.up; a->vw.line_up = 0; }
    if (a->fov) { a->vw.fov = a->flags.fov; a->vw.line_fov = 0; }
    if (a->size) { a->vw.width = a->flags.width; a->vw.height = a->flags.height; a->vw.line_size = 0; }
    mesh_bounds(&s->m, &lo, &hi);
    view_frame_bounds(&a->vw, lo, hi);
    if (camera_init(cam, &a->vw)) return 1;
    return a->write_view ? write_view(a) : 0;
}
