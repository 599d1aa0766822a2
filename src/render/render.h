/* render.h — the render loop, in passes: every pixel gets sample i before any gets sample i + 1,
 * so that the image is a uniform-spp image at the end of every pass (a render stopped by Ctrl-C or
 * --time writes the spp it reached). Inside a pass, 16x16 tiles are handed to threads as they come
 * free (parallel_for). The random numbers of sample i of pixel p depend on (seed, p, i) only, so
 * the image is the same whatever the threads and the passes, and samples A..B-1 can be rendered
 * alone and merged with others. Each image layer (the total, and with --split one per bounce L_k)
 * gets its mean and the variance of that mean per pixel. */
#ifndef PATHLAB_RENDER_H
#define PATHLAB_RENDER_H
#include <stdint.h>
#include "scene/camera.h"
#include "image/image.h"
#include "tracer/integrator.h"

/* render_opts.spp with --time alone: no count, the time decides when to stop. */
#define RENDER_SPP_UNTIL_TIME (1 << 30)

typedef struct {
    int spp;                /* the samples this render draws per pixel (at most: --time or a signal may
                               stop it sooner): indices first .. first + spp - 1 */
    int64_t first;          /* the first sample index */
    double time_limit;      /* --time: seconds; passes stop when the next would not fit (0: none) */
    int threads, quiet, pixel_center;
    float pixel_offset;     /* pixel (x, y) is centred at (x + offset, y + offset), y counted from the
                               bottom row as in gKit/OpenGL: 0.5 (pbrt, Mitsuba, gKit's x + .5) or 0 */
    int split;              /* --split: also one image layer per L_k */
    uint64_t seed;
    sampler_kind sampler;   /* --sampler: independent, sobol or sobol1 */
    integrator_opts io;     /* io.rr_below resolved (render_rr_below) */
    sky_spec sky;           /* --sky: put over the scene by scene_add_sky, recorded in the sidecar */
    const int *pixel_spp;   /* adaptive sampling: pixel p (row-major) gets only the samples first ..
                               first + pixel_spp[p] - 1, each <= spp, chosen before the render
                               (tracer/adaptive.h); NULL: every pixel gets spp */
} render_opts;

typedef struct {
    int nlayers;            /* 1 + (bmax - bmin + 1 with split) */
    image *mean, *var;      /* [0] the total, [1 + k - bmin] L_k with split; var: of the pixel's mean */
    int variance_dof;       /* the degrees of freedom of var: 0 many (independent), 3 sobol (pixel_sums.h) */
    int spp;                /* the samples reached: first .. first + spp - 1 (fewer than asked if stopped);
                               with pixel_spp, pixel p has min(pixel_spp[p], spp) of them */
    int interrupted;        /* the signal that stopped it after a pass (0: it ran to its end) */
    trace_stats st;
    uint64_t nonfinite;     /* samples that were NaN or infinite (counted, and dropped) */
    double seconds;
} render_result;

/* The roulette's T (integrator_opts.rr_below) of a render: `given` if > 0 (--rr-below), else 1 with
 * independent samples (the classic p_survive = max(beta)) and 1/3 with the Sobol samplers, whose
 * stratified samples leave the roulette's own noise as most of the error (docs/estimators.md,
 * "Where to stop"). */
#define RR_BELOW_STRATIFIED (1.0f / 3.0f)
float render_rr_below(float given, sampler_kind kind);

/* The image layer of L_k in a render whose first bounce is bmin: layer 0 is the total, layer
 * render_layer_of(k, bmin) = 1 + k - bmin is L_k (--split), and back. */
static inline int render_layer_of(int k, int bmin) { return 1 + k - bmin; }
static inline int render_bounce_of_layer(int layer, int bmin) { return bmin + layer - 1; }

/* Renders; 0 on success (also when stopped by a signal or --time: see spp), nonzero (after
 * printing why) if memory ran out. */
int render(const scene *sc, const camera *cam, const render_opts *o, render_result *out);
void render_result_free(render_result *r);
/* The one-line summary: time, samples per pixel (spp rendered now; after --resume, had + spp in all
 * and how many were added), samples/s, Mrays/s and the rays of each kind. */
void render_print_stats(const render_result *r, int spp, int64_t had, int npixels);
#endif
