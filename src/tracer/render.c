/* render.c — tiles handed to threads by parallel_for, per-pixel streams, per-layer means, progress. */
#include "tracer/render.h"
#include "sys/clock.h"
#include "sys/parallel.h"
#include <assert.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TILE 16

/* What one thread owns, so that rendering needs no lock; the counts are merged at the end. */
typedef struct {
    vec3 *Lk;                /* L_k of one sample for k = 0..bmax, with --split (else NULL) */
    double *sums;            /* per layer: the sum and sum of squares of one pixel's samples, 6 doubles */
    trace_stats st;
    uint64_t nonfinite;      /* samples dropped for being NaN or infinite */
} thread_state;

typedef struct {
    const scene *sc;
    const camera *cam;
    const render_opts *o;
    render_result *out;
    thread_state *ts;        /* [thread] */
    int tiles_x, ntiles;
    int done_tiles;          /* under lock, for the progress bar */
    int progress;            /* draw a progress bar on stderr */
    double t0;
    pthread_mutex_t lock;
} job;

static void accumulate(double *a, vec3 c)
{
    a[0] += c.x; a[1] += c.y; a[2] += c.z;
    a[3] += (double)c.x * c.x; a[4] += (double)c.y * c.y; a[5] += (double)c.z * c.z;
}

static void store_pixel(render_result *out, int layer, int idx, const double *a, int spp)
{
    float *m, *v;
    int ch;
    assert(0 <= layer && layer < out->nlayers);
    m = out->mean[layer].px + 3 * idx;
    v = out->var[layer].px + 3 * idx;
    for (ch = 0; ch < 3; ch++) {
        double mean = a[ch] / spp;
        double s2 = spp > 1 ? (a[3 + ch] - spp * mean * mean) / (spp - 1) : 0.0;   /* sample variance */
        m[ch] = (float)mean;
        v[ch] = (float)(s2 > 0.0 ? s2 / spp : 0.0);                               /* of the mean */
    }
}

/* One sample into the pixel's sums: layer 0 is the total; with --split, layer 1 + k - bmin is L_k. */
static void add_sample(const job *j, thread_state *t, vec3 L)
{
    const integrator_opts *io = &j->o->io;
    int k;
    accumulate(t->sums, L);
    for (k = io->bmin; t->Lk && k <= io->bmax; k++) {
        int layer = 1 + k - io->bmin;
        assert(layer < j->out->nlayers);
        accumulate(t->sums + 6 * layer, t->Lk[k]);
    }
}

static void render_pixel(const job *j, thread_state *t, int px, int py)
{
    const render_opts *o = j->o;
    int i, layer, idx = py * j->cam->width + px;
    pcg32 rng;
    pcg32_init(&rng, splitmix64_mix(o->seed ^ splitmix64_mix((uint64_t)idx)), (uint64_t)idx);   /* (seed, pixel) -> stream */
    memset(t->sums, 0, sizeof(double) * 6 * (size_t)j->out->nlayers);
    for (i = 0; i < o->spp; i++) {
        float jx = o->pixel_center ? 0.5f : pcg32_float(&rng);
        float jy = o->pixel_center ? 0.5f : pcg32_float(&rng);
        /* image rows run top to bottom here, gKit's bottom to top: its (x + o, y + o) is our (x + o, row + 1 - o) */
        ray r = camera_ray(j->cam, (float)px + (jx + (o->pixel_offset - 0.5f)), (float)py + (jy - (o->pixel_offset - 0.5f)));
        vec3 L = integrate(j->sc, &o->io, &r, &rng, t->Lk, &t->st);
        if (v3_is_finite(L)) add_sample(j, t, L);
        else t->nonfinite++;   /* counted, reported, dropped */
    }
    for (layer = 0; layer < j->out->nlayers; layer++) store_pixel(j->out, layer, idx, t->sums + 6 * layer, o->spp);
}

static void draw_progress(job *j)
{
    double t = clock_seconds() - j->t0, frac = (double)j->done_tiles / j->ntiles;
    int bar = (int)(40 * frac), i;
    fprintf(stderr, "\r[");
    for (i = 0; i < 40; i++) fputc(i < bar ? '#' : ' ', stderr);
    fprintf(stderr, "] %3d%%  %5.1fs", (int)(100 * frac), t);
    if (j->done_tiles < j->ntiles && frac > 0) fprintf(stderr, "  ETA %5.1fs ", t / frac - t);
    else fprintf(stderr, "            \n");
    fflush(stderr);
}

/* The parallel_for body: tiles [begin, end) on thread `thread`. */
static void render_tiles(void *ctx, int thread, int begin, int end)
{
    job *j = ctx;
    thread_state t = j->ts[thread];   /* copied to this thread's stack: its ray counters share no cache line */
    int tile, x, y;
    for (tile = begin; tile < end; tile++) {
        int x0 = (tile % j->tiles_x) * TILE, y0 = (tile / j->tiles_x) * TILE;
        for (y = y0; y < y0 + TILE && y < j->cam->height; y++)
            for (x = x0; x < x0 + TILE && x < j->cam->width; x++) render_pixel(j, &t, x, y);
        pthread_mutex_lock(&j->lock);
        j->done_tiles++;
        if (j->progress) draw_progress(j);
        pthread_mutex_unlock(&j->lock);
    }
    j->ts[thread].st = t.st;
    j->ts[thread].nonfinite = t.nonfinite;
}

static void free_thread_states(thread_state *ts, int nthreads)
{
    int t;
    for (t = 0; ts && t < nthreads; t++) {
        free(ts[t].Lk);
        free(ts[t].sums);
    }
    free(ts);
}

/* nLk entries of L_k per thread (0: none); NULL if memory ran out. */
static thread_state *alloc_thread_states(int nthreads, int nlayers, int nLk)
{
    thread_state *ts = calloc((size_t)nthreads, sizeof *ts);
    int t;
    for (t = 0; ts && t < nthreads; t++) {
        ts[t].Lk = nLk > 0 ? malloc(sizeof(vec3) * (size_t)nLk) : NULL;
        ts[t].sums = malloc(sizeof(double) * 6 * (size_t)nlayers);
        if ((nLk > 0 && !ts[t].Lk) || !ts[t].sums) {
            free_thread_states(ts, nthreads);
            return NULL;
        }
    }
    return ts;
}

static void add_stats(trace_stats *sum, const trace_stats *st)
{
    sum->camera_rays += st->camera_rays;
    sum->continuation_rays += st->continuation_rays;
    sum->shadow_rays += st->shadow_rays;
}

static int alloc_layers(render_result *out, int n, int w, int h)
{
    int k;
    out->nlayers = n;
    out->mean = calloc((size_t)n, sizeof(image));
    out->var = calloc((size_t)n, sizeof(image));
    if (!out->mean || !out->var) return 1;
    for (k = 0; k < n; k++)
        if (img_alloc(&out->mean[k], w, h) || img_alloc(&out->var[k], w, h)) return 1;
    return 0;
}

int render(const scene *sc, const camera *cam, const render_opts *o, render_result *out)
{
    job j;
    int t, nthreads = parallel_threads(o->threads);
    int nlayers = 1 + (o->split ? o->io.bmax - o->io.bmin + 1 : 0);
    memset(out, 0, sizeof *out);
    memset(&j, 0, sizeof j);
    j.ts = alloc_thread_states(nthreads, nlayers, o->split ? o->io.bmax + 1 : 0);
    if (!j.ts || alloc_layers(out, nlayers, cam->width, cam->height)) {
        fprintf(stderr, "pathlab: out of memory for a %dx%d image\n", cam->width, cam->height);
        free_thread_states(j.ts, nthreads);
        render_result_free(out);
        return 1;
    }
    j.sc = sc; j.cam = cam; j.o = o; j.out = out;
    j.tiles_x = (cam->width + TILE - 1) / TILE;
    j.ntiles = j.tiles_x * ((cam->height + TILE - 1) / TILE);
    j.progress = !o->quiet && isatty(2);
    j.t0 = clock_seconds();
    pthread_mutex_init(&j.lock, NULL);
    if (sc->lights.n > 0)   /* without emitters every pixel is black: no work at all */
        parallel_for(j.ntiles, 1, nthreads, render_tiles, &j);
    pthread_mutex_destroy(&j.lock);
    out->seconds = clock_seconds() - j.t0;
    for (t = 0; t < nthreads; t++) {
        add_stats(&out->st, &j.ts[t].st);
        out->nonfinite += j.ts[t].nonfinite;
    }
    free_thread_states(j.ts, nthreads);
    return 0;
}

void render_result_free(render_result *r)
{
    int k;
    for (k = 0; k < r->nlayers && r->mean; k++) img_free(&r->mean[k]);
    for (k = 0; k < r->nlayers && r->var; k++) img_free(&r->var[k]);
    free(r->mean);
    free(r->var);
}

void render_print_stats(const render_result *r, int spp, int npixels)
{
    const trace_stats *st = &r->st;
    double secs = r->seconds > 0 ? r->seconds : 1e-9;
    uint64_t rays = st->camera_rays + st->continuation_rays + st->shadow_rays;
    fprintf(stderr, "%.2f s, %d spp, %.2f Msamples/s, %.2f Mrays/s (camera %llu, continuation %llu, shadow %llu), "
            "%llu NaN/Inf samples\n",
            r->seconds, spp, (double)spp * npixels / secs * 1e-6, (double)rays / secs * 1e-6,
            (unsigned long long)st->camera_rays, (unsigned long long)st->continuation_rays,
            (unsigned long long)st->shadow_rays, (unsigned long long)r->nonfinite);
}
