/* render_resume.c — the command line of render --resume completed from the sidecar, and checked
 * against it (render_resume.h). A sidecar's flags and camera are "NAME VALUE" words: the flags in
 * render's canonical form (--rr 3 --pixel-center ...), the camera as "eye X target Y up Z fov F size WxH". */
#include "cmd/render_resume.h"
#include <stdio.h>
#include <string.h>
#include "cmd/render_adaptive.h"

static const char *const CAMERA_KEYS[] = {"eye", "target", "up", "fov", "size", NULL};
static const char *const CAMERA_FLAGS[] = {"--eye", "--target", "--up", "--fov", "--size", NULL};

/* The flag of render's tables named by arg (alone or as --flag=value), or NULL. */
static const cli_flag *render_flag(const cli_flag *t, const cli_flag *ta, const char *arg)
{
    int k;
    for (k = 0; t[k].name; k++)
        if (cli_flag_is(arg, t[k].name)) return &t[k];
    for (k = 0; ta[k].name; k++)
        if (cli_flag_is(arg, ta[k].name)) return &ta[k];
    return NULL;
}

/* The flags argv gives (names into given[], at most max) and the number of words; -o's value in *out. */
static int scan_args(int argc, char **argv, const cli_flag *t, const cli_flag *ta, const char **given, int max, int *nwords,
                     const char **out)
{
    int i, n = 0;
    *nwords = 0, *out = NULL;
    for (i = 1; i < argc; i++) {
        const cli_flag *f = cli_is_word(argv[i]) ? NULL : render_flag(t, ta, argv[i]);
        if (cli_is_word(argv[i])) { (*nwords)++; continue; }
        if (!f) continue;   /* an unknown flag: the parse says so */
        if (n < max) given[n++] = f->name;
        if (f->kind == CLI_SWITCH || strchr(argv[i], '=')) continue;
        if (!strcmp(f->name, "-o") && i + 1 < argc) *out = argv[i + 1];
        i++;
    }
    return n;
}

static int is_given(const char *const *given, int n, const char *name)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(given[i], name)) return 1;
    return 0;
}

/* Adds word to out[*n]; 1 if there is no room. */
static int push(char **out, int *n, char *word)
{
    if (*n >= RESUME_MAX_ARGS - 1) return 1;
    out[(*n)++] = word;
    return 0;
}

/* The flags a render writes in its sidecar's flags line (files/render_meta.c): the only ones replayed.
 * Any other there (--write-view, --variance, -o ...) did not come from pathlab: a sidecar must not
 * decide where a render writes. */
static const char *const SIDECAR_FLAGS[] = {"--bounces", "--light", "--dir", "--direct", "--rr", "--rr-below",
    "--pixel-offset", "--pixel-center", "--sampler", "--sky", "--material", "--normals", "--texture-filter",
    "--texture-decode", "--mtl", NULL};

static int sidecar_flag(const char *name)
{
    int k;
    for (k = 0; SIDECAR_FLAGS[k] && strcmp(SIDECAR_FLAGS[k], name); k++) continue;
    return SIDECAR_FLAGS[k] != NULL;
}

/* The sidecar's flags (words of text, split in place) that argv does not give, pushed to out; 1 if
 * there is no room, 2 (said) for a flag a render does not write there. */
static int push_flags(char *text, const cli_flag *t, const cli_flag *ta, const char *const *given, int ng, char **out, int *n,
                      const char *file)
{
    char *w = strtok(text, " ");
    while (w) {
        const cli_flag *f = render_flag(t, ta, w);
        char *v = f && f->kind != CLI_SWITCH ? strtok(NULL, " ") : NULL;
        int skip = !f || is_given(given, ng, f->name)
                   || (!strcmp(f->name, "--bounces") && is_given(given, ng, "--bounce"));
        if (v && sidecar_unescape(v)) {   /* a path of --sky or --mtl, written escaped */
            fprintf(stderr, "pathlab render: --resume: %s.meta: its flags line has a badly escaped value after %s: the "
                    "sidecar was edited; nothing written\n", file, f->name);
            return 2;
        }
        if (f && !sidecar_flag(f->name)) {
            fprintf(stderr, "pathlab render: --resume: %s.meta: its flags line has %s, which a render does not write "
                    "there: the sidecar was edited; nothing written\n", file, f->name);
            return 2;
        }
        if (!skip && (push(out, n, w) || (v && push(out, n, v)))) return 1;
        w = strtok(NULL, " ");
    }
    return 0;
}

/* The sidecar's camera as flags, unless argv gives a camera file or that flag. */
static int push_camera(char *text, const char *const *given, int ng, char **out, int *n)
{
    char *w = strtok(text, " ");
    int k;
    if (is_given(given, ng, "--view") || is_given(given, ng, "--orbiter")) return 0;
    while (w) {
        char *v = strtok(NULL, " ");
        for (k = 0; CAMERA_KEYS[k] && strcmp(CAMERA_KEYS[k], w); k++) continue;
        if (v && CAMERA_KEYS[k] && !is_given(given, ng, CAMERA_FLAGS[k]) && (push(out, n, (char *)CAMERA_FLAGS[k]) || push(out, n, v)))
            return 1;
        w = strtok(NULL, " ");
    }
    return 0;
}

int render_resume_args(int argc, char **argv, char **out, int *out_argc, char *text, size_t cap)
{
    render_args scratch;
    cli_flag t[RENDER_NFLAGS], ta[RENDER_ADAPTIVE_NFLAGS];
    const char *given[RESUME_MAX_ARGS], *file;
    sidecar m;
    int ng, nwords, n = 0, i, err = 0, bad = 0;
    size_t used;
    render_args_init(&scratch);
    render_flag_table(&scratch, t);
    render_adaptive_flag_table(&scratch, ta);
    ng = scan_args(argc, argv, t, ta, given, RESUME_MAX_ARGS, &nwords, &file);
    *out_argc = argc;
    for (i = 0; i < argc && i < RESUME_MAX_ARGS; i++) out[i] = argv[i];
    if (!is_given(given, ng, "--resume") || !file || argc >= RESUME_MAX_ARGS) return 0;
    if ((bad = sidecar_read(&m, file)) > 0) return 1;   /* malformed, said (going on added "needs a scene") */
    if (bad < 0) return 0;   /* none: the resume's own check says so */
    /* the sidecar's words, split in place in text: scene, seed, flags, camera */
    used = (size_t)snprintf(text, cap, "%s", m.scene) + 1;
    out[n++] = argv[0];
    if (!nwords && used < cap) err = push(out, &n, text);
    if (!is_given(given, ng, "--seed") && used + 24 < cap) {
        snprintf(text + used, cap - used, "%llu", (unsigned long long)m.seed);
        err = err || push(out, &n, "--seed") || push(out, &n, text + used);
        used += strlen(text + used) + 1;
    }
    if (used < cap) snprintf(text + used, cap - used, "%s", m.flags);
    err = err || (used < cap && (bad = push_flags(text + used, t, ta, given, ng, out, &n, file)) != 0);
    if (bad == 2) return 1;
    used += strlen(m.flags) + 1;
    if (used < cap) snprintf(text + used, cap - used, "%s", m.camera);
    err = err || (used < cap && push_camera(text + used, given, ng, out, &n));
    if (m.layers_n > 0 && !is_given(given, ng, "--split")) err = err || push(out, &n, "--split");
    for (i = 1; i < argc && !err; i++) err = push(out, &n, argv[i]);
    if (err) { fprintf(stderr, "pathlab render: --resume: too many arguments with those of %s's sidecar\n", file); return 1; }
    out[n] = NULL;
    *out_argc = n;
    return 0;
}

/* ---- the check: the first flag whose value differs ---- */

#define MAX_PAIRS 48
typedef struct { char key[64], val[128]; } pair;

/* words "--a 1 --b --c 2" (flags: a key without a value is "(given)") or "eye X target Y" (camera:
 * every key has a value, and its flag is --KEY) as pairs; their number. */
static int pairs_of(const char *words, int camera, pair *p)
{
    int n = 0;
    size_t len;
    while (*(words += strspn(words, " ")) && n < MAX_PAIRS) {
        len = strcspn(words, " ");
        snprintf(p[n].key, sizeof p[n].key, "%s%.*s", camera ? "--" : "", (int)(len < 60 ? len : 60), words);
        words += len;
        words += strspn(words, " ");
        len = strcspn(words, " ");
        if (*words && (camera || strncmp(words, "--", 2))) {
            snprintf(p[n].val, sizeof p[n].val, "%.*s", (int)(len < 120 ? len : 120), words);
            words += len;
        } else snprintf(p[n].val, sizeof p[n].val, "(given)");
        n++;
    }
    return n;
}

static const char *value_in(const pair *p, int n, const char *key)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(p[i].key, key)) return p[i].val;
    return "(not given)";
}

static int differ(const char *flag, const char *here, const char *there, const char *file)
{
    fprintf(stderr, "pathlab render: --resume: %s is %s on the command line but %s in %s's sidecar: leave %s out to "
                    "resume with the sidecar's, or render a new file\n", flag, here, there, file, flag);
    return 1;
}

/* The first key of a or b whose values differ, said; 1 then, else 0. */
static int first_difference(const char *a, const char *b, int camera, const char *file)
{
    pair pa[MAX_PAIRS], pb[MAX_PAIRS];
    int na = pairs_of(a, camera, pa), nb = pairs_of(b, camera, pb), i;
    for (i = 0; i < na; i++)
        if (strcmp(pa[i].val, value_in(pb, nb, pa[i].key))) return differ(pa[i].key, pa[i].val, value_in(pb, nb, pa[i].key), file);
    for (i = 0; i < nb; i++)
        if (strcmp(pb[i].val, value_in(pa, na, pb[i].key))) return differ(pb[i].key, value_in(pa, na, pb[i].key), pb[i].val, file);
    return 0;
}

int render_resume_check(const sidecar *now, const sidecar *had, const char *file)
{
    char a[32], b[32];
    if (first_difference(now->flags, had->flags, 0, file) || first_difference(now->camera, had->camera, 1, file)) return 1;
    if (now->seed == had->seed) return 0;
    snprintf(a, sizeof a, "%llu", (unsigned long long)now->seed);
    snprintf(b, sizeof b, "%llu", (unsigned long long)had->seed);
    return differ("--seed", a, b, file);
}
