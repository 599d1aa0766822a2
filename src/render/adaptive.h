/* adaptive.h — adaptive sampling that stays unbiased: a pilot render of a few samples per pixel,
 * from streams that are never kept (another seed), decides each pixel's sample count n(x); then
 * the kept samples 0 .. n(x) - 1 of pixel x are rendered exactly as a uniform render renders them
 * (render_opts.pixel_spp), so pixel x's value is that of a --spp n(x) render at x. n(x) depends
 * only on the pilot, which is independent of the kept samples: the mean of n(x) kept samples is
 * unbiased whatever n(x) is. docs/adaptive.md has the why and the figures. */
#ifndef PATHLAB_ADAPTIVE_H
#define PATHLAB_ADAPTIVE_H
#include "render/render.h"

typedef struct {
    double target_error;   /* relative standard error wanted of each pixel's mean (0: the time decides) */
    double time_limit;     /* seconds for the pilot and the render together (0: none) */
    int pilot;             /* pilot samples per pixel (>= 2) */
    int min_spp;           /* the fewest samples a pixel gets (>= 2, so that its variance exists) */
    double dark;           /* a pixel darker than dark x the image's mean is held to the error of that level */
    int spread;            /* 1: each pixel's relative variance is the largest of its 3x3 neighbours' */
    float pilot_rr_below;  /* the roulette's T of the pilot, whose samples are independent (render_rr_below) */
} adaptive_opts;

#define ADAPTIVE_GROUP 4   /* counts are rounded up to a multiple of this (the stratified sampler's groups) */

/* The defaults: no target, pilot 16, min 4, dark 0.1, spread on, the pilot's T 1 (no --rr-below). */
void adaptive_opts_init(adaptive_opts *ao);

typedef struct {
    int *pixel_spp;        /* n(x), row-major */
    image count;           /* the samples each pixel got: min(n(x), the passes reached), in R, G and B */
    double pilot_seconds, mean_spp;   /* mean_spp: of count */
    int pilot_spp;         /* the pilot's samples reached (fewer than asked only after a signal) */
    int max_spp;           /* the largest n(x) */
    uint64_t pilot_seed;
} adaptive_result;

/* The pilot, the allocation and the render (o->spp is the cap, o->time_limit is ignored: ao's
 * counts). 0, or nonzero (after printing why) if memory ran out; out as render()'s. */
int adaptive_render(const scene *sc, const camera *cam, const render_opts *o, const adaptive_opts *ao,
                    render_result *out, adaptive_result *ar);
void adaptive_result_free(adaptive_result *ar);
/* "adaptive: pilot 16 spp in 0.05 s (not kept), then 4..1024 spp per pixel, mean 87.3, in 2.1 s; ..."
 * on stderr, for a render that took `seconds` after the pilot. */
void adaptive_print_summary(const adaptive_result *ar, double seconds);
#endif
