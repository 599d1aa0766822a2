/* test_cli.c — util/cli: cli_parse over a table with every kind of flag (values, ranges, flags and
 * words in any order, "-" as a word, negative numbers as values, custom flags, the first table
 * wins), its errors (unknown flag, missing value, one word too many, bad value: status 1 and a
 * message naming the command, the flag and the value), the value parsers on their edge cases, and
 * render's flags (cmd/render_args) as compare uses them, one at a time. stderr is captured. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "cmd/render_args.h"
#include "util/cli.h"

/* One value through cli_parse_value, as a flag of kind `kind` named `flag` (no command: the
 * message starts "pathlab: "). */
static int one_value(cli_kind kind, const char *flag, const char *s, double lo, double hi, const char *const *names, void *out)
{
    cli_flag f = {NULL, CLI_INT, NULL, 0, 0, NULL, NULL, NULL};
    f.name = flag, f.kind = kind, f.dest = out, f.lo = lo, f.hi = hi, f.choices = names;
    return cli_parse_value(NULL, &f, s, NULL);
}
static int cli_int(const char *flag, const char *s, int lo, int hi, int *out) { return one_value(CLI_INT, flag, s, lo, hi, NULL, out); }
static int cli_u64(const char *flag, const char *s, uint64_t *out) { return one_value(CLI_U64, flag, s, 0, 0, NULL, out); }
static int cli_float(const char *flag, const char *s, float *out) { return one_value(CLI_FLOAT, flag, s, 0, 0, NULL, out); }
static int cli_double(const char *flag, const char *s, double lo, double hi, double *out) { return one_value(CLI_DOUBLE, flag, s, lo, hi, NULL, out); }
static int cli_vec3(const char *flag, const char *s, vec3 *out) { return one_value(CLI_VEC3, flag, s, 0, 0, NULL, out); }
static int cli_size(const char *flag, const char *s, int *w, int *h)
{
    int wh[2] = {0, 0}, rc = one_value(CLI_SIZE, flag, s, 0, 0, NULL, wh);
    if (!rc) *w = wh[0], *h = wh[1];
    return rc;
}
static int cli_choice(const char *flag, const char *s, const char *const *names, int *out) { return one_value(CLI_CHOICE, flag, s, 0, 0, names, out); }

static char err_path[] = "/tmp/pathlab_test_cli_XXXXXX";
static char err[1024];   /* what the last call printed on stderr */

/* From here on stderr goes to err_path: err_begin empties it, err_end reads it into err. */
static void err_begin(void)
{
    fflush(stderr);
    if (!freopen(err_path, "w", stderr)) { perror(err_path); exit(2); }
}

static void err_end(void)
{
    FILE *f;
    size_t n = 0;
    fflush(stderr);
    if ((f = fopen(err_path, "r"))) {
        n = fread(err, 1, sizeof err - 1, f);
        fclose(f);
    }
    err[n] = '\0';
    if (n && err[n - 1] == '\n') err[n - 1] = '\0';
}

/* Everything the test tables write into. */
typedef struct {
    int on, n, n_given, size[2], pick, even, calls, other_n;
    const char *name;
    uint64_t seed;
    float f;
    double d;
    vec3 v;
    void *ctx_seen;
} opts;

static opts o;
static const char *const COLOURS[] = {"red", "green", "blue", NULL};

/* --even K: a custom flag, an even whole number (ctx is the opts) */
static int parse_even(void *ctx, const char *flag, const char *value)
{
    opts *p = ctx;
    char *end;
    long k = strtol(value, &end, 10);
    p->calls++;
    p->ctx_seen = ctx;
    if (end == value || *end || k % 2) return cli_fail("test", flag, "an even number", value);
    p->even = (int)k;
    return 0;
}

static const cli_flag FLAGS[] = {
    {"--on", CLI_SWITCH, &o.on, 0, 0, NULL, NULL, NULL},
    {"--name", CLI_STRING, &o.name, 0, 0, NULL, NULL, NULL},
    {"--n", CLI_INT, &o.n, -5, 10, NULL, NULL, &o.n_given},
    {"--seed", CLI_U64, &o.seed, 0, 0, NULL, NULL, NULL},
    {"--f", CLI_FLOAT, &o.f, 0, 0, NULL, NULL, NULL},
    {"--d", CLI_DOUBLE, &o.d, 0, 1, NULL, NULL, NULL},
    {"--v", CLI_VEC3, &o.v, 0, 0, NULL, NULL, NULL},
    {"--size", CLI_SIZE, o.size, 0, 0, NULL, NULL, NULL},
    {"--pick", CLI_CHOICE, &o.pick, 0, 0, COLOURS, NULL, NULL},
    {"--even", CLI_CUSTOM, NULL, 0, 0, NULL, parse_even, NULL},
    {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
/* a second table: its --n is hidden by the first table's, its --other is its own */
static const cli_flag OTHER[] = {
    {"--n", CLI_INT, &o.other_n, 0, 100, NULL, NULL, NULL},
    {"--other", CLI_INT, &o.other_n, 0, 100, NULL, NULL, NULL},
    {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
static const cli_flag *const TABLES[] = {FLAGS, OTHER, NULL};

static char prog[] = "test", *args[32];
static int nargs;

/* Splits line at spaces into args[1..] (args[0] = "test"). */
static void split(const char *line)
{
    static char buf[512];
    char *t;
    strcpy(buf, line);
    args[0] = prog;
    nargs = 1;
    for (t = strtok(buf, " "); t && nargs < 31; t = strtok(NULL, " ")) args[nargs++] = t;
    args[nargs] = NULL;
}

/* cli_parse("test") of the words of line, on fresh opts; its status, stderr in err. */
static int run(const char *line, const char **words, int max_words, int *nwords)
{
    int rc;
    memset(&o, 0, sizeof o);
    split(line);
    err_begin();
    rc = cli_parse("test", nargs, args, TABLES, &o, words, max_words, nwords);
    err_end();
    return rc;
}

/* 1 if run(line) fails with a message containing each of the (up to 3) texts. */
static int fails_with(const char *line, int max_words, const char *t1, const char *t2, const char *t3)
{
    const char *w[4];
    int n;
    return run(line, w, max_words, &n) == 1 && strstr(err, t1) && (!t2 || strstr(err, t2)) && (!t3 || strstr(err, t3));
}

static void test_kinds(void)
{
    const char *w[4];
    int n, rc;
    rc = run("a.pfm --on --name x --n 7 --seed 18446744073709551615 --f 2.5 --d 0.25 b.pfm --v 1,-2,3.5 "
             "--size 640x480 --pick blue --even 4", w, 2, &n);
    check(rc == 0 && err[0] == '\0', "cli_parse: every kind of flag, words among them", "status %d, stderr '%s'", rc, err);
    check(o.on == 1 && o.name && !strcmp(o.name, "x") && o.n == 7 && o.n_given && o.seed == UINT64_MAX,
          "cli_parse: switch, string, int (given set), u64 up to 2^64 - 1", "on %d n %d seed %llu", o.on, o.n, (unsigned long long)o.seed);
    check(o.f == 2.5f && o.d == 0.25 && o.v.x == 1.0f && o.v.y == -2.0f && o.v.z == 3.5f,
          "cli_parse: float, double, vec3 (with a negative component)", "%g %g (%g,%g,%g)", o.f, o.d, o.v.x, o.v.y, o.v.z);
    check(o.size[0] == 640 && o.size[1] == 480 && o.pick == 2 && o.even == 4 && o.calls == 1 && o.ctx_seen == &o,
          "cli_parse: size, choice (index), custom (called once, with ctx)", "%dx%d pick %d even %d calls %d", o.size[0], o.size[1], o.pick, o.even, o.calls);
    check(n == 2 && !strcmp(w[0], "a.pfm") && !strcmp(w[1], "b.pfm"), "cli_parse: the words, in order, wherever they are", "%d words", n);
    rc = run("", w, 2, &n);
    check(rc == 0 && n == 0 && !o.n_given && !o.on && !o.name && o.calls == 0, "cli_parse: nothing given, nothing written", "status %d", rc);
    rc = run("--n 1 --n 2", w, 0, &n);
    check(rc == 0 && o.n == 2, "cli_parse: a repeated flag, the last value wins", "n %d", o.n);
    rc = run("--n 3 --other 9", w, 0, &n);
    check(rc == 0 && o.n == 3 && o.other_n == 9, "cli_parse: the first table has --n, the second --other", "n %d other %d", o.n, o.other_n);
}

static void test_words_and_values(void)
{
    const char *w[4];
    int n, rc;
    rc = run("- --on", w, 1, &n);
    check(rc == 0 && n == 1 && !strcmp(w[0], "-") && o.on, "cli_parse: '-' alone is a word (standard input or output)", "status %d, %d words", rc, n);
    rc = run("--n -5 --f -2.5e-3 --v -1,-2,-3", w, 0, &n);
    check(rc == 0 && o.n == -5 && o.f == -2.5e-3f && o.v.x == -1.0f && o.v.z == -3.0f,
          "cli_parse: negative numbers are values, not flags", "status %d, n %d, f %g; %s", rc, o.n, o.f, err);
    rc = run("--name --on", w, 0, &n);
    check(rc == 0 && o.name && !strcmp(o.name, "--on") && !o.on, "cli_parse: a value is the next argument, even one that looks like a flag",
          "status %d", rc);
    check(cli_is_word("a.pfm") && cli_is_word("-") && !cli_is_word("-o") && !cli_is_word("--spp") && !cli_is_word("-5"),
          "cli_is_word: a.pfm and - are words; -o, --spp and -5 are not", NULL);
}

static void test_errors(void)
{
    check(fails_with("--nope", 0, "pathlab test: unknown flag '--nope'", NULL, NULL), "cli_parse: unknown flag named", "'%s'", err);
    check(fails_with("a --n", 1, "pathlab test: --n needs a value", NULL, NULL), "cli_parse: missing value named", "'%s'", err);
    check(fails_with("a b c", 2, "pathlab test: unexpected 'c' after 'b'", "at most 2", NULL), "cli_parse: one word too many", "'%s'", err);
    check(fails_with("a", 0, "pathlab test: unexpected 'a'", "flags only", NULL), "cli_parse: a word where none is taken", "'%s'", err);
    check(fails_with("--n 11", 0, "pathlab test: --n expects", "from -5 to 10", "got '11'"), "cli_parse: int above its range", "'%s'", err);
    check(fails_with("--n -6", 0, "--n expects", "got '-6'", NULL), "cli_parse: int below its range", "'%s'", err);
    check(fails_with("--n 3.5", 0, "--n expects a whole number", "got '3.5'", NULL), "cli_parse: int with a fraction", "'%s'", err);
    check(fails_with("--d 1.5", 0, "--d expects a number from 0 to 1", "got '1.5'", NULL), "cli_parse: double out of range", "'%s'", err);
    check(fails_with("--seed -1", 0, "--seed expects a whole number >= 0", "got '-1'", NULL), "cli_parse: negative u64", "'%s'", err);
    check(fails_with("--seed 18446744073709551616", 0, "--seed expects", NULL, NULL), "cli_parse: u64 overflow", "'%s'", err);
    check(fails_with("--pick Green", 0, "--pick expects one of red, green, blue", "got 'Green'", NULL), "cli_parse: choice lists the names", "'%s'", err);
    check(fails_with("--size 64", 0, "--size expects WIDTHxHEIGHT", "got '64'", NULL), "cli_parse: size without x", "'%s'", err);
    check(fails_with("--size 0x10", 0, "--size expects", "1 to 65536", "got '0x10'"), "cli_parse: size out of range, whole value shown", "'%s'", err);
    check(fails_with("--even 3", 0, "pathlab test: --even expects an even number, got '3'", NULL, NULL) && o.calls == 1,
          "cli_parse: a custom flag's error", "'%s'", err);
    check(fails_with("--even 3 --nope", 0, "--even", NULL, NULL) && !strstr(err, "--nope"), "cli_parse: stops at the first error", "'%s'", err);
}

static void test_parse_flag(void)
{
    int i = 1, rc;
    memset(&o, 0, sizeof o);
    split("--n 3 --on");
    rc = cli_parse_flag("test", nargs, args, &i, TABLES, &o);
    check(rc == 0 && o.n == 3 && i == 2, "cli_parse_flag: one flag and its value, i left on the value", "status %d, i %d", rc, i);
    i = 3;
    rc = cli_parse_flag("test", nargs, args, &i, TABLES, &o);
    check(rc == 0 && o.on && i == 3, "cli_parse_flag: a switch, i unmoved", "status %d, i %d", rc, i);
}

/* The value parsers outside a table: "pathlab: FLAG expects ..., got 'VALUE'". (Each check's
 * condition is computed before the call: the order of a call's arguments is unspecified.) */
static void test_values(void)
{
    int k = -1, w = 0, h = 0, ok;
    float f = 0.0f;
    double d = 0.0;
    uint64_t u = 0;
    vec3 v;
    err_begin();
    ok = !cli_int("-x", "42", 0, 100, &k) && k == 42 && !cli_int("-x", "0", 0, 100, &k) && !cli_int("-x", "100", 0, 100, &k);
    check(ok, "cli_int: in range, bounds included", "%d", k);
    ok = cli_int("-x", "", 0, 100, &k) && cli_int("-x", "4x", 0, 100, &k) && cli_int("-x", "101", 0, 100, &k)
         && cli_int("-x", "99999999999999999999", 0, 100, &k) && k == 100;
    check(ok, "cli_int: empty, trailing text, range, overflow refused; *out kept", "%d", k);
    ok = !cli_u64("-s", "0", &u) && u == 0 && cli_u64("-s", " -1", &u) && cli_u64("-s", "1e3", &u);
    check(ok, "cli_u64: digits only", NULL);
    ok = !cli_float("-f", "1e-3", &f) && f == 1e-3f && cli_float("-f", "nan", &f) && cli_float("-f", "inf", &f)
         && cli_float("-f", "1e39", &f) && cli_float("-f", "1,5", &f);
    check(ok, "cli_float: finite and within a float's range", "%g", f);
    ok = !cli_double("-d", "-0.5", -1, 1, &d) && d == -0.5 && cli_double("-d", "1.0001", -1, 1, &d) && cli_double("-d", "nan", -1, 1, &d);
    check(ok, "cli_double: within [lo, hi], not nan", "%g", d);
    ok = !cli_vec3("-v", "0.5,1e2,-3", &v) && v.y == 100.0f && cli_vec3("-v", "1,2", &v) && cli_vec3("-v", "1,2,3,4", &v)
         && cli_vec3("-v", "1,,3", &v) && cli_vec3("-v", "1,2,nan", &v);
    check(ok, "cli_vec3: exactly three finite numbers", NULL);
    ok = !cli_size("-s", "10X20", &w, &h) && w == 10 && h == 20 && !cli_size("-s", "65536x1", &w, &h) && cli_size("-s", "65537x1", &w, &h)
         && cli_size("-s", "64x", &w, &h) && cli_size("-s", "64x64x", &w, &h);
    check(ok, "cli_size: WxH, each 1 to 65536", "%dx%d", w, h);
    ok = !cli_choice("-c", "green", COLOURS, &k) && k == 1 && cli_choice("-c", "", COLOURS, &k);
    check(ok, "cli_choice: the index of the name", "%d", k);
    err_end();
    err_begin();
    cli_int("--spp", "abc", 1, 8, &k);
    err_end();
    check(!strcmp(err, "pathlab: --spp expects a whole number from 1 to 8, got 'abc'"), "cli_int: the message", "'%s'", err);
}

static void test_render_defaults(void)
{
    render_args a;
    cli_flag t[RENDER_NFLAGS];
    int i, j, dup = 0;
    render_args_init(&a);
    check(!strcmp(a.cmd, "render") && a.spp == 16 && a.ro.seed == 1 && a.ro.io.bmin == 0 && a.ro.io.bmax == BOUNCES_NO_END
          && a.ro.io.rr_depth == 3 && a.ro.io.direct == DIRECT_MIS_POWER && a.ro.io.light == LIGHT_AREA && a.ro.io.dir == DIR_BRDF,
          "render_args_init: the defaults", NULL);
    render_flag_table(&a, t);
    for (i = 0; i < RENDER_NFLAGS - 1; i++)
        for (j = 0; j < i; j++) dup += !t[i].name || !strcmp(t[i].name, t[j].name);
    check(dup == 0 && !t[RENDER_NFLAGS - 1].name, "render_flag_table: RENDER_NFLAGS - 1 different flags, then the end", "%d", dup);
}

/* render_parse_flag at args[i]; its status, stderr in err. */
static int render_flag_at(render_args *a, int i, int *next)
{
    int rc;
    err_begin();
    rc = render_parse_flag(a, nargs, args, &i);
    err_end();
    if (next) *next = i;
    return rc;
}

/* render's flags, one at a time, as pathlab compare parses them. */
static void test_render_flags(void)
{
    render_args a;
    int i, rc = 0;
    render_args_init(&a);
    split("scene.obj --bounces 1:3 --rr off --light solid-angle --dir cosine --direct light --size 64x32 --eye 0,1,-5 --quiet");
    for (i = 1; i < nargs && !rc; i++) rc = render_flag_at(&a, i, &i);
    check(rc == 0 && !strcmp(a.scene, "scene.obj") && a.ro.io.bmin == 1 && a.ro.io.bmax == 3 && a.ro.io.rr_depth == -1
          && a.ro.io.light == LIGHT_SOLID_ANGLE && a.ro.io.dir == DIR_COSINE && a.ro.io.direct == DIRECT_LIGHT,
          "render_parse_flag: scene, --bounces, --rr off, --light, --dir, --direct", "status %d: %s", rc, err);
    check(a.cam.size && a.cam.flags.width == 64 && a.cam.flags.height == 32 && a.cam.eye && a.cam.flags.eye.z == -5.0f && a.ro.quiet && !a.cam.target,
          "render_parse_flag: --size, --eye (given), --quiet", NULL);
    split("--bounce 2 --bounces 0:inf other.obj --rr 7 --rr maybe --bounces 3:1 --rr-below 0.25 --rr-below 0");
    a.scene = "scene.obj";   /* the words of the first line are gone with it */
    a.cmd = "compare";
    rc = render_flag_at(&a, 1, &i);
    check(rc == 0 && i == 2 && a.ro.io.bmin == 2 && a.ro.io.bmax == 2, "render_parse_flag: --bounce K is K:K", "status %d, i %d", rc, i);
    rc = render_flag_at(&a, 3, NULL);
    check(rc == 0 && a.ro.io.bmin == 0 && a.ro.io.bmax == BOUNCES_NO_END, "render_parse_flag: --bounces 0:inf", NULL);
    rc = render_flag_at(&a, 5, NULL);
    check(rc == 1 && strstr(err, "pathlab compare: one scene only") && strstr(err, "other.obj"), "render_parse_flag: a second scene", "'%s'", err);
    rc = render_flag_at(&a, 6, NULL);
    check(rc == 0 && a.ro.io.rr_depth == 7, "render_parse_flag: --rr D", "%d", a.ro.io.rr_depth);
    rc = render_flag_at(&a, 8, NULL);
    check(rc == 1 && strstr(err, "pathlab compare: --rr expects") && strstr(err, "'maybe'"), "render_parse_flag: messages name a.cmd, the flag, the value", "'%s'", err);
    rc = render_flag_at(&a, 10, NULL);
    check(rc == 1 && strstr(err, "--bounces expects") && strstr(err, "'3:1'"), "render_parse_flag: --bounces A:B needs A <= B", "'%s'", err);
    check(a.ro.io.rr_below == 0.0f, "render_parse_flag: --rr-below is 0 (the sampler's default) until given", "%g", a.ro.io.rr_below);
    rc = render_flag_at(&a, 12, NULL);
    check(rc == 0 && a.ro.io.rr_below == 0.25f, "render_parse_flag: --rr-below T", "status %d, %g", rc, a.ro.io.rr_below);
    rc = render_flag_at(&a, 14, NULL);
    check(rc == 1 && strstr(err, "--rr-below expects") && strstr(err, "'0'"), "render_parse_flag: --rr-below 0 is refused", "'%s'", err);
}

int main(void)
{
    int fd = mkstemp(err_path);
    if (fd < 0) { perror("mkstemp"); return 2; }
    close(fd);
    test_kinds();
    test_words_and_values();
    test_errors();
    test_parse_flag();
    test_values();
    test_render_defaults();
    test_render_flags();
    unlink(err_path);
    return check_summary();
}
