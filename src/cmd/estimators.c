/* estimators.c — the estimator language of pathlab compare: split the list, expand the names
 * into render flags, parse those flags (see estimators.h). */
#include "cmd/estimators.h"
#include "sys/shown.h"
#include <stdio.h>
#include <string.h>
#include "util/cli.h"
#include "tracer/integrator.h"
#include "tracer/light.h"
#include "sampler/sampler.h"

#define MAX_FLAGS 64   /* of one estimator, its names expanded */

/* The names of the strategy tables beside their enums are shorthands: name X means FLAG X. */
typedef struct { const char *flag; const char *const *names; } strategy_table;
static const strategy_table STRATEGIES[] = {
    {"--direct", DIRECT_STRATEGY_NAMES}, {"--dir", DIR_STRATEGY_NAMES}, {"--light", LIGHT_STRATEGY_NAMES},
    {"--sampler", SAMPLER_NAMES}};   /* "sobol": stratification beside importance sampling */
#define NSTRATEGIES (int)(sizeof STRATEGIES / sizeof *STRATEGIES)

/* The shorthand of strategy `name` of table t: the name itself, with one exception: --dir brdf is
 * "dir-brdf", since "brdf" alone is --direct brdf. */
static const char *shorthand(int t, const char *name)
{
    return !strcmp(STRATEGIES[t].flag, "--dir") && !strcmp(name, "brdf") ? "dir-brdf" : name;
}

/* The words of one estimator once its names are expanded, as argv for render_parse_flag (which
 * reads them only: some point to the constant strings of the tables). */
typedef struct {
    const char *label;   /* for messages */
    char *tok[MAX_FLAGS];
    int n;
} flag_list;

static int add_flag(flag_list *f, const char *s)
{
    if (f->n >= MAX_FLAGS) {
        fprintf(stderr, "pathlab: compare: estimator '%s': more than %d flags\n", shown(f->label), MAX_FLAGS);
        return 1;
    }
    f->tok[f->n++] = (char *)s;
    return 0;
}

static void print_names(void)
{
    int t, k;
    for (t = 0; t < NSTRATEGIES; t++) {
        fputs(t ? "        " : "  names:", stderr);
        for (k = 0; STRATEGIES[t].names[k]; k++) fprintf(stderr, " %s", shorthand(t, STRATEGIES[t].names[k]));
        fprintf(stderr, " (%s)%s\n", STRATEGIES[t].flag, t + 1 < NSTRATEGIES ? "," : ";");
    }
    fprintf(stderr, "  or render flags, e.g. \"--direct light --light solid-angle\"\n");
}

/* "; did you mean NAME?" and the end of the line: the name closest to the n characters at w, if one is close. */
static void suggest_name(const char *w, size_t n)
{
    char word[64];
    const char *best = NULL;
    int t, k, d = 0;
    snprintf(word, sizeof word, "%.*s", (int)(n < sizeof word ? n : sizeof word - 1), w);
    for (t = 0; t < NSTRATEGIES; t++)
        for (k = 0; STRATEGIES[t].names[k]; k++) cli_consider(word, shorthand(t, STRATEGIES[t].names[k]), &best, &d);
    if (best) fprintf(stderr, "; did you mean %s?", best);
    fputc('\n', stderr);
}

/* One name (n characters at w) -> its flag and its value. */
static int expand_name(flag_list *f, const char *w, size_t n)
{
    int t, k;
    for (t = 0; t < NSTRATEGIES; t++)
        for (k = 0; STRATEGIES[t].names[k]; k++) {
            const char *name = STRATEGIES[t].names[k], *word = shorthand(t, name);
            if (strlen(word) == n && !strncmp(word, w, n)) return add_flag(f, STRATEGIES[t].flag) || add_flag(f, name);
        }
    fprintf(stderr, "pathlab: compare: estimator '%s': unknown name '%.*s'", shown(f->label), (int)n, w);
    suggest_name(w, n);
    print_names();
    return 1;
}

static int takes_value(const char *flag)
{
    return strcmp(flag, "--quiet") && strcmp(flag, "--pixel-center") && strcmp(flag, "--split");
}

/* Splits text (modified: words end with '\0') into flags, flag values and names joined with '+'. */
static int expand_words(flag_list *f, char *text)
{
    char *p = text, *end;
    int after_flag = 0;
    while (*(p += strspn(p, " \t"))) {
        end = p + strcspn(p, " \t");
        if (*end) *end++ = '\0';
        if (*p == '-' || after_flag) {            /* a flag or a flag's value, as it is */
            if (add_flag(f, p)) return 1;
            after_flag = *p == '-' && !after_flag && takes_value(p);
        } else {                                  /* names joined with '+' */
            while (*p) {
                size_t m = strcspn(p, "+");
                if (expand_name(f, p, m)) return 1;
                p += m + (p[m] == '+');
            }
        }
        p = end;
    }
    return 0;
}

static void trim(char *s)
{
    size_t n = strlen(s), i = 0;
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) s[--n] = '\0';
    while (s[i] == ' ' || s[i] == '\t') i++;
    memmove(s, s + i, n - i + 1);
}

/* "LABEL=FLAGS": moves LABEL out of text into e->label; without '=', the label is the text. */
static int split_label(estimator_spec *e, char *text, const char *item, size_t len)
{
    char *eq = strchr(text, '=');
    if (eq) {
        *eq = '\0';
        snprintf(e->label, sizeof e->label, "%s", text);
        trim(e->label);
        memmove(text, eq + 1, strlen(eq + 1) + 1);
        trim(text);
        if (!e->label[0]) { fprintf(stderr, "pathlab: compare: empty label before '=' in '%.*s'\n", (int)len, item); return 1; }
        if (strstr(e->label, "--")) {   /* "light --direct=brdf" was the label "light --direct" for --direct brdf */
            fprintf(stderr, "pathlab: compare: '%s' before '=' holds a flag: an estimator is LABEL=FLAGS, cut at its first '=' "
                    "(write --flag value, not --flag=value)\n", shown(e->label));
            return 1;
        }
    } else {
        snprintf(e->label, sizeof e->label, "%s", text);
    }
    if (!text[0]) { fprintf(stderr, "pathlab: compare: an empty estimator in --estimators (two commas, or nothing after '=')\n"); return 1; }
    return 0;
}

/* The slug: lower-case letters and digits of the label, other runs become one '-'. */
static int make_slug(estimator_spec *e)
{
    const char *p;
    size_t n = 0;
    for (p = e->label; *p && n + 1 < sizeof e->slug; p++) {
        int c = (unsigned char)*p;
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) e->slug[n++] = (char)c;
        else if (c >= 'A' && c <= 'Z') e->slug[n++] = (char)(c - 'A' + 'a');
        else if (n > 0 && e->slug[n - 1] != '-') e->slug[n++] = '-';
    }
    while (n > 0 && e->slug[n - 1] == '-') n--;
    e->slug[n] = '\0';
    if (!n) { fprintf(stderr, "pathlab: compare: label '%s' has no letter or digit to name its files\n", shown(e->label)); return 1; }
    return 0;
}

/* The flags of the scene, loaded once for all estimators: one estimator's would be ignored. */
static const char *const SCENE_FLAGS[] = {"--mtl", "--sky", "--texture-decode", NULL};

/* 1 (said) if the estimator sets one flag twice: "light+brdf" rendered --direct brdf as "light+brdf". */
static int flag_twice(const estimator_spec *e, const flag_list *f)
{
    int i, j;
    for (i = 0; i < f->n; i++)
        for (j = 0; j < i; j++) {
            size_t n = strcspn(f->tok[i], "=");   /* --direct=brdf sets --direct too */
            if (!strncmp(f->tok[i], "--", 2) && n == strcspn(f->tok[j], "=") && !strncmp(f->tok[i], f->tok[j], n)) {
                fprintf(stderr, "pathlab: compare: estimator '%s' sets %.*s twice (by its names or flags): which one?\n",
                        shown(e->label), (int)n, shown(f->tok[i]));
                return 1;
            }
        }
    return 0;
}

/* e->a: the shared flags of base, then the estimator's own, which win. */
static int apply_flags(estimator_spec *e, const flag_list *f, const render_args *base)
{
    int i, k;
    if (flag_twice(e, f)) return 1;
    e->a = *base;
    e->a.scene = e->a.out = e->a.variance = NULL;
    e->a.spp_given = 0;
    for (i = 0; i < f->n; i++) {
        for (k = 0; SCENE_FLAGS[k] && !cli_flag_is(f->tok[i], SCENE_FLAGS[k]); k++) continue;
        if (SCENE_FLAGS[k]) {
            fprintf(stderr, "pathlab: compare: estimator '%s': %s is for the scene, which all estimators share: give it "
                    "to compare, outside --estimators\n", shown(e->label), SCENE_FLAGS[k]);
            return 1;
        }
        if (render_parse_flag(&e->a, f->n, (char **)f->tok, &i)) {
            fprintf(stderr, "pathlab: compare: in estimator '%s'\n", shown(e->label));
            return 1;
        }
    }
    /* --time, --samples, --resume and adaptive sampling would change its samples under the table's
     * and the sidecar's feet (an estimator's --time rendered a third of the spp said) */
    if (e->a.scene || e->a.out || e->a.variance || e->a.ro.split || e->a.spp_given || e->a.ro.time_limit > 0.0 ||
        e->a.samples_given || e->a.resume || e->a.adaptive || e->a.target_given || e->a.sample_count) {
        fprintf(stderr, "pathlab: compare: estimator '%s': %s\n", shown(e->label),
                e->a.scene ? "a word that is neither a flag, a flag's value nor a name" :
                e->a.spp_given || e->a.ro.time_limit > 0.0 ? "--spp and --time are set for all estimators (--spp or --time of compare), not for one" :
                e->a.samples_given || e->a.resume ? "--samples and --resume are not for compare: each estimator renders its samples from 0" :
                e->a.adaptive || e->a.target_given || e->a.sample_count ? "adaptive sampling is not for compare: every pixel of an estimator gets its spp" :
                "-o, --variance and --split are not for an estimator");
        return 1;
    }
    e->a.scene = base->scene;
    e->a.ro.quiet = 1;
    e->a.ro.io.rr_below = render_rr_below(e->a.ro.io.rr_below, e->a.ro.sampler);   /* resolved once, for its sampler */
    return 0;
}

/* One estimator, the len characters at item: its label, slug, flags and render_args. */
static int parse_one(estimator_spec *e, const char *item, size_t len, const render_args *base)
{
    char *text = e->words;   /* not a local array: the string flags' values (--write-view F) point into it */
    flag_list f;
    int k;
    if (len >= sizeof e->words) { fprintf(stderr, "pathlab: compare: estimator '%.40s...' is too long\n", item); return 1; }
    memcpy(text, item, len);
    text[len] = '\0';
    trim(text);
    f.label = e->label;
    f.n = 0;
    if (split_label(e, text, item, len) || expand_words(&f, text) || make_slug(e)) return 1;
    e->flags[0] = '\0';
    for (k = 0; k < f.n; k++) {
        size_t used = strlen(e->flags);
        snprintf(e->flags + used, sizeof e->flags - used, "%s%s", k ? " " : "", f.tok[k]);
    }
    return apply_flags(e, &f, base);
}

/* A comma ends an estimator unless a number follows it (--eye 0,1,5 or --up 0,-1,0). */
static int splits_here(const char *s)
{
    return s[0] == ',' && !(s[1] >= '0' && s[1] <= '9') && s[1] != '.'
           && !(s[1] == '-' && ((s[2] >= '0' && s[2] <= '9') || s[2] == '.'));
}

int estimators_parse(const char *list, const render_args *base, estimator_spec *est, int max, int *n)
{
    const char *s = list;
    *n = 0;
    if (!*s) { fprintf(stderr, "pathlab: compare: --estimators is empty\n"); return 1; }
    while (*s) {
        size_t len = 0;
        while (s[len] && !splits_here(s + len)) len++;
        if (*n == max) { fprintf(stderr, "pathlab: compare: at most %d estimators\n", max); return 1; }
        if (parse_one(&est[(*n)++], s, len, base)) return 1;
        s += len + (s[len] == ',');
        if (s[-1] == ',' && !*s) { fprintf(stderr, "pathlab: compare: --estimators ends with a comma\n"); return 1; }
    }
    return 0;
}
