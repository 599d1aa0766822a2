/* grade_diagnose.c — the catalogue of likely mistakes (see grade_diagnose.h).
 *
 * A hypothesis is a mistake M with a way to undo it: either on the image (a flip, a factor: the
 * image is turned back and graded against the reference) or on the reference (a curve, a clamp,
 * bounces left out: the reference is made as M would make it and the image graded against it). The
 * statistics are those of the verdict, same alpha: "grading the flipped image passes" is a claim
 * with the verdict's false-alarm rate. A hypothesis must also halve the worst statistic: an image
 * just beyond a limit (a false alarm, 1 in 100) passes under almost any change, and flipping a
 * symmetric scene explains nothing. Bounce hypotheses need the per-bounce layers of the reference
 * (REF_split_L0.pfm, ... from `render --split`); their noise adds to the reference's, which the
 * grading takes as part of the difference's scatter. */
#include "grade/grade_diagnose.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "math/vec.h"

typedef struct {
    const image *img;
    const grade_refs *refs;
    const grade_opts *o;
    double excess0;
    grade_hypothesis *out;
    int max, n, oom;
    double energy0, energy0_sd;   /* the image's bias energy as it is (grade_bias_energy) */
    image a, b, c;       /* scratch: a transformed image, a transformed reference, c with outliers masked */
} diag;

static size_t nvalues(const image *im) { return 3 * (size_t)im->w * im->h; }

/* Keeps a hypothesis if it explains: passes, or brings the worst statistic well down. */
static void keep(diag *d, const char *what, const char *evidence, double excess, int passes)
{
    grade_hypothesis *h;
    int k;
    for (k = 0; k < d->n; k++) if (!strcmp(d->out[k].what, what)) return;   /* told by the values already */
    if (d->n >= d->max) return;
    h = &d->out[d->n++];
    snprintf(h->what, sizeof h->what, "%s", what);
    snprintf(h->evidence, sizeof h->evidence, "%s", evidence);
    h->excess = excess;
    h->passes = passes;
}

/* What grading under a hypothesis gave. */
typedef struct {
    double excess, energy, energy_sd;   /* grade_excess, grade_bias_energy and its sd */
    int passes;
} outcome;

static int grade_outcome(diag *d, const image *img, const image *ref, outcome *o, grade_report *keep_report)
{
    grade_report r;
    if (grade_compute(&r, img, ref, d->refs->var, d->o)) { d->oom = 1; return 1; }
    o->excess = grade_excess(&r);
    o->passes = !grade_failed(&r);
    o->energy = grade_bias_energy(&r, &o->energy_sd);
    if (keep_report) *keep_report = r;
    else grade_free(&r);
    return 0;
}

static int by_score(const void *pa, const void *pb)
{
    double a = ((const double *)pa)[0], b = ((const double *)pb)[0];
    return (a < b) - (a > b);
}

/* How far pixel p stands out: infinite for a missed exact pixel, else the largest over the channels
 * of |d - its block's mean d| over the block's scatter. */
static double outlier_score(const grade_report *r, const image *img, const image *ref, size_t p)
{
    int bx = (int)(p % (size_t)r->w) / r->block, by = (int)(p / (size_t)r->w) / r->block, ch;
    const grade_block *g = &r->blocks[(by < r->nby ? by : r->nby - 1) * r->nbx + (bx < r->nbx ? bx : r->nbx - 1)];
    double z = 0.0;
    for (ch = 0; ch < 3; ch++) {
        double dv = (double)img->px[3 * p + ch] - ref->px[3 * p + ch];
        if (r->exact[p] && fabs(dv) > 1e-4 * fabs(ref->px[3 * p + ch]) + 1e-30) return HUGE_VAL;
        if (!r->exact[p] && g->var[ch] > 0.0) z = fmax(z, fabs(dv - g->diff[ch]) / sqrt(g->var[ch]));
    }
    return z;
}

/* d->c = img with the handful of pixels that disagree most (outlier_score above DIAG_OUTLIER_Z, at
 * most DIAG_HANDFUL or 1 in 5,000) given the reference's values: how many. A mistake explains an
 * image even when a few pixels disagree for other reasons (a hot pixel, a missed exact one). */
#define DIAG_OUTLIER_Z 6.0
#define DIAG_HANDFUL 8
static int mask_outliers(diag *d, const grade_report *r, const image *img, const image *ref)
{
    size_t p, n = (size_t)r->w * r->h, m = 0, k, max = n / 5000 > DIAG_HANDFUL ? n / 5000 : DIAG_HANDFUL;
    double *q = malloc(2 * n * sizeof *q);
    if (!q) { d->oom = 1; return 0; }
    for (p = 0; p < n; p++) {
        double z = outlier_score(r, img, ref, p);
        if (z > DIAG_OUTLIER_Z) { q[2 * m] = z; q[2 * m + 1] = (double)p; m++; }
    }
    qsort(q, m, 2 * sizeof *q, by_score);
    if (m > max) m = 0;   /* more than a handful: not a few pixels apart, the hypothesis itself fails */
    memcpy(d->c.px, img->px, 3 * n * sizeof *img->px);
    for (k = 0; k < m; k++) memcpy(&d->c.px[3 * (size_t)q[2 * k + 1]], &ref->px[3 * (size_t)q[2 * k + 1]], 3 * sizeof(float));
    free(q);
    return (int)m;
}

/* 1 if the outcome leaves at most 1% of the image's bias energy (within 2.5 of its sd): a mistake
 * named must explain nearly all of the difference, not its larger part. */
static int explains(const diag *d, const outcome *o)
{
    if (!(d->energy0 > 2.5 * d->energy0_sd)) return 1;   /* no bias energy to speak of: failed on exact pixels or levels */
    return o->energy <= 0.01 * d->energy0 + 2.5 * o->energy_sd;
}

/* Grades img against ref and keeps the hypothesis if it explains: it passes (or nearly), perhaps
 * once a handful of pixels are left out, and leaves at most 1% of the bias; `graded` names what
 * was graded. */
static void judge(diag *d, const image *img, const image *ref, const char *what, const char *graded)
{
    grade_report r;
    outcome o;
    char ev[200], apart[96] = "", was[32];
    int masked = 0;
    if (grade_outcome(d, img, ref, &o, &r)) return;
    if (!o.passes) masked = mask_outliers(d, &r, img, ref);
    grade_free(&r);
    if (masked && grade_outcome(d, &d->c, ref, &o, NULL)) return;
    if (masked) snprintf(apart, sizeof apart, " once %d pixel%s that disagree for other reasons %s left out", masked,
                         masked == 1 ? "" : "s", masked == 1 ? "is" : "are");
    if (!explains(d, &o)) return;
    if (d->excess0 >= 1e9) snprintf(was, sizeof was, "exact pixels missed");
    else snprintf(was, sizeof was, "%.3g", d->excess0);
    if (o.passes && o.excess < 0.5 * d->excess0)
        snprintf(ev, sizeof ev, "grading %s passes%s (worst statistic %.2f of its limit; %s as it is)", graded, apart, o.excess, was);
    else if (o.excess < 0.1 * d->excess0 && o.excess < 3.0)
        snprintf(ev, sizeof ev, "grading %s nearly passes%s: the worst statistic falls from %s to %.2f times its limit",
                 graded, apart, was, o.excess);
    else return;
    keep(d, what, ev, o.excess, o.passes);
}

/* ---- hypotheses on the image: undo the mistake and grade against the reference ---- */

/* out = the image mirrored: mode 1 top-bottom, 2 left-right, 3 both; 4 channels in BGR order. */
static void remap(image *out, const image *in, int mode)
{
    int x, y, c;
    for (y = 0; y < in->h; y++)
        for (x = 0; x < in->w; x++) {
            int sx = mode & 2 && mode != 4 ? in->w - 1 - x : x, sy = mode & 1 ? in->h - 1 - y : y;
            for (c = 0; c < 3; c++)
                out->px[3 * ((size_t)y * in->w + x) + c] = in->px[3 * ((size_t)sy * in->w + sx) + (mode == 4 ? 2 - c : c)];
        }
}

static void try_geometry(diag *d)
{
    remap(&d->a, d->img, 1);
    judge(d, &d->a, d->refs->ref, "flipped vertically, upside down (rows written top to bottom? PFM stores the bottom row first)",
          "the image flipped vertically");
    remap(&d->a, d->img, 2);
    judge(d, &d->a, d->refs->ref, "mirrored left-right (x axis or camera's right vector reversed?)", "the mirrored image");
    remap(&d->a, d->img, 3);
    judge(d, &d->a, d->refs->ref, "turned by 180 degrees (both axes reversed)", "the image turned by 180 degrees");
    remap(&d->a, d->img, 4);
    judge(d, &d->a, d->refs->ref, "red and blue swapped (channels written as BGR)", "the image with red and blue swapped");
}

static void scale_into(image *out, const image *in, double f)
{
    size_t i;
    for (i = 0; i < nvalues(in); i++) out->px[i] = (float)(in->px[i] * f);
}

/* The named factors a student's formula can be off by, then the fitted one. */
static double fitted_factor(diag *d);

static void try_factors(diag *d)
{
    static const struct { double f; const char *name, *why; } F[] = {
        {PI, "pi", "a 1/pi missing? (the diffuse BRDF is Kd/pi)"},
        {1.0 / PI, "1/pi", "divided by pi once too often? (Kd/pi with a cosine pdf cos/pi: the pis cancel)"},
        {2.0, "2", "a factor 2 (a pdf of one hemisphere used for the whole sphere, or two estimators added without weights?)"},
        {0.5, "1/2", "half (a pdf of the whole sphere for a hemisphere, or two estimators each weighted 1/2 but one missing?)"},
        {2.0 * PI, "2 pi", "a 1/(2 pi) missing (the uniform hemisphere pdf)"},
        {1.0 / (2.0 * PI), "1/(2 pi)", "divided by 2 pi once too often"},
        {4.0 * PI, "4 pi", "a 1/(4 pi) missing (the uniform sphere pdf)"}};
    char what[160], graded[64];
    size_t k;
    int named = 0;
    double fitted;
    for (k = 0; k < sizeof F / sizeof F[0]; k++) {
        int before = d->n;
        scale_into(&d->a, d->img, 1.0 / F[k].f);
        snprintf(what, sizeof what, "%s times the reference: %s", F[k].name, F[k].why);
        snprintf(graded, sizeof graded, "the image divided by %s", F[k].name);
        judge(d, &d->a, d->refs->ref, what, graded);
        named += d->n > before;
    }
    if (named) return;
    fitted = fitted_factor(d);   /* only now: its search grades the image some 14 times */
    if (!(fitted > 0.0) || fabs(fitted - 1.0) < 1e-3) return;
    scale_into(&d->a, d->img, 1.0 / fitted);
    snprintf(what, sizeof what, "a global factor: %.4g times the reference everywhere (fitted)", fitted);
    snprintf(graded, sizeof graded, "the image divided by %.4g", fitted);
    judge(d, &d->a, d->refs->ref, what, graded);
}

/* ---- hypotheses on the reference: make it as the mistake would, grade the image against it ---- */

static float srgb_of(float v) { return srgb_encode(fminf(fmaxf(v, 0.0f), 1.0f)); }
/* The curves are undone on the image, not applied to the reference: the student applied them to a
 * noisy pixel, and a curve of the mean is not the mean of the curve (at 4 spp, far from it). */
static float srgb_undo(float v) { return v <= 0.04045f ? v / 12.92f : powf((v + 0.055f) / 1.055f, 2.4f); }
static float gamma_undo(float v) { return powf(fmaxf(v, 0.0f), 2.2f); }
static float clamp1_of(float v) { return fminf(v, 1.0f); }

static void map_into(image *out, const image *in, float (*f)(float))
{
    size_t i;
    for (i = 0; i < nvalues(in); i++) out->px[i] = f(in->px[i]);
}

/* out = the reference in grey: mode 0 the mean of R, G, B; 1 the luminance. */
static void grey_into(image *out, const image *in, int mode)
{
    size_t p;
    for (p = 0; p < (size_t)in->w * in->h; p++) {
        const float *v = &in->px[3 * p];
        float g = mode ? luminance(v3(v[0], v[1], v[2])) : (v[0] + v[1] + v[2]) / 3.0f;
        out->px[3 * p] = out->px[3 * p + 1] = out->px[3 * p + 2] = g;
    }
}

static void try_curves(diag *d)
{
    const image *ref = d->refs->ref;
    map_into(&d->a, d->img, srgb_undo);
    map_into(&d->b, ref, clamp1_of);
    judge(d, &d->a, &d->b, "the sRGB curve applied (and values cut at 1): a PFM holds linear radiance, write it before any display curve",
          "the image decoded from sRGB, against the reference clamped at 1,");
    map_into(&d->a, d->img, gamma_undo);
    judge(d, &d->a, ref, "a gamma curve applied (x^(1/2.2)): a PFM holds linear radiance", "the image to the power 2.2");
    judge(d, d->img, &d->b, "values clamped at 1 (radiance has no maximum: an emitter seen directly is far above 1)",
          "against the reference clamped at 1");
    grey_into(&d->b, ref, 0);
    judge(d, d->img, &d->b, "grey instead of colour", "against the reference's mean of R, G, B");
    grey_into(&d->b, ref, 1);
    judge(d, d->img, &d->b, "grey instead of colour", "against the reference's luminance");
}

/* out = sum of coef[k] layer k, plus whole times the reference. */
static void layers_into(image *out, const grade_refs *refs, const double *coef, double whole)
{
    size_t i;
    int k;
    for (i = 0; i < nvalues(refs->ref); i++) {
        double v = whole * refs->ref->px[i];
        for (k = 0; k < refs->nlayers; k++) v += coef[k] * refs->layer[k]->px[i];
        out->px[i] = (float)v;
    }
}

static void try_bounces(diag *d)
{
    double c[GRADE_MAX_LAYERS];
    char what[160], graded[96];
    int k, j, n = d->refs->nlayers;
    if (n < 2) return;
    memset(c, 0, sizeof c);
    c[0] = -1.0;
    layers_into(&d->b, d->refs, c, 1.0);
    judge(d, d->img, &d->b, "no L0: the emitters seen directly are black (add Le at the first hit)", "against the reference without L0");
    for (k = 1; k < n; k++) {
        for (j = 0; j < n; j++) c[j] = j <= k ? 1.0 : 0.0;
        layers_into(&d->b, d->refs, c, 0.0);
        if (k == 1) snprintf(what, sizeof what, "direct light only (L0 + L1): no indirect bounce");
        else snprintf(what, sizeof what, "stopped after %d bounces (L0 .. L%d): the path ends too early (\"et on arrete quand ?\")", k, k);
        snprintf(graded, sizeof graded, "against L0 + ... + L%d of the reference", k);
        judge(d, d->img, &d->b, what, graded);
    }
    memset(c, 0, sizeof c);
    c[0] = c[1] = -1.0;
    layers_into(&d->b, d->refs, c, 1.0);
    judge(d, d->img, &d->b, "indirect light only (L2 and beyond): L0 and L1 missing", "against the reference without L0 and L1");
    for (k = 1; k < n; k++) {
        memset(c, 0, sizeof c);
        c[k] = -1.0;
        layers_into(&d->b, d->refs, c, 1.0);
        snprintf(what, sizeof what, k == 1 ? "L1 missing: no direct light (the light sample's contribution lost?)" : "L%d missing: one bounce lost", k);
        snprintf(graded, sizeof graded, "against the reference without L%d", k);
        judge(d, d->img, &d->b, what, graded);
    }
}

/* ---- the pixel convention: centres against jittered samples ---- */

static double lum_of(const image *im, size_t p)
{
    return luminance(v3(im->px[3 * p], im->px[3 * p + 1], im->px[3 * p + 2]));
}

/* The variance of a pixel's luminance from the reference's per-channel variance (channels taken
 * as independent), 0 without it. */
static double lum_var(const image *var, size_t p)
{
    static const double w[3] = {0.2126, 0.7152, 0.0722};
    double v = 0.0;
    int ch;
    for (ch = 0; var && ch < 3; ch++) v += w[ch] * w[ch] * var->px[3 * p + ch];
    return v;
}

/* 1 if pixel p of the reference lies on an edge: an 8-neighbour differs by more than a fifth of
 * their sum and by more than 4 standard deviations of the reference's noise. An edge crosses the
 * pixel, which a pixel-centre sample sees on one side and a jittered one averages. */
static int on_edge(const image *ref, const image *var, int x, int y)
{
    double l = lum_of(ref, (size_t)y * ref->w + x), vl = lum_var(var, (size_t)y * ref->w + x);
    int u, v;
    for (v = y - 1; v <= y + 1; v++)
        for (u = x - 1; u <= x + 1; u++) {
            size_t q = (size_t)v * ref->w + u;
            double m;
            if (u < 0 || v < 0 || u >= ref->w || v >= ref->h || (u == x && v == y)) continue;
            m = lum_of(ref, q);
            if (fabs(l - m) > 0.2 * (l + m) && (l - m) * (l - m) > 16.0 * (vl + lum_var(var, q))) return 1;
        }
    return 0;
}

/* Pixel centres against a jittered reference, or the reverse: the image differs on the edges only,
 * brighter on some and darker on others (which side of the pixel's centre the edge passes), and
 * the interiors agree. Tested by grading with the edge pixels given the reference's values, once
 * the differences there are seen to have both signs (at least 5% of them each way: a straight edge
 * along a row of pixels is off the same way all along, so one sign may well dominate). */
static void try_pixel_convention(diag *d)
{
    const image *ref = d->refs->ref, *img = d->img;
    size_t p, n = (size_t)img->w * img->h, nedge = 0;
    double up = 0.0, down = 0.0;
    char what[160], graded[160];
    memcpy(d->a.px, img->px, 3 * n * sizeof *img->px);
    for (p = 0; p < n; p++) {
        double dl;
        if (!on_edge(ref, d->refs->var, (int)(p % (size_t)img->w), (int)(p / (size_t)img->w))) continue;
        nedge++;
        dl = lum_of(img, p) - lum_of(ref, p);
        up += fmax(dl, 0.0);
        down += fmax(-dl, 0.0);
        memcpy(&d->a.px[3 * p], &ref->px[3 * p], 3 * sizeof(float));
    }
    if (nedge == 0 || 10 * nedge > 3 * n || fmin(up, down) < 0.05 * (up + down)) return;
    snprintf(what, sizeof what, "%s", d->refs->pixel_center == 1
             ? "jittered in the pixel against a reference shot through pixel centres: render the reference without --pixel-center"
             : d->refs->pixel_center == 0 ? "pixel centres against a jittered reference (gKit's Point(x + .5f, y + .5f)): render the reference with --pixel-center"
             : "pixel centres against a jittered reference, or the reverse: render the reference with --pixel-center (or without)");
    snprintf(graded, sizeof graded, "the image with its %zu edge pixels (%.1f%%; %.0f%% of their difference up, %.0f%% down) given the reference's values", nedge,
             100.0 * nedge / n, 100.0 * up / (up + down), 100.0 * down / (up + down));
    judge(d, &d->a, ref, what, graded);
}

/* ---- evidence from the values alone ---- */

static int all_values(const image *im, int (*test)(float))
{
    size_t i;
    for (i = 0; i < nvalues(im); i++) if (!test(im->px[i])) return 0;
    return 1;
}

/* v = k / 255 for some k, 0 itself or k >= 1: a value far below 1/255 is no byte (an image scaled by
 * 1e-30 was called quantised, each of its values within 1e-3 of 0 / 255) */
static int is_8bit(float v)
{
    return v == 0.0f || (v * 255.0f >= 0.5f && v <= 1.0f && fabsf(v * 255.0f - floorf(v * 255.0f + 0.5f)) < 1e-3f);
}

/* v = decode(k / 255) of the sRGB curve for some k (0 itself or k >= 1): the linear value of an 8-bit sRGB byte */
static int is_8bit_srgb(float v)
{
    float e = srgb_of(v) * 255.0f;
    return v == 0.0f || (e >= 0.5f && v <= 1.0f && fabsf(e - floorf(e + 0.5f)) < 2e-2f);
}

static int is_grey(const image *im, double tol)
{
    size_t p;
    for (p = 0; p < (size_t)im->w * im->h; p++) {
        const float *v = &im->px[3 * p];
        double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
        if (fabs(v[0] - v[1]) > tol * m || fabs(v[1] - v[2]) > tol * m) return 0;
    }
    return 1;
}

static float max_value(const image *im)
{
    size_t i;
    float m = 0.0f;
    for (i = 0; i < nvalues(im); i++) m = fmaxf(m, im->px[i]);
    return m;
}

static void try_values(diag *d)
{
    const image *img = d->img, *ref = d->refs->ref;
    char ev[200];
    size_t i, ones = 0;
    float rmax = max_value(ref);
    if (max_value(img) == 0.0f && rmax > 0.0f) {
        keep(d, "a black image: no light reached the camera (emitters not read from the MTL's Ke? Le never added?)",
             "every value of the image is 0 or below", 0.0, 1);
        return;
    }
    if (all_values(img, is_8bit))
        keep(d, "quantised to 8 bits: every value is a multiple of 1/255 (the image went through PNG/PPM or bytes before the PFM)",
             "seen in the values", 0.0, 1);
    else if (all_values(img, is_8bit_srgb))
        keep(d, "quantised to 8 bits through the sRGB curve (an 8-bit image decoded back to linear)", "seen in the values", 0.0, 1);
    if (is_grey(img, 1e-6) && !is_grey(ref, 1e-2))
        keep(d, "grey instead of colour", "R = G = B in every pixel of the image, the reference is in colour", 0.0, 1);
    for (i = 0; i < nvalues(img); i++) ones += img->px[i] == 1.0f;
    if (max_value(img) <= 1.0f && rmax > 1.05f && ones > 0) {
        snprintf(ev, sizeof ev, "no value above 1 and %zu at exactly 1, while the reference reaches %.3g", ones, rmax);
        keep(d, "values clamped at 1 (radiance has no maximum: an emitter seen directly is far above 1)", ev, 0.0, 1);
    }
}

/* The step of an RGBE pixel whose largest channel is vmax: its mantissa lies in [128, 256), so the
 * step is 2^(floor(log2 vmax) - 7); 0 for a black pixel. */
static double rgbe_step(double vmax)
{
    int e;
    if (!(vmax > 0.0)) return 0.0;
    frexp(vmax, &e);
    return ldexp(1.0, e - 8);
}

/* 1 if at least 99.9% of the image's lit pixels (and 16 or more) hold whole multiples of their RGBE
 * step in every channel: an RGBE file decoded without the half step, (m + 0.5) step being the
 * unbiased value. */
static int rgbe_truncated(const image *im)
{
    size_t p, lit = 0, on = 0;
    for (p = 0; p < (size_t)im->w * im->h; p++) {
        const float *v = &im->px[3 * p];
        double step = rgbe_step(fmax(v[0], fmax(v[1], v[2]))), q;
        int ch, whole = 1;
        if (step == 0.0) continue;
        lit++;
        for (ch = 0; ch < 3; ch++) {
            q = v[ch] / step;
            whole &= v[ch] >= 0.0f && fabs(q - floor(q + 0.5)) < 1e-3;
        }
        on += whole;
    }
    return lit >= 16 && on >= lit - lit / 1000;
}

/* The image of an RGBE file decoded without the half step: half a step low in every channel of
 * every lit pixel, a relative bias of -0.5 / m (m the channel's mantissa: -0.2% to -0.4% on the
 * largest channel, percents on small ones). Undone: half a step added. */
static void try_rgbe(diag *d)
{
    size_t p;
    int ch, before = d->n;
    const char *what = "RGBE truncated without the half step: a .hdr decoded as gKit's and OpenImageIO's decoders do, "
                       "m 2^(e-136) for (m + 0.5) 2^(e-136)";
    if (!rgbe_truncated(d->img)) return;
    for (p = 0; p < (size_t)d->img->w * d->img->h; p++) {
        const float *v = &d->img->px[3 * p];
        double step = rgbe_step(fmax(v[0], fmax(v[1], v[2])));
        for (ch = 0; ch < 3; ch++) d->a.px[3 * p + ch] = (float)(v[ch] + 0.5 * step);
    }
    judge(d, &d->a, d->refs->ref, what, "the image with half an RGBE step added");
    if (d->n == before)
        keep(d, what, "seen in the values: every lit pixel holds whole multiples of its RGBE step (m 2^(e-136), no half step)", 0.0, 1);
}

/* ---- the catalogue ---- */

static int by_strength(const void *pa, const void *pb)
{
    const grade_hypothesis *a = pa, *b = pb;
    if (a->passes != b->passes) return b->passes - a->passes;
    return (a->excess > b->excess) - (a->excess < b->excess);
}

/* The worst statistic of the image divided by f (scratch in d->a); 1e30 when out of memory. */
static double excess_scaled(diag *d, double f)
{
    grade_report r;
    double e;
    scale_into(&d->a, d->img, 1.0 / f);
    if (grade_compute(&r, &d->a, d->refs->ref, d->refs->var, d->o)) { d->oom = 1; return 1e30; }
    e = grade_excess(&r);
    grade_free(&r);
    return e;
}

/* The global factor that best explains the image: the one that minimises the worst statistic of
 * image / f, by golden-section search between the factors the whole-image fit and the plain mean
 * suggest (widened by a tenth). The fit alone is not enough: it weighs the blocks, while the lamp's
 * level, far more precise, may want another value (x 1.02 fitted as 1.024 left the lamp -0.4% off,
 * which its level sees). */
static double fitted_factor(diag *d)
{
    grade_report r;
    double fit, plain, lo, hi, a, b, ea, eb;
    const double g = 0.6180339887498949;
    int k;
    if (grade_compute(&r, d->img, d->refs->ref, d->refs->var, d->o)) { d->oom = 1; return 1.0; }
    fit = 1.0 + (r.image_eps[0] + r.image_eps[1] + r.image_eps[2]) / 3.0;
    plain = r.image_ref[0] + r.image_ref[1] + r.image_ref[2];
    plain = plain > 0.0 ? 1.0 + (r.image_diff[0] + r.image_diff[1] + r.image_diff[2]) / plain : fit;
    grade_free(&r);
    if (!(fit > 0.0) || !(plain > 0.0)) return 1.0;
    lo = fmin(fit, plain) / 1.1;
    hi = fmax(fit, plain) * 1.1;
    a = hi - g * (hi - lo);
    b = lo + g * (hi - lo);
    ea = excess_scaled(d, a);
    eb = excess_scaled(d, b);
    for (k = 0; k < 12 && !d->oom; k++) {   /* the interval shrinks 0.618^12 = 0.3%: the factor to 4 digits */
        if (ea < eb) { hi = b; b = a; eb = ea; a = hi - g * (hi - lo); ea = excess_scaled(d, a); }
        else { lo = a; a = b; ea = eb; b = lo + g * (hi - lo); eb = excess_scaled(d, b); }
    }
    return ea < eb ? a : b;
}

int grade_diagnose(const image *img, const grade_refs *refs, const grade_opts *o, double excess0,
                   grade_hypothesis *out, int max)
{
    diag d;
    memset(&d, 0, sizeof d);
    d.img = img;
    d.refs = refs;
    d.o = o;
    d.excess0 = excess0;
    d.out = out;
    d.max = max;
    if (img_alloc(&d.a, img->w, img->h) || img_alloc(&d.b, img->w, img->h) || img_alloc(&d.c, img->w, img->h)) {
        img_free(&d.a);
        img_free(&d.b);
        return -1;
    }
    {
        outcome o0;
        if (!grade_outcome(&d, img, refs->ref, &o0, NULL)) d.energy0 = o0.energy, d.energy0_sd = o0.energy_sd;
    }
    try_values(&d);
    try_rgbe(&d);
    try_geometry(&d);
    try_pixel_convention(&d);
    try_curves(&d);
    try_bounces(&d);
    try_factors(&d);
    img_free(&d.a);
    img_free(&d.b);
    img_free(&d.c);
    if (d.oom) return -1;
    qsort(out, (size_t)d.n, sizeof *out, by_strength);
    return d.n;
}
