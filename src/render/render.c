/* render.c — passes of samples over tiles handed to threads by parallel_for, one random stream per
 * sample, per-pixel sums kept across passes, progress, and the stop between passes. */
#include "render/render.h"
#include "render/pixel_sums.h"
#include "sys/clock.h"
#include "sys/interrupt.h"
#include "sys/parallel.h"
#include "sys/progress.h"
#include <assert.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TILE 16
#define PASS_SECONDS 1.0   /* a pass lasts about this long (after the first, of 1 spp): Ctrl-C waits at most that */

/* What one thread owns, so that rendering needs no lock; the counts are merged at the end. */
typedef struct {
    vec3 *Lk;                /* L_k of one sample for k = 0..bmax, with --split (else NULL) */
    trace_stats st;
    uint64_t nonfinite;      /* samples dropped for being NaN or infinite */
} thread_state;

typedef struct {
    const scene *sc;
    const camera *cam;
    const render_opts *o;
    render_result *out;
    thread_state *ts;        /* [thread] */
    double *sums;            /* [pixel][layer][nsum], over the samples of the passes done */
    int nsum;                /* doubles per pixel and layer (tracer/pixel_sums.h: depends on --sampler) */
    int64_t s0, s1;          /* the current pass: sample indices [s0, s1) */
    int done;                /* samples of the passes done */
    int tiles_x, ntiles;
    int *tile_spp;           /* with pixel_spp: the largest count of each tile's pixels (else NULL) */
    int done_tiles;          /* of the current pass, under lock, for the progress line */
    progress pr;
    pthread_mutex_t lock;
} job;

/* Sample i into the pixel's sums a: layer 0 is the total; with --split, layer 1 + k - bmin is L_k. */
static void add_sample(const job *j, const thread_state *t, double *a, int64_t i, vec3 L)
{
    const integrator_opts *io = &j->o->io;
    int k;
    pixel_sums_add(a, j->o->sampler, i, L);
    for (k = io->bmin; t->Lk && k <= io->bmax; k++) {
        int layer = render_layer_of(k, io->bmin);
        assert(layer < j->out->nlayers);
        pixel_sums_add(a + j->nsum * layer, j->o->sampler, i, t->Lk[k]);
    }
}

/* The samples s0..s1-1 of pixel (px, py), each addressed by (seed, pixel, sample index) in --sampler. */
static void render_pixel(const job *j, thread_state *t, int px, int py)
{
    const render_opts *o = j->o;
    int idx = py * j->cam->width + px;
    double *a = j->sums + (size_t)idx * (size_t)j->nsum * (size_t)j->out->nlayers;
    int64_t i, end = j->s1;
    if (o->pixel_spp && o->first + o->pixel_spp[idx] < end) end = o->first + o->pixel_spp[idx];
    for (i = j->s0; i < end; i++) {
        sampler smp;
        float jx = 0.5f, jy = 0.5f;
        ray r;
        vec3 L;
        sampler_start(&smp, o->sampler, o->seed, (uint64_t)idx, (uint64_t)i);
        if (!o->pixel_center) sampler_pixel(&smp, &jx, &jy);
        /* image rows run top to bottom here, gKit's bottom to top: its (x + o, y + o) is our (x + o, row + 1 - o) */
        r = camera_ray(j->cam, (float)px + (jx + (o->pixel_offset - 0.5f)), (float)py + (jy - (o->pixel_offset - 0.5f)));
        L = integrate(j->sc, &o->io, &r, &smp, t->Lk, &t->st);
        if (v3_is_finite(L)) add_sample(j, t, a, i, L);
        else t->nonfinite++;   /* counted, reported, dropped */
    }
}

/* "384 of 4096 spp", or "384 spp, --time 1m00s" */
static void describe(const job *j, char *buf, size_t cap, int spp)
{
    char limit[32];
    progress_duration(limit, sizeof limit, j->o->time_limit);
    if (j->o->time_limit > 0) snprintf(buf, cap, "%d spp, --time %s", spp, limit);
    else snprintf(buf, cap, "%d of %d spp", spp, j->o->spp);
}

/* The pixel-samples of sample indices first + a .. first + b - 1: npixels * (b - a), or with
 * pixel_spp only those of the pixels whose count goes past a (a pass costs what it renders). */
static double work(const job *j, double a, double b)
{
    size_t npx = (size_t)j->cam->width * (size_t)j->cam->height, p;
    double w = 0;
    if (!j->o->pixel_spp) return (b - a) * (double)npx;
    for (p = 0; p < npx; p++) {
        double n = j->o->pixel_spp[p];
        w += (n < b ? n : b) - (n < a ? n : a);
    }
    return w;
}

/* The fraction done: of the pixel-samples, or of the time with --time. */
static double fraction(const job *j, double spp_now)
{
    double f = j->o->time_limit > 0 ? (clock_seconds() - j->pr.t0) / j->o->time_limit
                                    : work(j, 0, spp_now) / work(j, 0, j->o->spp);
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

/* The parallel_for body: tiles [begin, end) of the current pass on thread `thread`. */
static void render_tiles(void *ctx, int thread, int begin, int end)
{
    job *j = ctx;
    thread_state t = j->ts[thread];   /* copied to this thread's stack: its ray counters share no cache line */
    int tile, x, y;
    char what[96];
    for (tile = begin; tile < end; tile++) {
        int x0 = (tile % j->tiles_x) * TILE, y0 = (tile / j->tiles_x) * TILE;
        if (j->tile_spp && j->o->first + j->tile_spp[tile] <= j->s0) continue;   /* every pixel done: costs nothing */
        for (y = y0; y < y0 + TILE && y < j->cam->height; y++)
            for (x = x0; x < x0 + TILE && x < j->cam->width; x++) render_pixel(j, &t, x, y);
        pthread_mutex_lock(&j->lock);
        j->done_tiles++;
        if (progress_due(&j->pr)) {   /* the line is built only when it is drawn */
            double spp_now = j->done + (double)(j->s1 - j->s0) * j->done_tiles / j->ntiles;
            describe(j, what, sizeof what, j->done);
            progress_update(&j->pr, fraction(j, spp_now), what);
        }
        pthread_mutex_unlock(&j->lock);
    }
    j->ts[thread].st = t.st;
    j->ts[thread].nonfinite = t.nonfinite;
}

/* The most samples (up to left) after those done whose pixel-samples take at most `seconds` at
 * per_work seconds each; work grows with n, so by bisection (exact division when uniform). */
static int fit(const job *j, double seconds, double per_work, int left)
{
    int lo = 0, hi = left;
    if (per_work <= 0) return left;
    if (!j->o->pixel_spp) {
        double n = floor(seconds / (per_work * (double)j->cam->width * j->cam->height));
        return n < 0 ? 0 : n < left ? (int)n : left;
    }
    while (lo < hi) {   /* the largest n in [lo, hi] that fits */
        int mid = lo + (hi - lo + 1) / 2;
        if (work(j, j->done, (double)j->done + mid) * per_work <= seconds) lo = mid;
        else hi = mid - 1;
    }
    return lo;
}

/* The samples of the next pass: 1 first, then about PASS_SECONDS' worth at the speed measured so
 * far, never past --spp, and with --time only if they fit in the time left (0: stop). */
static int next_pass(const job *j)
{
    double elapsed = clock_seconds() - j->pr.t0, per_work;
    int left = j->o->spp - j->done, n;
    if (left <= 0) return 0;
    if (j->done == 0) return 1;
    per_work = elapsed / work(j, 0, j->done);
    n = fit(j, PASS_SECONDS, per_work, left);
    if (n < 1) n = 1;
    if (j->o->time_limit > 0) {
        int room = fit(j, j->o->time_limit - elapsed, per_work, left);
        if (room < n) n = room;
        if (n < 1) return 0;
    }
    return n;
}

/* The passes, until --spp is reached, --time is spent, or a signal asked to stop. */
static void run_passes(job *j, int nthreads)
{
    char what[96];
    int n;
    while ((n = next_pass(j)) > 0) {
        j->s0 = j->o->first + j->done;
        j->s1 = j->s0 + n;
        j->done_tiles = 0;
        parallel_for(j->ntiles, 1, nthreads, render_tiles, j);
        j->done += n;
        if ((j->out->interrupted = interrupt_signal()) != 0) break;
    }
    describe(j, what, sizeof what, j->done);
    progress_end(&j->pr, fraction(j, j->done), what);
}

/* The means and the variances of the means of every layer, from the sums of `done` samples (with
 * pixel_spp, of min(pixel_spp[p], done) at pixel p). */
static void store_images(const job *j, render_result *out, int done)
{
    size_t npx = (size_t)out->mean[0].w * (size_t)out->mean[0].h, p;
    const int *pixel_spp = j->o->pixel_spp;
    int layer, fewest = done;   /* the dof are those of the pixel with the fewest samples */
    for (p = 0; p < npx; p++)
        for (layer = 0; layer < out->nlayers; layer++) {
            int n = pixel_spp && pixel_spp[p] < done ? pixel_spp[p] : done;
            const double *a = j->sums + (p * (size_t)out->nlayers + (size_t)layer) * (size_t)j->nsum;
            if (n < fewest) fewest = n;
            pixel_sums_store(a, j->o->sampler, j->o->first, n, out->mean[layer].px + 3 * p, out->var[layer].px + 3 * p);
        }
    out->variance_dof = pixel_sums_dof(j->o->sampler, fewest);
}

static void free_thread_states(thread_state *ts, int nthreads)
{
    int t;
    for (t = 0; ts && t < nthreads; t++) free(ts[t].Lk);
    free(ts);
}

/* nLk entries of L_k per thread (0: none); NULL if memory ran out. */
static thread_state *alloc_thread_states(int nthreads, int nLk)
{
    thread_state *ts = calloc((size_t)nthreads, sizeof *ts);
    int t;
    for (t = 0; ts && t < nthreads; t++) {
        ts[t].Lk = nLk > 0 ? malloc(sizeof(vec3) * (size_t)nLk) : NULL;
        if (nLk > 0 && !ts[t].Lk) {
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
    sum->shadow_rays_spared += st->shadow_rays_spared;
    sum->paths_cut += st->paths_cut;
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

/* j->tile_spp: the largest pixel_spp of each tile (j->tiles_x, j->ntiles set); 1 if memory ran out. */
static int tile_counts(job *j)
{
    int x, y, w = j->cam->width, h = j->cam->height;
    if (!(j->tile_spp = calloc((size_t)j->ntiles, sizeof(int)))) return 1;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int *t = &j->tile_spp[(y / TILE) * j->tiles_x + x / TILE], n = j->o->pixel_spp[y * w + x];
            if (n > *t) *t = n;
        }
    return 0;
}

/* The job's buffers: per-thread states, the result's layers, the sums; 1 if memory ran out. */
static int setup(job *j, int nthreads, render_result *out)
{
    const render_opts *o = j->o;
    int nlayers = o->split ? render_layer_of(o->io.bmax, o->io.bmin) + 1 : 1;
    size_t npx = (size_t)j->cam->width * (size_t)j->cam->height;
    j->ts = alloc_thread_states(nthreads, o->split ? o->io.bmax + 1 : 0);
    if (!j->ts || alloc_layers(out, nlayers, j->cam->width, j->cam->height)) return 1;
    j->tiles_x = (j->cam->width + TILE - 1) / TILE;
    j->ntiles = j->tiles_x * ((j->cam->height + TILE - 1) / TILE);
    j->nsum = pixel_sums_size(o->sampler);
    j->sums = calloc(npx * (size_t)nlayers, (size_t)j->nsum * sizeof(double));
    return j->sums == NULL || (o->pixel_spp && tile_counts(j));
}

float render_rr_below(float given, sampler_kind kind)
{
    if (given > 0.0f) return given;
    return kind == SAMPLER_INDEPENDENT ? 1.0f : RR_BELOW_STRATIFIED;
}

int render(const scene *sc, const camera *cam, const render_opts *o, render_result *out)
{
    job j;
    int t, nthreads = parallel_threads(o->threads);
    assert(o->io.rr_depth < 0 || o->io.rr_below > 0.0f);   /* resolved by the caller: render_rr_below */
    memset(out, 0, sizeof *out);
    memset(&j, 0, sizeof j);
    j.sc = sc; j.cam = cam; j.o = o; j.out = out;
    if (setup(&j, nthreads, out)) {
        fprintf(stderr, "pathlab: out of memory for a %dx%d image%s\n", cam->width, cam->height, o->split ? " and its layers" : "");
        free_thread_states(j.ts, nthreads);
        free(j.sums);
        free(j.tile_spp);
        render_result_free(out);
        return 1;
    }
    progress_start(&j.pr, !o->quiet);
    pthread_mutex_init(&j.lock, NULL);
    if (scene_has_light(sc)) run_passes(&j, nthreads);
    else j.done = o->spp;   /* without emitters or a sky every pixel is black: no work at all */
    pthread_mutex_destroy(&j.lock);
    out->seconds = clock_seconds() - j.pr.t0;
    out->spp = j.done;
    store_images(&j, out, j.done);
    for (t = 0; t < nthreads; t++) {
        add_stats(&out->st, &j.ts[t].st);
        out->nonfinite += j.ts[t].nonfinite;
    }
    free_thread_states(j.ts, nthreads);
    free(j.sums);
    free(j.tile_spp);
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

void render_print_stats(const render_result *r, int spp, int64_t had, int npixels)
{
    const trace_stats *st = &r->st;
    double secs = r->seconds > 0 ? r->seconds : 1e-9;
    uint64_t rays = st->camera_rays + st->continuation_rays + st->shadow_rays;
    if (had > 0) fprintf(stderr, "%.2f s, %lld spp in all (%d added to the %lld it had)", r->seconds, (long long)(had + spp), spp, (long long)had);
    else fprintf(stderr, "%.2f s, %d spp", r->seconds, spp);
    fprintf(stderr, ", %.2f Msamples/s, %.2f Mrays/s (camera %llu, continuation %llu, shadow %llu; "
            "%llu shadow rays not traced: nothing could block them), %llu NaN/Inf samples, %llu paths cut at %d bounces\n",
            (double)spp * npixels / secs * 1e-6, (double)rays / secs * 1e-6,
            (unsigned long long)st->camera_rays, (unsigned long long)st->continuation_rays,
            (unsigned long long)st->shadow_rays, (unsigned long long)st->shadow_rays_spared, (unsigned long long)r->nonfinite,
            (unsigned long long)st->paths_cut, BOUNCES_CAP);
}
