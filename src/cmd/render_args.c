/* render_args.c — the flags of pathlab render as a cli_flag table (most are plain kinds; the
 * custom ones store into an enum or a pair of fields, or check a range or a conflict); the camera
 * they describe is made by files/view_setup.c. */
#include "cmd/render_args.h"
#include "sys/shown.h"
#include "sys/parallel.h"
#include <math.h>
#include <ctype.h>
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

/* The index of v in the list names (a CLI_CHOICE flag, for an enum), or -1 after printing why. */
static int choice_index(const render_args *a, const char *flag, const char *v, const char *const *names)
{
    int k = -1;
    return parse_as(a, flag, v, CLI_CHOICE, &k, 0, 0, names) ? -1 : k;
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
/* --exposure STOPS, or auto: NAN until the image is there (image/exposure.h picks it then) */
static int parse_exposure(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    const cli_flag f = {flag, CLI_FLOAT, &a->exposure, 0, 0, NULL, NULL, NULL};
    if (!strcmp(v, "auto")) { a->exposure = NAN; return 0; }
    return cli_parse_value(a->cmd, &f, v, NULL);
}

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
    a->cam.flags.width = wh[0];
    a->cam.flags.height = wh[1];
    return 0;
}

/* --light, --dir, --direct: a name of the strategy's list, stored as its enum */
static int parse_light(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, LIGHT_STRATEGY_NAMES);
    if (k < 0) return 1;
    a->ro.io.light = (light_strategy)k;
    return 0;
}

static int parse_dir(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, DIR_STRATEGY_NAMES);
    if (k < 0) return 1;
    a->ro.io.dir = (dir_strategy)k;
    return 0;
}

static int parse_direct(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, DIRECT_STRATEGY_NAMES);
    if (k < 0) return 1;
    a->ro.io.direct = (direct_strategy)k;
    return 0;
}

/* --material, --normals, --texture-filter, --texture-decode: a name of the list, stored as its enum */
static int parse_material(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, BRDF_MODEL_NAMES);
    if (k < 0) return 1;
    a->ro.io.material = a->so.model = (brdf_model)k;
    return 0;
}

static int parse_normals(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, NORMALS_MODE_NAMES);
    if (k < 0) return 1;
    a->ro.io.normals = (normals_mode)k;
    return 0;
}

static int parse_texture_filter(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, TEXTURE_FILTER_NAMES);
    if (k < 0) return 1;
    a->ro.io.filter = (texture_filter)k;
    return 0;
}

static int parse_texture_decode(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, TEXTURE_DECODE_NAMES);
    if (k < 0) return 1;
    a->so.obj.decode = (texture_decode)k;
    return 0;
}

/* --sampler independent|sobol|sobol1 */
static int parse_sampler(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int k = choice_index(a, flag, v, SAMPLER_NAMES);
    if (k < 0) return 1;
    a->ro.sampler = (sampler_kind)k;
    a->sampler_given = 1;
    return 0;
}

/* --orbiter FILE and --view FILE: two sources of the same view, so one only */
static int parse_camera_file(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    int orb = !strcmp(flag, "--orbiter");
    if (orb ? a->cam.view_file != NULL : a->cam.orbiter != NULL) {
        fprintf(stderr, "pathlab %s: --orbiter and --view both give the camera: use one of them\n", a->cmd);
        return 1;
    }
    *(orb ? &a->cam.orbiter : &a->cam.view_file) = v;
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

/* 1 if path ends in ext (".pfm"), in any case */
static int has_extension(const char *path, const char *ext)
{
    const char *e = img_extension(path);
    size_t k;
    if (strlen(e) != strlen(ext)) return 0;
    for (k = 0; e[k]; k++)
        if (tolower((unsigned char)e[k]) != ext[k]) return 0;
    return 1;
}

/* --sky R,G,B (a constant radiance, each finite and >= 0) or --sky FILE.pfm|FILE.hdr (an
 * equirectangular image, tracer/sky.h; read with the scene) */
static int parse_sky(void *ctx, const char *flag, const char *v)
{
    render_args *a = ctx;
    const cli_flag f = {flag, CLI_VEC3, &a->ro.sky.rgb, 0, 0, NULL, NULL, NULL};
    vec3 c;
    if (has_extension(v, ".pfm") || has_extension(v, ".hdr")) {
        a->ro.sky.kind = SKY_IMAGE, a->ro.sky.path = v;
        return 0;
    }
    if (!strchr(v, ',')) return cli_fail(a->cmd, flag, "R,G,B (a radiance, e.g. 1,1,1) or an equirectangular image FILE.pfm or FILE.hdr", v);
    if (cli_parse_value(a->cmd, &f, v, NULL)) return 1;
    c = a->ro.sky.rgb;
    if (!(c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f && c.x <= 3.4e38f && c.y <= 3.4e38f && c.z <= 3.4e38f))
        return cli_fail(a->cmd, flag, "a radiance R,G,B with each value finite and >= 0 (e.g. 1,1,1)", v);
    a->ro.sky.kind = SKY_CONSTANT;
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
        {"--exposure", CLI_CUSTOM, NULL, 0, 0, NULL, parse_exposure, NULL},
        {"--eye", CLI_VEC3, &a->cam.flags.eye, 0, 0, NULL, NULL, &a->cam.eye},
        {"--target", CLI_VEC3, &a->cam.flags.target, 0, 0, NULL, NULL, &a->cam.target},
        {"--up", CLI_VEC3, &a->cam.flags.up, 0, 0, NULL, NULL, &a->cam.up},
        {"--fov", CLI_FLOAT, &a->cam.flags.fov, 0, 0, NULL, NULL, &a->cam.fov},
        {"--size", CLI_CUSTOM, NULL, 0, 0, NULL, parse_size, &a->cam.size},
        {"--pixel-center", CLI_SWITCH, &a->ro.pixel_center, 0, 0, NULL, NULL, NULL},
        {"--bounces", CLI_CUSTOM, NULL, 0, 0, NULL, parse_bounces, NULL},
        {"--bounce", CLI_CUSTOM, NULL, 0, 0, NULL, parse_bounce, NULL},
        {"--split", CLI_SWITCH, &a->ro.split, 0, 0, NULL, NULL, NULL},
        {"--light", CLI_CUSTOM, NULL, 0, 0, LIGHT_STRATEGY_NAMES, parse_light, NULL},
        {"--dir", CLI_CUSTOM, NULL, 0, 0, DIR_STRATEGY_NAMES, parse_dir, NULL},
        {"--direct", CLI_CUSTOM, NULL, 0, 0, DIRECT_STRATEGY_NAMES, parse_direct, NULL},
        {"--rr", CLI_CUSTOM, NULL, 0, 0, NULL, parse_rr, NULL},
        {"--rr-below", CLI_CUSTOM, NULL, 0, 0, NULL, parse_rr_below, NULL},
        {"--orbiter", CLI_CUSTOM, NULL, 0, 0, NULL, parse_camera_file, NULL},
        {"--view", CLI_CUSTOM, NULL, 0, 0, NULL, parse_camera_file, NULL},
        {"--write-view", CLI_STRING, &a->cam.write_view, 0, 0, NULL, NULL, NULL},
        {"--pixel-offset", CLI_CUSTOM, NULL, 0, 0, NULL, parse_pixel_offset, NULL},
        {"--sampler", CLI_CUSTOM, NULL, 0, 0, SAMPLER_NAMES, parse_sampler, NULL},
        {"--material", CLI_CUSTOM, NULL, 0, 0, BRDF_MODEL_NAMES, parse_material, NULL},
        {"--normals", CLI_CUSTOM, NULL, 0, 0, NORMALS_MODE_NAMES, parse_normals, NULL},
        {"--texture-filter", CLI_CUSTOM, NULL, 0, 0, TEXTURE_FILTER_NAMES, parse_texture_filter, NULL},
        {"--texture-decode", CLI_CUSTOM, NULL, 0, 0, TEXTURE_DECODE_NAMES, parse_texture_decode, NULL},
        {"--mtl", CLI_STRING, &a->so.obj.mtl, 0, 0, NULL, NULL, NULL},
        {"--sky", CLI_CUSTOM, NULL, 0, 0, NULL, parse_sky, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    memcpy(t, flags, sizeof flags);
}

int render_parse_flag(render_args *a, int argc, char **argv, int *i)
{
    cli_flag t[RENDER_NFLAGS];
    const cli_flag *tables[3];
    if (cli_is_word(argv[*i])) {
        if (a->scene) {
            fprintf(stderr, "pathlab %s: one scene only, got '%s' and '%s'\n", a->cmd, shown(a->scene), shown(argv[*i]));
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

int render_check_camera_flags(const render_args *a) { return view_setup_check(&a->cam, a->cmd); }

int render_make_camera(render_args *a, const scene *s, camera *cam) { return view_setup_camera(&a->cam, a->cmd, a->scene, &s->m, cam); }
