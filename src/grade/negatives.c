/* negatives.c — negative radiance located and explained (negatives.h). */
#include "grade/negatives.h"
#include <math.h>
#include <stdio.h>
#include "grade/grade_print.h"
#include "image/radiance.h"
#include "math/vec.h"

enum { ON_BLACK, ON_EDGE, ON_LIT, KINDS };

static double lum_at(const image *im, int x, int y)
{
    const float *v = &im->px[3 * ((size_t)y * im->w + x)];
    return luminance(v3(v[0], v[1], v[2]));
}

/* Where the reference is black (below 1e-3 of its mean luminance: no direct light reaches there),
 * on an edge (a 4-neighbour differs by more than half their sum: a silhouette, a crease, a shadow's
 * border), or lit. */
static int kind_at(const image *ref, int x, int y, double mean)
{
    static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    double l = lum_at(ref, x, y);
    int k;
    if (l <= 1e-3 * mean) return ON_BLACK;
    for (k = 0; k < 4; k++) {
        int u = x + dx[k], v = y + dy[k];
        double m;
        if (u < 0 || v < 0 || u >= ref->w || v >= ref->h) continue;
        m = lum_at(ref, u, v);
        if (fabs(l - m) > 0.5 * (l + m)) return ON_EDGE;
    }
    return ON_LIT;
}

static const char *const CAUSE[KINDS] = {
    "likely an unclamped cos theta at the light: light leaving the back of the emitter counts, negative "
    "(use max(0, dot(n_light, -l)), the emitter lights its front side only)",
    "likely an unclamped cos theta at the surface: a normal facing away from the light at silhouettes and creases "
    "(use max(0, dot(n, l)))",
    "an unclamped cosine (at the light or at the surface), or a negative weight or BRDF"};
static const char *const WHERE[KINDS] = {"where the reference is black (behind the light, or facing away from it)",
                                         "on edges (silhouettes, creases, shadow borders)", "on lit surfaces"};

int grade_explain_negatives(char *out, size_t cap, const image *img, const image *ref)
{
    long count[KINDS] = {0, 0, 0}, n = 0;
    int x, y, k, box[4] = {1 << 30, 1 << 30, 0, 0}, most = 0, first;
    double mean_img, mean_ref = 0.0;
    char where[64];
    size_t used;
    out[0] = '\0';
    mean_img = img_typical_abs(img);
    for (y = 0; y < ref->h; y++) for (x = 0; x < ref->w; x++) mean_ref += lum_at(ref, x, y) / ((double)ref->w * ref->h);
    for (y = 0; y < img->h; y++)
        for (x = 0; x < img->w; x++) {
            const float *v = &img->px[3 * ((size_t)y * img->w + x)];
            if (!(fminf(v[0], fminf(v[1], v[2])) < -RADIANCE_NEG_TOL * mean_img)) continue;
            n++;
            count[kind_at(ref, x, y, mean_ref)]++;
            if (x < box[0]) box[0] = x;
            if (y < box[1]) box[1] = y;
            if (x + 1 > box[2]) box[2] = x + 1;
            if (y + 1 > box[3]) box[3] = y + 1;
        }
    if (!n) return 0;
    for (k = 1; k < KINDS; k++) if (count[k] > count[most]) most = k;
    grade_describe_box(where, sizeof where, box[0], box[1], box[2], box[3], img->w, img->h);
    used = (size_t)snprintf(out, cap, "negative radiance in %ld pixels, within x %d..%d, y %d..%d (%s):", n, box[0], box[2] - 1,
                            box[1], box[3] - 1, where);
    for (k = 0, first = 1; k < KINDS && used < cap; k++)
        if (count[k]) used += (size_t)snprintf(out + used, cap - used, "%s %ld %s", first ? "" : ",", count[k], WHERE[k]), first = 0;
    if (used < cap) snprintf(out + used, cap - used, "; %s", 2 * count[most] > n ? CAUSE[most] : CAUSE[ON_LIT]);
    return 1;
}
