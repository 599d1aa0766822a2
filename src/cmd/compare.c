/* compare.c — pathlab compare: several estimators of one scene side by side, with their errors.
 *
 * Choices (summed up in COMPARE_HELP, compare.h):
 * - An estimator is a list of render flags. Shorthand words expand to flags: light, brdf,
 *   mis-balance, mis-power -> --direct X; uniform, cosine, dir-brdf -> --dir X (dir-brdf because
 *   "brdf" already means --direct brdf); area, triangle, power, solid-angle -> --light X. Words join
 *   with '+' or spaces and mix with flags: "light+solid-angle", "mis-power --rr off". "LABEL=FLAGS"
 *   names it; otherwise its text is its label. Estimators are separated by commas, except a comma
 *   followed by a number, which stays inside a value (--eye 0,1,5).
 * - Flags outside --estimators apply to all; each estimator's flags are parsed after them, so they
 *   win. --spp, -o, --variance and --split are refused inside an estimator: the comparison fixes
 *   the samples (or the time) and the files.
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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cmd/render_args.h"
#include "cmd/diff.h"
#include "image/font.h"
#include "tracer/render.h"

#define MAX_EST 16
#define CALIB_FRACTION 0.2    /* of --time: the length of the last calibration render */
#define MAX_TOK 64
#define RESERVED_SLUGS "reference", "mosaic", "table"

typedef struct {
    char label[600], slug[64], flags[600];   /* label: as long as the text it comes from */
    char *tok[MAX_TOK];        /* the expanded flags, owned */
    int ntok;
    render_args a;
    camera cam;
    int spp;
    double secs, sec_per_spp, mse, eff;
    image img, heat;
    diff_stats ds;
} estimator;

typedef struct {
    render_args base;
    const char *list, *dir, *ref, *ref_var;
    int spp, spp_given, ref_spp, nest;
    float time, scale;
    estimator est[MAX_EST];
} compare_args;

typedef struct { const char *word, *flag, *value; } shorthand;
static const shorthand SHORTHANDS[] = {
    {"light", "--direct", "light"}, {"brdf", "--direct", "brdf"},
    {"mis-balance", "--direct", "mis-balance"}, {"mis-power", "--direct", "mis-power"},
    {"uniform", "--dir", "uniform"}, {"cosine", "--dir", "cosine"}, {"dir-brdf", "--dir", "brdf"},
    {"area", "--light", "area"}, {"triangle", "--light", "triangle"}, {"power", "--light", "power"},
    {"solid-angle", "--light", "solid-angle"}, {NULL, NULL, NULL}};

/* The best estimator of the course, for the reference. */
static const char *const BEST[] = {"--direct", "mis-power", "--light", "solid-angle", "--dir", "brdf"};

static char *dupstr(const char *s, size_t n)
{
    char *d = malloc(n + 1);
    if (d) { memcpy(d, s, n); d[n] = '\0'; }
    return d;
}

static void trim(char *s)
{
    size_t n = strlen(s), i = 0;
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) s[--n] = '\0';
    while (s[i] == ' ' || s[i] == '\t') i++;
    memmove(s, s + i, n - i + 1);
}

static int add_tok(estimator *e, const char *s, size_t n)
{
    if (e->ntok >= MAX_TOK) { fprintf(stderr, "pathlab: compare: estimator '%s': more than %d flags\n", e->label, MAX_TOK); return 1; }
    if (!(e->tok[e->ntok] = dupstr(s, n))) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    e->ntok++;
    return 0;
}

/* One shorthand word (n characters at w) -> its flag and value. */
static int add_word(estimator *e, const char *w, size_t n)
{
    int k;
    for (k = 0; SHORTHANDS[k].word; k++)
        if (strlen(SHORTHANDS[k].word) == n && !strncmp(SHORTHANDS[k].word, w, n))
            return add_tok(e, SHORTHANDS[k].flag, strlen(SHORTHANDS[k].flag)) || add_tok(e, SHORTHANDS[k].value, strlen(SHORTHANDS[k].value));
    fprintf(stderr, "pathlab: compare: estimator '%s': unknown name '%.*s'\n"
            "  names: light brdf mis-balance mis-power (--direct), uniform cosine dir-brdf (--dir),\n"
            "  area triangle power solid-angle (--light); or render flags, e.g. \"--direct light --light solid-angle\"\n",
            e->label, (int)n, w);
    return 1;
}

static int takes_value(const char *flag)
{
    return strcmp(flag, "--quiet") && strcmp(flag, "--pixel-center") && strcmp(flag, "--split");
}

/* Splits the text of one estimator into its expanded flags (e->tok), its label and its slug. */
static int parse_estimator(estimator *e, const char *item, size_t len)
{
    char text[600], *eq, *p;
    int after_flag = 0;
    size_t n, k;
    if (len >= sizeof text) { fprintf(stderr, "pathlab: compare: estimator '%.40s...' is too long\n", item); return 1; }
    memcpy(text, item, len);
    text[len] = '\0';
    trim(text);
    eq = strchr(text, '=');
    if (eq) {
        *eq = '\0';
        snprintf(e->label, sizeof e->label, "%s", text);
        trim(e->label);
        memmove(text, eq + 1, strlen(eq + 1) + 1);
        trim(text);
        if (!e->label[0]) { fprintf(stderr, "pathlab: compare: empty label before '=' in '%.*s'\n", (int)len, item); return 1; }
    } else {
        snprintf(e->label, sizeof e->label, "%s", text);
    }
    if (!text[0]) { fprintf(stderr, "pathlab: compare: an empty estimator in --estimators (two commas, or nothing after '=')\n"); return 1; }
    for (p = text; *p;) {
        while (*p == ' ' || *p == '\t') p++;
        if (!*p) break;
        n = strcspn(p, " \t");
        if (*p == '-' || after_flag) {                /* a flag or a flag's value, as it is */
            if (add_tok(e, p, n)) return 1;
            after_flag = *p == '-' && !after_flag && takes_value(e->tok[e->ntok - 1]);
        } else {                                      /* shorthand words joined with '+' */
            for (k = 0; k < n;) {
                size_t m = strcspn(p + k, "+ \t");
                if (m > n - k) m = n - k;
                if (add_word(e, p + k, m)) return 1;
                k += m + 1;
            }
        }
        p += n;
    }
    /* the slug: lower-case letters and digits, other runs become one '-' */
    for (n = 0, p = e->label; *p && n + 1 < sizeof e->slug; p++) {
        int c = (unsigned char)*p;
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) e->slug[n++] = (char)c;
        else if (c >= 'A' && c <= 'Z') e->slug[n++] = (char)(c - 'A' + 'a');
        else if (n > 0 && e->slug[n - 1] != '-') e->slug[n++] = '-';
    }
    while (n > 0 && e->slug[n - 1] == '-') n--;
    e->slug[n] = '\0';
    if (!n) { fprintf(stderr, "pathlab: compare: label '%s' has no letter or digit to name its files\n", e->label); return 1; }
    e->flags[0] = '\0';
    for (k = 0; k < (size_t)e->ntok; k++) {
        size_t used = strlen(e->flags);
        snprintf(e->flags + used, sizeof e->flags - used, "%s%s", k ? " " : "", e->tok[k]);
    }
    return 0;
}

/* A comma ends an estimator unless a number follows it (--eye 0,1,5 or --up 0,-1,0). */
static int splits_here(const char *s)
{
    return s[0] == ',' && !(s[1] >= '0' && s[1] <= '9') && s[1] != '.'
           && !(s[1] == '-' && ((s[2] >= '0' && s[2] <= '9') || s[2] == '.'));
}

/* The estimator's render_args: the shared flags, then its own. */
static int estimator_args(estimator *e, const render_args *base)
{
    int i;
    e->a = *base;
    e->a.scene = e->a.out = e->a.variance = NULL;
    e->a.ro.spp = 0;
    for (i = 0; i < e->ntok; i++)
        if (render_parse_flag(&e->a, e->ntok, e->tok, &i)) {
            fprintf(stderr, "pathlab: compare: in estimator '%s'\n", e->label);
            return 1;
        }
    if (e->a.scene || e->a.out || e->a.variance || e->a.ro.io.split || e->a.ro.spp) {
        fprintf(stderr, "pathlab: compare: estimator '%s': %s\n", e->label,
                e->a.scene ? "a word that is neither a flag, a flag's value nor a name" :
                e->a.ro.spp ? "--spp is set for all estimators (--spp or --time of compare), not for one" :
                "-o, --variance and --split are not for an estimator");
        return 1;
    }
    e->a.scene = base->scene;
    e->a.ro.quiet = 1;
    return 0;
}

static int parse_args(compare_args *c, int argc, char **argv)
{
    int i, j;
    const char *s;
    render_args_init(&c->base);
    c->spp = 16;
    for (i = 1; i < argc; i++) {
        const char *f = argv[i], *v;
        int ours = !strcmp(f, "--estimators") || !strcmp(f, "-o") || !strcmp(f, "--ref") || !strcmp(f, "--ref-var")
                   || !strcmp(f, "--ref-spp") || !strcmp(f, "--time") || !strcmp(f, "--spp") || !strcmp(f, "--scale");
        if (!strcmp(f, "--split") || !strcmp(f, "--variance")) {
            fprintf(stderr, "pathlab: compare: %s is a flag of render only\n", f);
            return 1;
        }
        if (!ours) { if (render_parse_flag(&c->base, argc, argv, &i)) return 1; continue; }
        if (!(v = cli_value(argc, argv, &i))) return 1;
        if (!strcmp(f, "--estimators")) c->list = v;
        else if (!strcmp(f, "-o")) c->dir = v;
        else if (!strcmp(f, "--ref")) c->ref = v;
        else if (!strcmp(f, "--ref-var")) c->ref_var = v;
        else if (!strcmp(f, "--ref-spp")) { if (cli_int(f, v, 1, 1 << 30, &c->ref_spp)) return 1; }
        else if (!strcmp(f, "--spp")) { if (cli_int(f, v, 1, 1 << 30, &c->spp)) return 1; c->spp_given = 1; }
        else if (!strcmp(f, "--scale")) { if (cli_float(f, v, &c->scale)) return 1; }
        else if (cli_float(f, v, &c->time)) return 1;
        else if (!(c->time > 0.0f && c->time <= 86400.0f)) { fprintf(stderr, "pathlab: --time expects seconds in (0, 86400], got '%s'\n", v); return 1; }
    }
    if (!c->base.scene || !c->list || !c->dir) {
        fprintf(stderr, "pathlab: compare needs a scene, --estimators and -o DIR\nusage:\n" COMPARE_USAGE COMPARE_HELP);
        return 1;
    }
    if (c->spp_given && c->time > 0.0f) { fprintf(stderr, "pathlab: compare: --spp (equal samples) or --time (equal time), not both\n"); return 1; }
    if (c->ref_var && !c->ref) { fprintf(stderr, "pathlab: compare: --ref-var goes with --ref\n"); return 1; }
    if (c->ref && c->ref_spp) { fprintf(stderr, "pathlab: compare: --ref-spp is for a rendered reference, not with --ref\n"); return 1; }
    if (c->base.ro.threads < 1) c->base.ro.threads = 1;
    for (s = c->list; *s;) {
        size_t n = 0;
        while (s[n] && !splits_here(s + n)) n++;
        if (c->nest == MAX_EST) { fprintf(stderr, "pathlab: compare: at most %d estimators\n", MAX_EST); return 1; }
        if (parse_estimator(&c->est[c->nest++], s, n) || estimator_args(&c->est[c->nest - 1], &c->base)) return 1;
        s += n + (s[n] == ',');
        if (s[-1] == ',' && !*s) { fprintf(stderr, "pathlab: compare: --estimators ends with a comma\n"); return 1; }
    }
    for (i = 0; i < c->nest; i++) {
        static const char *const reserved[] = {RESERVED_SLUGS};
        for (j = 0; j < (int)(sizeof reserved / sizeof *reserved); j++)
            if (!strcmp(c->est[i].slug, reserved[j])) {
                fprintf(stderr, "pathlab: compare: label '%s' would write over DIR/%s.*: name it, e.g. \"my %s=%s\"\n",
                        c->est[i].label, reserved[j], c->est[i].label, c->est[i].flags);
                return 1;
            }
        for (j = 0; j < i; j++)
            if (!strcmp(c->est[i].slug, c->est[j].slug)) {
                fprintf(stderr, "pathlab: compare: estimators '%s' and '%s' would both write DIR/%s.pfm: label one (LABEL=FLAGS)\n",
                        c->est[j].label, c->est[i].label, c->est[i].slug);
                return 1;
            }
    }
    return 0;
}

/* ---- rendering ---- */

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

/* Seconds per sample of e: renders at 1, 2, 4 ... spp until a render lasts target seconds. */
static int calibrate(const scene *s, estimator *e, double target)
{
    render_opts ro = e->a.ro;
    image im;
    double t = 0.0;
    for (ro.spp = 1;; ro.spp *= 2) {
        if (render_image(s, &e->cam, &ro, &im, NULL, &t)) return 1;
        img_free(&im);
        if (t >= target || ro.spp >= (1 << 20)) break;
    }
    e->sec_per_spp = t / ro.spp;
    return 0;
}

static double mean_of(const image *im)
{
    long i, n = 3L * im->w * im->h;
    double sum = 0.0;
    for (i = 0; i < n; i++) sum += im->px[i];
    return sum / n;
}

/* ---- the mosaic ---- */

#define GAP 4                 /* pixels between panels and around them */
#define MAX_LINES 3           /* of a label */

static const float BG[3] = {0.012f, 0.012f, 0.014f};     /* dark grey once sRGB-encoded (~0.11) */
static const float INK[3] = {1.0f, 1.0f, 1.0f};

/* Breaks text into at most MAX_LINES lines of at most cols characters, at spaces when it can;
 * the last line ends with ".." if the text did not fit. Returns the number of lines. */
static int wrap(const char *text, int cols, char lines[MAX_LINES][128])
{
    int n = 0, len;
    if (cols < 3) cols = 3;
    if (cols > 127) cols = 127;
    while (*text == ' ') text++;
    while (*text && n < MAX_LINES) {
        len = (int)strlen(text);
        if (len > cols) {
            int k = cols;
            while (k > 0 && text[k] != ' ') k--;
            len = k > cols / 3 ? k : cols;   /* break at the last space, or cut a long word */
        }
        memcpy(lines[n], text, (size_t)len);
        lines[n][len] = '\0';
        text += len;
        while (*text == ' ') text++;
        n++;
    }
    if (*text && n > 0) {   /* did not fit: mark the cut */
        size_t m = strlen(lines[n - 1]);
        if (m + 2 > (size_t)cols) m = (size_t)cols - 2;
        strcpy(lines[n - 1] + m, "..");
    }
    return n;
}

typedef struct { int k, ts, pw, ph, cols, band[2], rows, ncol, w, h; } layout;

static int label_lines(const layout *L, const char *text)
{
    char lines[MAX_LINES][128];
    return wrap(text, L->cols, lines);
}

static void draw_label(image *m, const layout *L, int x, int y, const char *text)
{
    char lines[MAX_LINES][128];
    int i, n = wrap(text, L->cols, lines);
    for (i = 0; i < n; i++) font_draw(m, x, y + 2 + i * FONT_LINE * L->ts, lines[i], L->ts, INK);
}

/* Copies im into m at (x, y), each pixel a k x k square, multiplied by gain. */
static void blit(image *m, const image *im, int x, int y, int k, float gain)
{
    int i, j, c;
    for (j = 0; j < im->h * k; j++)
        for (i = 0; i < im->w * k; i++)
            for (c = 0; c < 3; c++)
                m->px[3 * ((long)(y + j) * m->w + x + i) + c] = gain * im->px[3 * ((long)(j / k) * im->w + i / k) + c];
}

/* Row 0: the reference and each estimator's image; row 1 (with heatmaps): a legend of the error
 * scale, then each heatmap. A label band over every panel. */
static int make_mosaic(image *m, const compare_args *c, const image *ref, const char *ref_label,
                       const image *legend, double scale, float exposure)
{
    layout L;
    char text[160];
    int i, r, x, y;
    memset(&L, 0, sizeof L);
    for (L.k = 1; ref->w * L.k < 128 && L.k < 4; L.k++) continue;   /* small renders: 2x to 4x */
    L.pw = ref->w * L.k;
    L.ph = ref->h * L.k;
    L.ts = L.pw >= 400 ? 2 : 1;
    L.cols = (L.pw + L.ts) / (FONT_ADVANCE * L.ts);
    L.ncol = c->nest + 1;
    L.rows = 2;
    for (r = 0; r < 2; r++) {
        int most = r ? 1 : label_lines(&L, ref_label);
        for (i = 0; i < c->nest && !r; i++)
            if (label_lines(&L, c->est[i].label) > most) most = label_lines(&L, c->est[i].label);
        L.band[r] = 2 + most * FONT_LINE * L.ts;
    }
    L.w = GAP + L.ncol * (L.pw + GAP);
    L.h = GAP + L.band[0] + L.ph + GAP + L.band[1] + L.ph + GAP;
    if (img_alloc(m, L.w, L.h)) { fprintf(stderr, "pathlab: compare: out of memory for the mosaic\n"); return 1; }
    for (i = 0; i < L.w * L.h; i++) memcpy(m->px + 3L * i, BG, sizeof BG);
    for (r = 0; r < L.rows; r++) {
        y = GAP + (r ? L.band[0] + L.ph + GAP : 0);
        for (i = 0; i < L.ncol; i++) {
            x = GAP + i * (L.pw + GAP);
            if (r == 0) {
                draw_label(m, &L, x, y, i ? c->est[i - 1].label : ref_label);
                blit(m, i ? &c->est[i - 1].img : ref, x, y + L.band[0], L.k, exp2f(exposure));
            } else {
                if (i) snprintf(text, sizeof text, "RMSE %.3g", c->est[i - 1].ds.rmse);
                else snprintf(text, sizeof text, "error 0 to %.3g", scale);
                draw_label(m, &L, x, y, text);
                blit(m, i ? &c->est[i - 1].heat : legend, x, y + L.band[1], L.k, 1.0f);
            }
        }
    }
    return 0;
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

/* ---- the table ---- */

static void print_table(FILE *f, const compare_args *c, int md)
{
    int i, wl = 9, wf = 5;
    double best = 0.0;
    for (i = 0; i < c->nest; i++) {
        if (c->est[i].eff > best) best = c->est[i].eff;
        if ((int)strlen(c->est[i].label) > wl) wl = (int)strlen(c->est[i].label);
        if ((int)strlen(c->est[i].flags) > wf) wf = (int)strlen(c->est[i].flags);
    }
    if (md) fprintf(f, "| estimator | flags | spp | time (s) | RMSE | relMSE | MAE | MSE | efficiency 1/(MSE*time) | ratio to best |\n"
                       "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    else fprintf(f, "%-*s  %-*s %7s %8s %10s %10s %10s %10s %11s %6s\n", wl, "estimator", wf, "flags", "spp", "time(s)",
                 "RMSE", "relMSE", "MAE", "MSE", "efficiency", "ratio");
    for (i = 0; i < c->nest; i++) {
        const estimator *e = &c->est[i];
        double ratio = best > 0.0 ? e->eff / best : 0.0;
        if (md) fprintf(f, "| %s | `%s` | %d | %.3f | %.4g | %.4g | %.4g | %.4g | %.4g | %.3f |\n",
                        e->label, e->flags, e->spp, e->secs, e->ds.rmse, e->ds.relmse, e->ds.mae, e->mse, e->eff, ratio);
        else fprintf(f, "%-*s  %-*s %7d %8.3f %10.4g %10.4g %10.4g %10.4g %11.4g %6.3f\n",
                     wl, e->label, wf, e->flags, e->spp, e->secs, e->ds.rmse, e->ds.relmse, e->ds.mae, e->mse, e->eff, ratio);
    }
}

static void csv_field(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) { if (*s == '"') fputc('"', f); fputc(*s, f); }
    fputc('"', f);
}

/* Writes path via a temporary file renamed at the end, like the images. */
static int write_text(const char *path, const compare_args *c, const char *notes, int csv)
{
    char tmp[4200];
    FILE *f;
    int i, err;
    double best = 0.0;
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    if (!(f = fopen(tmp, "w"))) { fprintf(stderr, "%s: %s\n", tmp, strerror(errno)); return 1; }
    if (csv) {
        for (i = 0; i < c->nest; i++) if (c->est[i].eff > best) best = c->est[i].eff;
        fprintf(f, "estimator,flags,spp,time_s,rmse,relmse,mae,mse,efficiency,ratio_to_best\n");
        for (i = 0; i < c->nest; i++) {
            const estimator *e = &c->est[i];
            csv_field(f, e->label);
            fputc(',', f);
            csv_field(f, e->flags);
            fprintf(f, ",%d,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f\n", e->spp, e->secs, e->ds.rmse, e->ds.relmse,
                    e->ds.mae, e->mse, e->eff, best > 0.0 ? e->eff / best : 0.0);
        }
    } else {
        print_table(f, c, 1);
        fprintf(f, "\nNotes:\n\n%s", notes);
    }
    err = ferror(f);
    err |= fclose(f) != 0;
    if (err || rename(tmp, path)) { fprintf(stderr, "%s: could not write\n", path); remove(tmp); return 1; }
    return 0;
}

static int out_path(char *dst, size_t cap, const char *dir, const char *pre, const char *slug, const char *ext)
{
    if ((size_t)snprintf(dst, cap, "%s/%s%s%s", dir, pre, slug, ext) >= cap) {
        fprintf(stderr, "pathlab: compare: path too long in %s\n", dir);
        return 1;
    }
    return 0;
}

/* ---- the command ---- */

static int same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* One reference serves all: the estimators must see the same image. */
static int same_camera(const camera *a, const camera *b)
{
    return same_vec(a->eye, b->eye) && same_vec(a->w, b->w) && same_vec(a->u, b->u) && same_vec(a->v, b->v);
}

static int run(compare_args *c, scene *s)
{
    image ref = {0, 0, NULL}, ref_var = {0, 0, NULL}, legend = {0, 0, NULL}, mosaic = {0, 0, NULL};
    render_args ra;
    char notes[4096], path[4200], ref_label[160];
    double ref_secs = 0.0, mean_var = 0.0, scale = c->scale, worst = 0.0;
    int i, rc = 2, has_var = 0, w, h, max_spp = 0, ref_spp = 0;
    size_t nn = 0;
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        if (render_make_camera(&e->a, s, &e->cam)) goto done;
        if (i && (e->cam.width != c->est[0].cam.width || e->cam.height != c->est[0].cam.height)) {
            fprintf(stderr, "pathlab: compare: estimator '%s' renders %dx%d but '%s' %dx%d: one size for all\n",
                    e->label, e->cam.width, e->cam.height, c->est[0].label, c->est[0].cam.width, c->est[0].cam.height);
            goto done;
        }
        if (i && !same_camera(&e->cam, &c->est[0].cam)) {
            fprintf(stderr, "pathlab: compare: estimator '%s' sees the scene from another camera than '%s': one view for all\n",
                    e->label, c->est[0].label);
            goto done;
        }
    }
    w = c->est[0].cam.width;
    h = c->est[0].cam.height;
    if (c->ref) {
        if (img_read_pfm(&ref, c->ref)) goto done;
        if (ref.w != w || ref.h != h) {
            fprintf(stderr, "pathlab: compare: the reference %s is %dx%d but the renders are %dx%d (use --size %dx%d, or another reference)\n",
                    c->ref, ref.w, ref.h, w, h, ref.w, ref.h);
            goto done;
        }
        if (c->ref_var) {
            if (img_read_pfm(&ref_var, c->ref_var)) goto done;
            if (ref_var.w != w || ref_var.h != h) {
                fprintf(stderr, "pathlab: compare: --ref-var %s is %dx%d but the reference is %dx%d\n", c->ref_var, ref_var.w, ref_var.h, w, h);
                goto done;
            }
        }
    }
    if (mkdir(c->dir, 0777) && errno != EEXIST) { fprintf(stderr, "pathlab: compare: cannot create %s: %s\n", c->dir, strerror(errno)); goto done; }
    rc = 1;
    /* the number of samples of each */
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        if (c->time > 0.0f) {
            double target = CALIB_FRACTION * c->time;
            if (calibrate(s, e, target)) goto done;
            e->spp = (int)fmin(1 << 30, fmax(1.0, floor(c->time / e->sec_per_spp + 0.5)));
            if (!c->base.ro.quiet) fprintf(stderr, "compare: %s: %.3g ms per spp -> %d spp for %g s\n", e->label, 1e3 * e->sec_per_spp, e->spp, c->time);
        } else {
            e->spp = c->spp;
        }
        if (e->spp > max_spp) max_spp = e->spp;
    }
    if (!c->ref) {   /* the reference: the best estimator, many more samples, its own seed */
        ra = c->base;
        for (i = 0; i < 6; i += 2) {
            int j = i;
            if (render_parse_flag(&ra, 6, (char **)BEST, &j)) goto done;
        }
        ra.ro.quiet = c->base.ro.quiet;
        ref_spp = c->ref_spp ? c->ref_spp : (int)fmin(1 << 30, 16.0 * max_spp);
        ra.ro.spp = ref_spp;
        ra.ro.seed = c->base.ro.seed ^ 0x9e3779b97f4a7c15ULL;
        if (!c->base.ro.quiet) fprintf(stderr, "compare: rendering the reference: %d spp of %s %s %s %s %s %s\n", ref_spp,
                                       BEST[0], BEST[1], BEST[2], BEST[3], BEST[4], BEST[5]);
        if (render_image(s, &c->est[0].cam, &ra.ro, &ref, &ref_var, &ref_secs)) goto done;
        if (out_path(path, sizeof path, c->dir, "", "reference", ".pfm") || img_write(&ref, path, 0.0f)) goto done;
        if (out_path(path, sizeof path, c->dir, "", "reference-var", ".pfm") || img_write(&ref_var, path, 0.0f)) goto done;
        if (out_path(path, sizeof path, c->dir, "", "reference", ".png") || img_write(&ref, path, c->base.exposure)) goto done;
    }
    has_var = ref_var.px != NULL;
    if (has_var) mean_var = mean_of(&ref_var);
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        render_opts ro = e->a.ro;
        ro.spp = e->spp;
        if (render_image(s, &e->cam, &ro, &e->img, NULL, &e->secs)) goto done;
        diff_compute(&e->ds, &e->img, &ref);
        e->mse = e->ds.rmse * e->ds.rmse - mean_var;
        if (!(e->mse > 0.0)) e->mse = 1e-30;   /* below the reference's noise: efficiency is then meaningless */
        e->eff = 1.0 / (e->mse * fmax(e->secs, 1e-9));
        if (e->ds.rmse > worst) worst = e->ds.rmse;
        if (!c->base.ro.quiet) fprintf(stderr, "compare: %s: %d spp in %.3f s, RMSE %.4g\n", e->label, e->spp, e->secs, e->ds.rmse);
        if (out_path(path, sizeof path, c->dir, "", e->slug, ".pfm") || img_write(&e->img, path, 0.0f)) goto done;
        if (out_path(path, sizeof path, c->dir, "", e->slug, ".png") || img_write(&e->img, path, c->base.exposure)) goto done;
    }
    if (!(scale > 0.0)) scale = worst > 0.0 ? 3.0 * worst : 1.0;
    for (i = 0; i < c->nest; i++) {
        estimator *e = &c->est[i];
        if (diff_heatmap(&e->heat, &e->img, &ref, scale)) goto done;
        if (out_path(path, sizeof path, c->dir, "heat-", e->slug, ".png") || img_write(&e->heat, path, 0.0f)) goto done;
    }
    /* the notes under the table */
    if (c->ref) {
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn, "- reference: %s (given)%s%s.\n", c->ref,
                               has_var ? ", its variance " : "", has_var ? c->ref_var : "");
        snprintf(ref_label, sizeof ref_label, "reference");
    } else {
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn,
                               "- reference: rendered with `--direct mis-power --light solid-angle --dir brdf` at %d spp "
                               "(%s), seed %llu, in %.2f s; written as reference.pfm (its variance: reference-var.pfm).\n",
                               ref_spp, c->ref_spp ? "--ref-spp" : "16 x the largest spp", (unsigned long long)ra.ro.seed, ref_secs);
        snprintf(ref_label, sizeof ref_label, "reference %d spp", ref_spp);
    }
    if (has_var)
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn,
                               "- MSE = RMSE^2 - %.4g, the mean variance of the reference's pixels: its own noise, which adds to every "
                               "squared error; efficiency = 1/(MSE * time). RMSE, relMSE and MAE are raw (as pathlab diff prints them).\n", mean_var);
    else
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn,
                               "- MSE = RMSE^2: the reference's variance is unknown (--ref-var), so its noise counts as error.\n");
    if (c->time > 0.0f)
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn,
                               "- equal time: %g s each; spp = SEC / (seconds per spp measured on calibration renders of 1, 2, 4... spp "
                               "lasting %.3g s); time = the final render's wall-clock time, %d threads.\n",
                               c->time, CALIB_FRACTION * c->time, c->base.ro.threads);
    else
        nn += (size_t)snprintf(notes + nn, sizeof notes - nn, "- equal samples: %d spp each; time = wall-clock time of the render, %d threads.\n",
                               c->spp, c->base.ro.threads);
    snprintf(notes + nn, sizeof notes - nn, "- heatmaps (heat-LABEL.png): |image - reference| averaged over RGB, black 0 to white %.4g.\n", scale);
    if (make_legend(&legend, w, h) || make_mosaic(&mosaic, c, &ref, ref_label, &legend, scale, c->base.exposure)) goto done;
    if (out_path(path, sizeof path, c->dir, "", "mosaic", ".ppm") || img_write(&mosaic, path, 0.0f)) goto done;
    if (out_path(path, sizeof path, c->dir, "", "mosaic", ".png") || img_write(&mosaic, path, 0.0f)) goto done;
    if (out_path(path, sizeof path, c->dir, "", "table", ".md") || write_text(path, c, notes, 0)) goto done;
    if (out_path(path, sizeof path, c->dir, "", "table", ".csv") || write_text(path, c, notes, 1)) goto done;
    print_table(stdout, c, 0);
    printf("\n%s", notes);
    printf("(mosaic %dx%d in %s/mosaic.png; images, heatmaps and table.md, table.csv in %s)\n", mosaic.w, mosaic.h, c->dir, c->dir);
    rc = 0;
done:
    img_free(&ref);
    img_free(&ref_var);
    img_free(&legend);
    img_free(&mosaic);
    return rc;
}

int compare_main(int argc, char **argv)
{
    compare_args *c = calloc(1, sizeof *c);
    scene s;
    int rc = 2, i, k;
    if (!c) { fprintf(stderr, "pathlab: compare: out of memory\n"); return 1; }
    if (!parse_args(c, argc, argv) && !scene_load(&s, c->base.scene, c->base.ro.threads, 1)) {
        if (s.lights.n == 0) fprintf(stderr, "pathlab: warning: %s has no emitters: every image is black\n", c->base.scene);
        rc = run(c, &s);
        scene_free(&s);
    }
    for (i = 0; i < MAX_EST; i++) {
        for (k = 0; k < c->est[i].ntok; k++) free(c->est[i].tok[k]);
        img_free(&c->est[i].img);
        img_free(&c->est[i].heat);
    }
    free(c);
    return rc;
}
