/* render.h — the render loop: pixels in 16x16 tiles handed to threads as they come free
 * (parallel_for), each pixel with its own random stream (seed, pixel index), so the image is the
 * same whatever the number of threads. Each image layer (the total, and with --split one per
 * bounce L_k) gets its mean and the variance of that mean per pixel. */
#ifndef PATHLAB_RENDER_H
#define PATHLAB_RENDER_H
#include "scene/camera.h"
#include "image/image.h"
#include "tracer/integrator.h"

typedef struct {
    int spp, threads, quiet, pixel_center;
    float pixel_offset;     /* pixel (x, y) is centred at (x + offset, y + offset), y counted from the
                               bottom row as in gKit/OpenGL: 0.5 (pbrt, Mitsuba, gKit's x + .5) or 0 */
    int split;              /* --split: also one image layer per L_k */
    uint64_t seed;
    integrator_opts io;
} render_opts;

typedef struct {
    int nlayers;            /* 1 + (bmax - bmin + 1 with split) */
    image *mean, *var;      /* [0] the total, [1 + k - bmin] L_k with split; var: of the pixel's mean */
    trace_stats st;
    uint64_t nonfinite;     /* samples that were NaN or infinite (counted, and dropped) */
    double seconds;
} render_result;

/* Renders; 0 on success, nonzero (after printing why) if memory ran out. */
int render(const scene *sc, const camera *cam, const render_opts *o, render_result *out);
void render_result_free(render_result *r);
/* The one-line summary: time, samples/s, Mrays/s and the rays of each kind. */
void render_print_stats(const render_result *r, int spp, int npixels);
#endif
