/* render.c — threads, tiles, per-pixel streams, progress. */
#include "tracer/render.h"
#include "sys/clock.h"
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TILE 16

typedef struct {
    const scene *s;
    const camera *c;
    const render_opts *o;
    render_result *out;
    int tiles_x, ntiles, next_tile, done_tiles;
    int progress;            /* draw a progress bar on stderr */
    double t0;
    pthread_mutex_t lock;
} job;

static int finite3(vec3 c) { return isfinite(c.x) && isfinite(c.y) && isfinite(c.z); }

/* Layer 0 is the total; with --split, layer 1 + k - bmin holds L_k. */
static void accumulate(double *a, vec3 c)
{
    a[0] += c.x; a[1] += c.y; a[2] += c.z;
    a[3] += (double)c.x * c.x; a[4] += (double)c.y * c.y; a[5] += (double)c.z * c.z;
}

static void store_pixel(render_result *out, int k, int idx, const double *a, int spp)
{
    float *m = out->mean[k].px + 3 * idx, *v = out->var[k].px + 3 * idx;
    int ch;
    for (ch = 0; ch < 3; ch++) {
        double mean = a[ch] / spp;
        double s2 = spp > 1 ? (a[3 + ch] - spp * mean * mean) / (spp - 1) : 0.0;   /* sample variance */
        m[ch] = (float)mean;
        v[ch] = (float)(s2 > 0.0 ? s2 / spp : 0.0);                               /* of the mean */
    }
}

static void render_pixel(job *j, int px, int py, vec3 *L, double *acc, trace_stats *st)
{
    const render_opts *o = j->o;
    int n = j->out->nlayers, i, k, idx = py * j->c->width + px;
    pcg32 rng;
    pcg32_init(&rng, splitmix64_mix(o->seed ^ splitmix64_mix((uint64_t)idx)), (uint64_t)idx);   /* (seed, pixel) -> stream */
    memset(acc, 0, sizeof(double) * 6 * (size_t)n);   /* sum, sum of squares per layer */
    for (i = 0; i < o->spp; i++) {
        float jx = o->pixel_center ? 0.5f : pcg32_float(&rng);
        float jy = o->pixel_center ? 0.5f : pcg32_float(&rng);
        ray r = camera_ray(j->c, (float)px + jx, (float)py + jy);
        memset(L, 0, sizeof(vec3) * (size_t)n);
        integrate(j->s, &o->io, &r, &rng, L, st);
        if (!finite3(L[0])) { st->nonfinite++; continue; }   /* counted, reported, dropped */
        for (k = 0; k < n; k++) accumulate(acc + 6 * k, L[k]);
    }
    for (k = 0; k < n; k++) store_pixel(j->out, k, idx, acc + 6 * k, o->spp);
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

static void *worker(void *arg)
{
    job *j = arg;
    trace_stats st = {0, 0, 0, 0};
    int n = j->out->nlayers;
    vec3 *L = malloc(sizeof(vec3) * (size_t)n);
    double *acc = malloc(sizeof(double) * 6 * (size_t)n);
    for (;;) {
        int t, x0, y0, x, y;
        pthread_mutex_lock(&j->lock);
        t = j->next_tile++;
        pthread_mutex_unlock(&j->lock);
        if (t >= j->ntiles || !L || !acc) break;
        x0 = (t % j->tiles_x) * TILE;
        y0 = (t / j->tiles_x) * TILE;
        for (y = y0; y < y0 + TILE && y < j->c->height; y++)
            for (x = x0; x < x0 + TILE && x < j->c->width; x++) render_pixel(j, x, y, L, acc, &st);
        pthread_mutex_lock(&j->lock);
        j->done_tiles++;
        if (j->progress) draw_progress(j);
        pthread_mutex_unlock(&j->lock);
    }
    pthread_mutex_lock(&j->lock);
    j->out->st.camera_rays += st.camera_rays;
    j->out->st.continuation_rays += st.continuation_rays;
    j->out->st.shadow_rays += st.shadow_rays;
    j->out->st.nonfinite += st.nonfinite;
    pthread_mutex_unlock(&j->lock);
    free(L);
    free(acc);
    return NULL;
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

int render(const scene *s, const camera *c, const render_opts *o, render_result *out)
{
    job j;
    pthread_t th[256];
    int i, nthreads = o->threads < 1 ? 1 : o->threads > 256 ? 256 : o->threads;
    int nlayers = 1 + (o->io.split ? o->io.bmax - o->io.bmin + 1 : 0);
    memset(out, 0, sizeof *out);
    if (alloc_layers(out, nlayers, c->width, c->height)) {
        fprintf(stderr, "pathlab: out of memory for a %dx%d image\n", c->width, c->height);
        render_result_free(out);
        return 1;
    }
    memset(&j, 0, sizeof j);
    j.s = s; j.c = c; j.o = o; j.out = out;
    j.tiles_x = (c->width + TILE - 1) / TILE;
    j.ntiles = j.tiles_x * ((c->height + TILE - 1) / TILE);
    j.progress = !o->quiet && isatty(2);
    j.t0 = clock_seconds();
    pthread_mutex_init(&j.lock, NULL);
    if (s->lights.n > 0)   /* without emitters every pixel is black: no work at all */
        for (i = 0; i < nthreads; i++)
            if (pthread_create(&th[i], NULL, worker, &j)) { nthreads = i; break; }
    if (s->lights.n > 0 && nthreads == 0) worker(&j);
    for (i = 0; i < nthreads && s->lights.n > 0; i++) pthread_join(th[i], NULL);
    pthread_mutex_destroy(&j.lock);
    out->seconds = clock_seconds() - j.t0;
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
            (unsigned long long)st->shadow_rays, (unsigned long long)st->nonfinite);
}
