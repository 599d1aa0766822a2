/* cli.c — flag value parsing. */
#include "util/cli.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int bad(const char *flag, const char *what, const char *s)
{
    fprintf(stderr, "pathlab: %s expects %s, got '%s'\n", flag, what, s);
    return 1;
}

int cli_int(const char *flag, const char *s, int lo, int hi, int *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi) {
        char what[96];
        sprintf(what, "a whole number from %d to %d", lo, hi);
        return bad(flag, what, s);
    }
    *out = (int)v;
    return 0;
}

int cli_u64(const char *flag, const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (end == s || *end || errno || s[0] == '-') return bad(flag, "a whole number >= 0", s);
    *out = (uint64_t)v;
    return 0;
}

int cli_float(const char *flag, const char *s, float *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v)) return bad(flag, "a number", s);
    *out = (float)v;
    return 0;
}

int cli_vec3(const char *flag, const char *s, vec3 *out)
{
    double v[3];
    char *end;
    const char *p = s;
    int i;
    for (i = 0; i < 3; i++) {
        v[i] = strtod(p, &end);
        if (end == p || !isfinite(v[i]) || *end != (i < 2 ? ',' : '\0')) return bad(flag, "three numbers x,y,z", s);
        p = end + 1;
    }
    *out = v3((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

int cli_size(const char *flag, const char *s, int *w, int *h)
{
    char *end;
    long a, b;
    a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X')) return bad(flag, "WIDTHxHEIGHT, e.g. 512x512", s);
    s = end + 1;
    b = strtol(s, &end, 10);
    if (end == s || *end || a < 1 || b < 1 || a > 65536 || b > 65536) return bad(flag, "WIDTHxHEIGHT, each 1 to 65536", s);
    *w = (int)a;
    *h = (int)b;
    return 0;
}

int cli_choice(const char *flag, const char *s, const char *const *names, int *out)
{
    char what[256] = "one of";
    int i;
    for (i = 0; names[i]; i++) {
        if (!strcmp(s, names[i])) { *out = i; return 0; }
    }
    for (i = 0; names[i] && strlen(what) + strlen(names[i]) + 3 < sizeof what; i++) {
        strcat(what, i ? ", " : " ");
        strcat(what, names[i]);
    }
    return bad(flag, what, s);
}

const char *cli_value(int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        fprintf(stderr, "pathlab: %s needs a value (see pathlab help)\n", argv[*i]);
        return NULL;
    }
    return argv[++*i];
}

int cli_double(const char *flag, const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v) || v < lo || v > hi) {
        char what[96];
        sprintf(what, "a number from %g to %g", lo, hi);
        return bad(flag, what, s);
    }
    *out = v;
    return 0;
}

/* The flag of the tables named f, or NULL. */
static const cli_flag *find_flag(const cli_flag *const *tables, const char *f)
{
    int t, k;
    for (t = 0; tables[t]; t++)
        for (k = 0; tables[t][k].name; k++)
            if (!strcmp(tables[t][k].name, f)) return &tables[t][k];
    return NULL;
}

/* Parses value v of flag f into its destination. */
static int parse_value(const cli_flag *f, const char *v, void *ctx)
{
    int i;
    switch (f->kind) {
    case CLI_STRING: *(const char **)f->dest = v; return 0;
    case CLI_INT: return cli_int(f->name, v, (int)f->lo, (int)f->hi, (int *)f->dest);
    case CLI_U64: return cli_u64(f->name, v, (uint64_t *)f->dest);
    case CLI_FLOAT: return cli_float(f->name, v, (float *)f->dest);
    case CLI_DOUBLE: return cli_double(f->name, v, f->lo, f->hi, (double *)f->dest);
    case CLI_VEC3: return cli_vec3(f->name, v, (vec3 *)f->dest);
    case CLI_SIZE: return cli_size(f->name, v, (int *)f->dest, (int *)f->dest + 1);
    case CLI_CHOICE: return cli_choice(f->name, v, f->choices, &i) || (*(int *)f->dest = i, 0);
    case CLI_CUSTOM: return f->custom(ctx, f->name, v);
    default: return 1;
    }
}

int cli_parse(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
              const char **words, int max_words, int *nwords)
{
    int i;
    *nwords = 0;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        const cli_flag *f;
        if (a[0] != '-' || !a[1]) {
            if (*nwords == max_words) {
                fprintf(stderr, "pathlab %s: unexpected '%s' (see pathlab help)\n", cmd, a);
                return 1;
            }
            words[(*nwords)++] = a;
            continue;
        }
        if (!(f = find_flag(tables, a))) {
            fprintf(stderr, "pathlab %s: unknown flag '%s' (see pathlab help)\n", cmd, a);
            return 1;
        }
        if (f->given) *f->given = 1;
        if (f->kind == CLI_SWITCH) { *(int *)f->dest = 1; continue; }
        if (!(v = cli_value(argc, argv, &i)) || parse_value(f, v, ctx)) return 1;
    }
    return 0;
}

/* The flags of pathlab render. */

static int parse_bounces(const char *flag, const char *s, integrator_opts *io)
{
    const char *colon = strchr(s, ':');
    char first[32];
    if (!colon || colon - s >= (long)sizeof first) {
        fprintf(stderr, "pathlab: %s expects A:B (e.g. 0:1, 2:inf), got '%s'\n", flag, s);
        return 1;
    }
    memcpy(first, s, (size_t)(colon - s));
    first[colon - s] = '\0';
    if (cli_int(flag, first, 0, 1000, &io->bmin)) return 1;
    if (!strcmp(colon + 1, "inf")) io->bmax = BOUNCES_INF;
    else if (cli_int(flag, colon + 1, 0, 1000, &io->bmax)) return 1;
    if (io->bmax < io->bmin) {
        fprintf(stderr, "pathlab: %s A:B needs A <= B, got '%s'\n", flag, s);
        return 1;
    }
    return 0;
}

int render_parse_flag(render_args *a, int argc, char **argv, int *i)
{
    const char *f = argv[*i], *v;
    integrator_opts *io = &a->ro.io;
    int choice;
    if (!strcmp(f, "--quiet")) { a->ro.quiet = 1; return 0; }
    if (!strcmp(f, "--pixel-center")) { a->ro.pixel_center = 1; return 0; }
    if (!strcmp(f, "--split")) { io->split = 1; return 0; }
    if (f[0] != '-') {
        if (a->scene) { fprintf(stderr, "pathlab: one scene only, got '%s' and '%s'\n", a->scene, f); return 1; }
        a->scene = f;
        return 0;
    }
    if (!(v = cli_value(argc, argv, i))) return 1;
    if (!strcmp(f, "-o")) { a->out = v; return 0; }
    if (!strcmp(f, "--variance")) { a->variance = v; return 0; }
    if (!strcmp(f, "--spp")) return cli_int(f, v, 1, 1 << 30, &a->ro.spp);
    if (!strcmp(f, "--seed")) return cli_u64(f, v, &a->ro.seed);
    if (!strcmp(f, "--threads")) return cli_int(f, v, 1, 256, &a->ro.threads);
    if (!strcmp(f, "--exposure")) return cli_float(f, v, &a->exposure);
    if (!strcmp(f, "--eye")) return a->eye = 1, cli_vec3(f, v, &a->flags.eye);
    if (!strcmp(f, "--target")) return a->target = 1, cli_vec3(f, v, &a->flags.target);
    if (!strcmp(f, "--up")) return a->up = 1, cli_vec3(f, v, &a->flags.up);
    if (!strcmp(f, "--fov")) return a->fov = 1, cli_float(f, v, &a->flags.fov);
    if (!strcmp(f, "--size")) return a->size = 1, cli_size(f, v, &a->flags.width, &a->flags.height);
    if (!strcmp(f, "--bounces")) return parse_bounces(f, v, io);
    if (!strcmp(f, "--bounce")) return cli_int(f, v, 0, 1000, &io->bmin) || (io->bmax = io->bmin, 0);
    if (!strcmp(f, "--rr")) return !strcmp(v, "off") ? (io->rr_depth = -1, 0) : cli_int(f, v, 0, 1000, &io->rr_depth);
    if (!strcmp(f, "--light")) return cli_choice(f, v, LIGHT_STRATEGY_NAMES, &choice) || (io->light = (light_strategy)choice, 0);
    if (!strcmp(f, "--dir")) return cli_choice(f, v, DIR_STRATEGY_NAMES, &choice) || (io->dir = (dir_strategy)choice, 0);
    if (!strcmp(f, "--direct")) return cli_choice(f, v, DIRECT_STRATEGY_NAMES, &choice) || (io->direct = (direct_strategy)choice, 0);
    fprintf(stderr, "pathlab: unknown flag '%s' (see pathlab help)\n", f);
    return 1;
}

void render_args_init(render_args *a)
{
    memset(a, 0, sizeof *a);
    a->ro.spp = 16;
    a->ro.seed = 1;
    a->ro.threads = (int)sysconf(_SC_NPROCESSORS_ONLN);
    a->ro.io.light = LIGHT_AREA;
    a->ro.io.dir = DIR_BRDF;
    a->ro.io.direct = DIRECT_MIS_POWER;
    a->ro.io.bmin = 0;
    a->ro.io.bmax = BOUNCES_INF;
    a->ro.io.rr_depth = 3;
}

const char *path_extension(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    return dot && (!slash || dot > slash) ? dot : "";
}

int render_make_camera(render_args *a, const scene *s, camera *cam)
{
    char path[4096];
    size_t n = strlen(a->scene) - strlen(path_extension(a->scene));
    vec3 lo, hi;
    view_defaults(&a->vw);
    if (n + 6 < sizeof path) {
        memcpy(path, a->scene, n);
        strcpy(path + n, ".view");
        if (view_read(&a->vw, path) > 0) return 1;
    }
    if (a->eye) { a->vw.eye = a->flags.eye; a->vw.has_eye = 1; }
    if (a->target) { a->vw.target = a->flags.target; a->vw.has_target = 1; }
    if (a->up) a->vw.up = a->flags.up;
    if (a->fov) a->vw.fov = a->flags.fov;
    if (a->size) { a->vw.width = a->flags.width; a->vw.height = a->flags.height; }
    mesh_bounds(&s->m, &lo, &hi);
    view_frame_bounds(&a->vw, lo, hi);
    return camera_init(cam, &a->vw);
}
