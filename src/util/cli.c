/* cli.c — a command's flags as a table, and strict parsing of their values.
 * Each kind of value has one reader (int_of, float_of...) that stores the value and returns NULL,
 * or returns what it expected; the callers print that, with the command, flag and value. */
#include "util/cli.h"
#include "sys/shown.h"
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define WHAT 256   /* room for the description of an expected value */

/* ---- the readers: NULL when s was stored in *out, else what was expected (written in what[WHAT]) ---- */

static const char *int_of(const char *s, int lo, int hi, int *out, char *what)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end != s && !*end && !errno && v >= lo && v <= hi) { *out = (int)v; return NULL; }
    sprintf(what, "a whole number from %d to %d", lo, hi);
    return what;
}

static const char *u64_of(const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (!isdigit((unsigned char)s[0]) || *end || errno) return "a whole number >= 0";
    *out = (uint64_t)v;
    return NULL;
}

static const char *double_of(const char *s, double lo, double hi, double *out, char *what)
{
    char *end;
    double v = strtod(s, &end);
    if (end != s && !*end && isfinite(v) && v >= lo && v <= hi) { *out = v; return NULL; }
    sprintf(what, "a number from %g to %g", lo, hi);
    return what;
}

static const char *float_of(const char *s, float *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end) return "a number";
    if (isnan(v)) return "a number, not nan";
    if (!(fabs(v) <= FLT_MAX)) return "a number between -3.4e38 and 3.4e38";   /* not inf or beyond a float */
    *out = (float)v;
    return NULL;
}

static const char *vec3_of(const char *s, vec3 *out)
{
    double v[3];
    char *end;
    const char *p = s;
    int i;
    for (i = 0; i < 3; i++) {
        v[i] = strtod(p, &end);
        if (end == p || !isfinite(v[i]) || *end != (i < 2 ? ',' : '\0')) return "three numbers x,y,z";
        p = end + 1;
    }
    *out = v3((float)v[0], (float)v[1], (float)v[2]);
    return NULL;
}

static const char *size_of(const char *s, int *w, int *h)
{
    char *end;
    const char *p;
    long a, b;
    a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X')) return "WIDTHxHEIGHT, e.g. 512x512";
    p = end + 1;
    b = strtol(p, &end, 10);
    if (end == p || *end || a < 1 || b < 1 || a > 65536 || b > 65536) return "WIDTHxHEIGHT, each from 1 to 65536";
    *w = (int)a;
    *h = (int)b;
    return NULL;
}

/* The index of s in names, or -1. */
static int choice_of(const char *s, const char *const *names)
{
    int i;
    for (i = 0; names[i]; i++)
        if (!strcmp(s, names[i])) return i;
    return -1;
}

/* ---- messages ---- */

/* "pathlab CMD: ", or "pathlab: " without a command. */
static void say_who(const char *cmd)
{
    if (cmd) fprintf(stderr, "pathlab %s: ", cmd);
    else fputs("pathlab: ", stderr);
}

int cli_fail(const char *cmd, const char *flag, const char *what, const char *value)
{
    say_who(cmd);
    fprintf(stderr, "%s expects %s, got '%s'\n", shown(flag), what, shown(value));
    return 1;
}

/* ---- a table of flags ---- */

static const cli_flag *find_flag(const cli_flag *const *tables, const char *f, size_t len);
static FILE *list_to;   /* cli_list_flags: where the tables are listed instead of parsed, or NULL */

void cli_list_flags(FILE *f)
{
    list_to = f;
}

int cli_listing(void)
{
    return list_to != NULL;
}

/* Each flag of the tables on a line of list_to, its values after it if it takes one of a list; 1. */
static int list_tables(const cli_flag *const *tables)
{
    int t, k, j;
    for (t = 0; tables[t]; t++)
        for (k = 0; tables[t][k].name; k++) {
            if (find_flag(tables, tables[t][k].name, strlen(tables[t][k].name)) != &tables[t][k]) continue;   /* listed */
            fputs(tables[t][k].name, list_to);
            for (j = 0; tables[t][k].choices && tables[t][k].choices[j]; j++) fprintf(list_to, " %s", tables[t][k].choices[j]);
            fputc('\n', list_to);
        }
    return 1;
}

int cli_is_word(const char *arg)
{
    return arg[0] != '-' || !arg[1];
}

int cli_parse_value(const char *cmd, const cli_flag *f, const char *v, void *ctx)
{
    char what[WHAT];
    const char *e = NULL;
    switch (f->kind) {
    case CLI_SWITCH: *(int *)f->dest = 1; break;
    case CLI_STRING: *(const char **)f->dest = v; break;
    case CLI_INT: e = int_of(v, (int)f->lo, (int)f->hi, (int *)f->dest, what); break;
    case CLI_U64: e = u64_of(v, (uint64_t *)f->dest); break;
    case CLI_FLOAT: e = float_of(v, (float *)f->dest); break;
    case CLI_DOUBLE: e = double_of(v, f->lo, f->hi, (double *)f->dest, what); break;
    case CLI_VEC3: e = vec3_of(v, (vec3 *)f->dest); break;
    case CLI_SIZE: e = size_of(v, (int *)f->dest, (int *)f->dest + 1); break;
    case CLI_CHOICE:
        if (choice_of(v, f->choices) < 0) return cli_fail_choice(cmd, f->name, v, f->choices);
        *(int *)f->dest = choice_of(v, f->choices);
        break;
    case CLI_CUSTOM: return f->custom(ctx, f->name, v);
    }
    return e ? cli_fail(cmd, f->name, e, v) : 0;
}

/* ---- did you mean: the closest name by edit distance ---- */

/* The edit distance of a and b (insert, delete, substitute, swap two neighbours). */
static int cli_distance(const char *a, const char *b)
{
    /* optimal string alignment: insertions, deletions, substitutions and swaps of two neighbours
     * ("rendr", "--sp", "--sapmler"); three rows suffice, the words are cut at 63 characters */
    int row[3][64], la = (int)strlen(a), lb = (int)strlen(b), i, j;
    if (la > 63) la = 63;
    if (lb > 63) lb = 63;
    for (j = 0; j <= lb; j++) row[0][j] = j;
    for (i = 1; i <= la; i++) {
        int *r = row[i % 3], *p = row[(i - 1) % 3], *pp = row[(i + 1) % 3];
        r[0] = i;
        for (j = 1; j <= lb; j++) {
            int cost = a[i - 1] != b[j - 1], d = p[j - 1] + cost;
            if (p[j] + 1 < d) d = p[j] + 1;
            if (r[j - 1] + 1 < d) d = r[j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && pp[j - 2] + 1 < d) d = pp[j - 2] + 1;
            r[j] = d;
        }
    }
    return row[la % 3][lb];
}

void cli_consider(const char *word, const char *name, const char **best, int *best_d)
{
    const char *w = word, *n = name;
    int d, len;
    while (*w == '-') w++;   /* --sp against --spp: the dashes are not part of the typo */
    while (*n == '-') n++;
    len = (int)strlen(n);
    d = cli_distance(w, n);
    if (strlen(w) >= 2 && !strncmp(n, w, strlen(w))) d = 1;   /* a prefix: --var for --variance */
    /* close enough to be what was meant: one edit in a short name, two in a name of 6 or more, or
     * the name and a few more letters (--reference for --ref, --alphas for --alpha) */
    if (len >= 3 && (int)strlen(w) > len && (int)strlen(w) <= len + 7 && !strncmp(w, n, (size_t)len)) d = 2;
    else if (d > (len >= 6 ? 2 : 1) || d >= len) return;
    if (!*best || d < *best_d) { *best = name; *best_d = d; }
}

int cli_fail_choice(const char *cmd, const char *flag, const char *value, const char *const *names)
{
    char what[WHAT];
    const char *best = NULL;
    size_t n;
    int i, d = 0;
    for (i = 0; names[i]; i++) cli_consider(value, names[i], &best, &d);
    snprintf(what, sizeof what, "one of");
    for (i = 0; names[i] && (n = strlen(what)) + strlen(names[i]) + 3 < sizeof what; i++)
        snprintf(what + n, sizeof what - n, "%s%s", i ? ", " : " ", names[i]);
    say_who(cmd);
    fprintf(stderr, "%s expects %s, got '%.200s'", flag, what, value);
    if (best) fprintf(stderr, "; did you mean %s?", best);
    fputc('\n', stderr);
    return 1;
}

/* The flag of the tables named by f, the first `len` characters of it, or NULL. */
static const cli_flag *find_flag(const cli_flag *const *tables, const char *f, size_t len)
{
    int t, k;
    for (t = 0; tables[t]; t++)
        for (k = 0; tables[t][k].name; k++)
            if (strlen(tables[t][k].name) == len && !strncmp(tables[t][k].name, f, len)) return &tables[t][k];
    return NULL;
}

/* "unknown flag", with the closest flag of the tables if one is close enough; returns 1. */
static int unknown_flag(const char *cmd, const cli_flag *const *tables, const char *arg, size_t len)
{
    const char *best = NULL;
    char word[64], said[201];
    int t, k, d = 0;
    snprintf(word, sizeof word, "%.*s", (int)(len < sizeof word ? len : sizeof word - 1), arg);
    for (t = 0; tables[t]; t++)
        for (k = 0; tables[t][k].name; k++) cli_consider(word, tables[t][k].name, &best, &d);
    say_who(cmd);
    snprintf(said, sizeof said, "%.*s", (int)(len > 200 ? 200 : len), arg);
    fprintf(stderr, "unknown flag '%s'", shown(said));
    if (best) fprintf(stderr, "; did you mean '%s'?", shown(best));
    if (access(arg, F_OK) == 0) fprintf(stderr, "; a file of that name: write ./%s, or put it after --", shown(arg));
    else fprintf(stderr, " (pathlab %s --help lists its flags)", cmd ? cmd : "help");
    putc('\n', stderr);
    return 1;
}

/* The length of the flag's name in arg: up to the '=' of --flag=value, else all of it. */
static size_t cli_flag_length(const char *arg)
{
    const char *eq = strchr(arg, '=');
    return arg[0] == '-' && arg[1] == '-' && eq ? (size_t)(eq - arg) : strlen(arg);
}

int cli_flag_is(const char *arg, const char *name)
{
    size_t n = cli_flag_length(arg);
    return n == strlen(name) && !strncmp(arg, name, n);
}

int cli_parse_flag(const char *cmd, int argc, char **argv, int *i, const cli_flag *const *tables, void *ctx)
{
    const char *arg = argv[*i];
    size_t len = cli_flag_length(arg);
    const cli_flag *f = find_flag(tables, arg, len);
    if (list_to) return list_tables(tables);
    if (!f) return unknown_flag(cmd, tables, arg, len);
    if (f->given) *f->given = 1;
    if (arg[len] == '=') {   /* --flag=value, the same as --flag value */
        if (f->kind != CLI_SWITCH) return cli_parse_value(cmd, f, arg + len + 1, ctx);
        say_who(cmd);
        fprintf(stderr, "%s takes no value, got '%s'\n", f->name, shown(arg));
        return 1;
    }
    if (f->kind == CLI_SWITCH) return cli_parse_value(cmd, f, NULL, ctx);
    if (*i + 1 >= argc) {
        say_who(cmd);
        fprintf(stderr, "%s needs a value (see pathlab %s --help)\n", f->name, cmd ? cmd : "help");
        return 1;
    }
    return cli_parse_value(cmd, f, argv[++*i], ctx);
}

/* 1 after saying so if flag f was given before (its name among seen[0..n-1]): the last one would
 * silently win, and a student's file named --ref=x.pfm, expanded by the shell's *.pfm, would
 * replace the teacher's reference. */
static int given_twice(const char *cmd, const cli_flag *f, const char *const *seen, int n, const char *arg)
{
    int k;
    for (k = 0; k < n && strcmp(seen[k], f->name); k++) continue;
    if (k == n) return 0;
    say_who(cmd);
    fprintf(stderr, "%s given twice (again as '%s'): give it once. A file whose name starts with '-' is read as a flag: put -- "
            "before the file names, or write ./NAME\n", f->name, shown(arg));
    return 1;
}

static int parse_all(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
                     const char **words, int max_words, int *nwords, int once)
{
    const char *seen[64];
    int i, words_only = 0, nseen = 0;
    *nwords = 0;
    if (list_to) return list_tables(tables);
    for (i = 1; i < argc; i++) {
        if (!words_only && !strcmp(argv[i], "--")) { words_only = 1; continue; }   /* then "-x.pfm" is a file */
        if (!words_only && !cli_is_word(argv[i])) {
            const cli_flag *f = find_flag(tables, argv[i], cli_flag_length(argv[i]));
            if (once && f && given_twice(cmd, f, seen, nseen, argv[i])) return 1;
            if (f && nseen < (int)(sizeof seen / sizeof *seen)) seen[nseen++] = f->name;
            if (cli_parse_flag(cmd, argc, argv, &i, tables, ctx)) return 1;
        } else if (*nwords < max_words) {
            words[(*nwords)++] = argv[i];
        } else {
            say_who(cmd);
            if (max_words == 0) fprintf(stderr, "unexpected '%s': %s takes flags only (see pathlab %s --help)\n", shown(argv[i]), cmd ? cmd : "it", cmd ? cmd : "help");
            else fprintf(stderr, "unexpected '%s' after '%s': %s takes at most %d file name%s (see pathlab %s --help)\n",
                         shown(argv[i]), shown(words[max_words - 1]), cmd ? cmd : "it", max_words, max_words > 1 ? "s" : "", cmd ? cmd : "help");
            return 1;
        }
    }
    return 0;
}

int cli_parse(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
              const char **words, int max_words, int *nwords)
{
    return parse_all(cmd, argc, argv, tables, ctx, words, max_words, nwords, 0);
}

int cli_parse_once(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
                   const char **words, int max_words, int *nwords)
{
    return parse_all(cmd, argc, argv, tables, ctx, words, max_words, nwords, 1);
}
