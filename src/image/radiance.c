/* radiance.c — the NaN, infinite and negative values of an image, counted and located. */
#include "image/radiance.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>

enum { K_NAN, K_PINF, K_NINF, K_NEG, K_TINY, K_KINDS };

typedef struct {
    long count, at[RADIANCE_MAX_LISTED];   /* at: indices into px of the first ones */
    int listed;
    float worst;                           /* the most negative value (K_NEG, K_TINY) */
} rad_kind;

double img_typical_abs(const image *im)
{
    long i, n = 3L * im->w * im->h, count[256] = {0}, nonzero = 0, below = 0;
    int e;
    for (i = 0; i < n; i++) {
        float v = im->px[i];
        if (!(v - v == 0.0f) || v == 0.0f) continue;
        (void)frexpf(v, &e);   /* |v| in [2^(e-1), 2^e) */
        count[e + 150 < 0 ? 0 : e + 150 > 255 ? 255 : e + 150]++;
        nonzero++;
    }
    for (e = 0; e < 256; e++)
        if ((below += count[e]) * 2 >= nonzero && nonzero) return ldexp(1.0, e - 150 - 1);
    return 0.0;
}

/* The kind of v, or -1 for a good radiance value (>= 0, -0.0 included). */
static int kind_of(float v, double tol)
{
    if (v != v) return K_NAN;
    if (v - v != 0.0f) return v > 0.0f ? K_PINF : K_NINF;
    if (!(v < 0.0f)) return -1;
    return v < -tol ? K_NEG : K_TINY;
}

static void print_kind(const image *im, const char *path, const rad_kind *k, int kind, double mean)
{
    static const char *const what[K_KINDS] = { "NaN", "+Inf", "-Inf", "negative", "slightly negative" };
    static const char *const channel[3] = { "red", "green", "blue" };
    int j;
    fprintf(stderr, "%s: %s%ld pixel-channel%s %s %s", shown(path), kind == K_TINY ? "warning: " : "", k->count,
            k->count == 1 ? "" : "s", k->count == 1 ? "is" : "are", what[kind]);
    if (kind == K_NEG)
        fprintf(stderr, " (below -%g x %.3g, the median |value| rounded down to a power of 2; down to %.3g)", RADIANCE_NEG_TOL, mean, k->worst);
    if (kind == K_TINY)
        fprintf(stderr, " (down to %.3g, within %g x %.3g, the median |value| rounded down to a power of 2: float rounding?)",
                k->worst, RADIANCE_NEG_TOL, mean);
    for (j = 0; j < k->listed; j++) {
        long i = k->at[j], p = i / 3;
        fprintf(stderr, "%s x %ld, y %ld (%s", j == 0 ? (k->count == 1 ? ", at" : ", first at") : ",",
                p % im->w, p / im->w, channel[i % 3]);
        if (kind >= K_NEG) fprintf(stderr, " %.3g", im->px[i]);
        fprintf(stderr, ")");
    }
    fprintf(stderr, "%s; y = 0 is the top row\n", k->count > k->listed ? ", ..." : "");
}

int img_check_radiance(const image *im, const char *path, int max_listed)
{
    rad_kind k[K_KINDS] = { { 0, { 0 }, 0, 0.0f } };
    long i, n = 3L * im->w * im->h;
    double mean = img_typical_abs(im), tol = RADIANCE_NEG_TOL * mean;
    int kind, bad = 0;
    if (max_listed < 0) max_listed = 0;
    if (max_listed > RADIANCE_MAX_LISTED) max_listed = RADIANCE_MAX_LISTED;
    for (i = 0; i < n; i++) {
        kind = kind_of(im->px[i], tol);
        if (kind < 0) continue;
        if (k[kind].listed < max_listed) k[kind].at[k[kind].listed++] = i;
        if (k[kind].count++ == 0 || im->px[i] < k[kind].worst) k[kind].worst = im->px[i];
    }
    for (kind = 0; kind < K_KINDS; kind++) {
        if (k[kind].count == 0) continue;
        print_kind(im, path, &k[kind], kind, mean);
        if (kind != K_TINY) bad = 1;
    }
    if (bad)
        fprintf(stderr, "%s: radiance is a finite number >= 0 in every pixel-channel (NaN: 0/0 or the root of a "
                "negative number? Inf: a division by a zero pdf? negative: a negative weight or BRDF?)\n", shown(path));
    return bad;
}
