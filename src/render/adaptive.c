/* adaptive.c — the pilot, the per-pixel counts it decides, and the render of the kept samples. */
#include "render/adaptive.h"
#include "math/rng.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void adaptive_opts_init(adaptive_opts *ao)
{
    memset(ao, 0, sizeof *ao);
    ao->pilot = 16;
    ao->min_spp = 4;
    ao->dark = 0.1;
    ao->spread = 1;
    ao->pilot_rr_below = 1.0f;
}

/* A constant of its own ("pilot" in ASCII) hashed with the seed: the pilot's streams are keyed by
 * another seed than any kept stream of this render (pcg32_for_sample hashes (seed, p, i)). */
static uint64_t adaptive_pilot_seed(uint64_t seed) { return splitmix64_mix(seed ^ 0x70696c6f74ULL) + SPLITMIX64_GAMMA; }

/* The level d below which a pixel's error is held to d instead of its own mean: dark x the
 * image's mean (of the channels' absolute values), so that black corners do not take every sample. */
static double dark_level(const image *m, double dark)
{
    size_t n = 3 * (size_t)m->w * (size_t)m->h, i;
    double sum = 0;
    for (i = 0; i < n; i++) sum += fabs(m->px[i]);
    return n ? dark * sum / (double)n : 0.0;
}

/* rel[p]: each pixel's relative variance per sample, s^2 / max(|m|, d)^2, the largest of its three
 * channels (each channel is held to E; zcheck and grade test channels). 0 where the pilot saw nothing. */
static void relative_variance(const image *m, const image *v, int pilot, double d, double *rel)
{
    size_t npx = (size_t)m->w * (size_t)m->h, p;
    int c;
    for (p = 0; p < npx; p++) {
        double r = 0;
        for (c = 0; c < 3; c++) {
            double level = fmax(fabs(m->px[3 * p + c]), d), s2 = (double)v->px[3 * p + c] * pilot;
            if (level > 0 && s2 / (level * level) > r) r = s2 / (level * level);
        }
        rel[p] = r;
    }
}

/* out[p] = the largest rel of the 3x3 pixels around p: a pixel whose pilot was lucky (it missed
 * the light's sliver or a rare bright path its neighbours found) is not starved. */
static void spread_max(const double *rel, int w, int h, double *out)
{
    int x, y, dx, dy;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double r = 0;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && rel[yy * w + xx] > r) r = rel[yy * w + xx];
                }
            out[y * w + x] = r;
        }
}

/* x samples rounded up to the group size and clamped to [min_spp, cap]. */
static int clamp_count(double x, int min_spp, int cap)
{
    double g = ADAPTIVE_GROUP, n = ceil(fmax(x, (double)min_spp) / g) * g;
    return n >= cap ? cap : (int)n;
}

/* The counts lambda x sqrt(rel), and their sum. */
static double counts_for(const double *rel, size_t npx, double lambda, int min_spp, int cap, int *n)
{
    double sum = 0;
    size_t p;
    for (p = 0; p < npx; p++) sum += n[p] = clamp_count(lambda * sqrt(rel[p]), min_spp, cap);
    return sum;
}

/* The largest scale lambda whose counts add up to at most budget (by bisection: the sum grows with
 * lambda); at least min_spp each whatever the budget. n proportional to the relative standard
 * deviation minimises the sum of the pixels' relative variances rel/n for a given sum of n. */
static void counts_for_budget(const double *rel, size_t npx, int min_spp, int cap, double budget, int *n)
{
    double lo = 0, hi = 1;
    int k;
    while (hi < 1e30 && counts_for(rel, npx, hi, min_spp, cap, n) < budget) hi *= 2;
    for (k = 0; k < 100; k++) {
        double mid = 0.5 * (lo + hi);
        if (counts_for(rel, npx, mid, min_spp, cap, n) <= budget) lo = mid;
        else hi = mid;
    }
    counts_for(rel, npx, lo, min_spp, cap, n);
}

/* n(x) from a pilot's mean m and variance of the mean v (pilot samples per pixel) into n, each in
 * [min_spp, cap] and a multiple of ADAPTIVE_GROUP (or cap). With a target error, n(x) =
 * ceil(s^2 / (E^2 max(|m|, d)^2)); else the counts are proportional to the relative standard
 * deviation s / max(|m|, d), scaled so that they add up to about `budget` pixel-samples. */
static void adaptive_allocate(const image *m, const image *v, int pilot, const adaptive_opts *ao, int cap, double budget, int *n)
{
    size_t npx = (size_t)m->w * (size_t)m->h, p;
    int min_spp = ao->min_spp < cap ? ao->min_spp : cap;
    double *rel = malloc(2 * npx * sizeof *rel), *use;
    if (!rel) {   /* no room to choose: every pixel its minimum, still unbiased */
        for (p = 0; p < npx; p++) n[p] = min_spp;
        return;
    }
    relative_variance(m, v, pilot, dark_level(m, ao->dark), rel);
    use = rel;
    if (ao->spread) spread_max(rel, m->w, m->h, use = rel + npx);
    if (ao->target_error > 0)
        for (p = 0; p < npx; p++) n[p] = clamp_count(fmin(use[p] / (ao->target_error * ao->target_error), 2.0 * cap), min_spp, cap);
    else counts_for_budget(use, npx, min_spp, cap, budget, n);
    free(rel);
}

/* The pilot: `pilot` samples per pixel from the pilot's seed, the total only, no time limit. */
static int run_pilot(const scene *sc, const camera *cam, const render_opts *o, const adaptive_opts *ao,
                     render_result *pr, adaptive_result *ar)
{
    render_opts po = *o;
    po.spp = ao->pilot;
    po.first = 0;
    po.seed = ar->pilot_seed = adaptive_pilot_seed(o->seed);
    po.split = 0;
    po.time_limit = 0;
    po.pixel_spp = NULL;
    po.sampler = SAMPLER_INDEPENDENT;   /* its variance per sample must be that of independent samples */
    po.io.rr_below = ao->pilot_rr_below;
    if (render(sc, cam, &po, pr)) return 1;
    ar->pilot_seconds = pr->seconds;
    ar->pilot_spp = pr->spp;
    return 0;
}

/* ar->count and its mean, from n(x) and the passes reached. */
static void fill_counts(adaptive_result *ar, int reached)
{
    size_t npx = (size_t)ar->count.w * (size_t)ar->count.h, p;
    double sum = 0;
    for (p = 0; p < npx; p++) {
        int n = ar->pixel_spp[p] < reached ? ar->pixel_spp[p] : reached;
        ar->count.px[3 * p] = ar->count.px[3 * p + 1] = ar->count.px[3 * p + 2] = (float)n;
        sum += n;
    }
    ar->mean_spp = npx ? sum / (double)npx : 0;
}

int adaptive_render(const scene *sc, const camera *cam, const render_opts *o, const adaptive_opts *ao,
                    render_result *out, adaptive_result *ar)
{
    size_t npx = (size_t)cam->width * (size_t)cam->height, p;
    render_result pr;
    render_opts ko = *o;
    double left, budget;
    int maxn = 0, rc;
    memset(ar, 0, sizeof *ar);
    memset(out, 0, sizeof *out);
    ar->pixel_spp = malloc(npx * sizeof *ar->pixel_spp);
    if (!ar->pixel_spp || img_alloc(&ar->count, cam->width, cam->height)) {
        fprintf(stderr, "pathlab: out of memory for a %dx%d image's sample counts\n", cam->width, cam->height);
        adaptive_result_free(ar);
        return 1;
    }
    if (run_pilot(sc, cam, o, ao, &pr, ar)) { adaptive_result_free(ar); return 1; }
    left = ao->time_limit - ar->pilot_seconds;
    /* with a time budget: the pixel-samples left at the pilot's speed */
    budget = left > 0 && pr.seconds > 0 ? left * (double)ar->pilot_spp * (double)npx / pr.seconds : 0;
    adaptive_allocate(&pr.mean[0], &pr.var[0], ar->pilot_spp, ao, o->spp, budget, ar->pixel_spp);
    render_result_free(&pr);
    for (p = 0; p < npx; p++) maxn = ar->pixel_spp[p] > maxn ? ar->pixel_spp[p] : maxn;
    ko.spp = ar->max_spp = maxn;
    ko.first = 0;
    ko.pixel_spp = ar->pixel_spp;
    ko.time_limit = ao->time_limit > 0 ? fmax(left, 1e-9) : 0;   /* 0 would mean no limit */
    if ((rc = render(sc, cam, &ko, out)) != 0) { adaptive_result_free(ar); return rc; }
    fill_counts(ar, out->spp);
    return 0;
}

void adaptive_result_free(adaptive_result *ar)
{
    free(ar->pixel_spp);
    ar->pixel_spp = NULL;
    img_free(&ar->count);
}

void adaptive_print_summary(const adaptive_result *ar, double seconds)
{
    size_t npx = (size_t)ar->count.w * (size_t)ar->count.h, p;
    float lo = npx ? ar->count.px[0] : 0, hi = lo;
    for (p = 0; p < npx; p++) {
        float n = ar->count.px[3 * p];
        lo = n < lo ? n : lo;
        hi = n > hi ? n : hi;
    }
    fprintf(stderr, "adaptive: pilot %d spp in %.2f s (not kept), then %.0f..%.0f spp per pixel, mean %.1f, in %.2f s; "
                    "%.2f Msamples/s kept\n", ar->pilot_spp, ar->pilot_seconds, lo, hi, ar->mean_spp, seconds,
            seconds > 0 ? ar->mean_spp * (double)npx / seconds * 1e-6 : 0.0);
}
