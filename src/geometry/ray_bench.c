/* ray_bench.c — the rays of the BVH benchmark, traced and timed (ray_bench.h). Every float
 * expression below follows embree_rays.c operation for operation; do not "simplify" them. */
#include "geometry/ray_bench.h"
#include "geometry/bvh_layout.h"
#include <stdint.h>
#include <stdlib.h>
#include "sys/clock.h"
#include "sys/parallel.h"
#include <time.h>


typedef struct {
    int cpu_time;               /* time with the process's CPU clock (ray_bench.h) */
    const bvh *b;
    const vec3 *P;              /* the mesh's vertices and triangles */
    const int *tri;
    int res;
    vec3 eye, cu, cv, cw, light;
    float offs;                 /* 1e-4 D: how far secondary rays start off the surface */
    vec3 *hitp, *hitn;          /* primary hit points and normals facing the camera */
    unsigned char *hitok;
} bench_scene;

static double now(int cpu_time)
{
    struct timespec t;
    if (!cpu_time) return clock_seconds();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One ray kind traced over every row; rays and hits counted per thread (parallel_for's index). */
typedef struct {
    const bench_scene *s;
    int kind;
    long rays[PARALLEL_MAX_THREADS], hits[PARALLEL_MAX_THREADS];
} trace_job;

/* lowbias32 (Chris Wellons), the recipe's only source of randomness, and its top 24 bits in [0,1). */
static uint32_t lowbias32(uint32_t x)
{
    x ^= x >> 16; x *= 0x7feb352dU; x ^= x >> 15; x *= 0x846ca68bU; x ^= x >> 16;
    return x;
}
static float u01(uint32_t h) { return (float)(h >> 8) * (1.0f / 16777216.0f); }

/* Each returns 1 for a hit (or an occluded shadow ray). */
static int trace_primary(const bench_scene *s, int px, int py)
{
    int i = py * s->res + px;
    float sx = (2.0f * (px + 0.5f) / s->res - 1.0f), sy = (1.0f - 2.0f * (py + 0.5f) / s->res);
    vec3 d = v3_normalize(v3_add(s->cw, v3_add(v3_scale(s->cu, sx), v3_scale(s->cv, sy))));
    ray r = {s->eye, d, INFINITY};
    hit h;
    const int *t;
    vec3 a, b, c, n;
    if (!bvh_intersect(s->b, &r, &h)) return 0;
    t = s->tri + 3 * h.tri;
    a = s->P[t[0]]; b = s->P[t[1]]; c = s->P[t[2]];
    n = v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)));
    if (v3_dot(n, d) > 0) n = v3_scale(n, -1.0f);
    s->hitp[i] = v3_add(s->eye, v3_scale(d, h.t)); s->hitn[i] = n; s->hitok[i] = 1;
    return 1;
}

static vec3 diffuse_dir(vec3 n, int i)
{
    float u1 = u01(lowbias32(2u * (uint32_t)i)), u2 = u01(lowbias32(2u * (uint32_t)i + 1u));
    vec3 t = fabsf(n.x) > 0.5f ? v3_normalize(v3_cross(v3(0, 1, 0), n)) : v3_normalize(v3_cross(v3(1, 0, 0), n));
    vec3 s = v3_cross(n, t);
    float r = sqrtf(u1), ph = 6.28318530718f * u2;
    return v3_normalize(v3_add(v3_add(v3_scale(t, r * cosf(ph)), v3_scale(s, r * sinf(ph))),
                               v3_scale(n, sqrtf(fmaxf(0.0f, 1.0f - u1)))));
}

static int trace_secondary(const bench_scene *s, int kind, int i)
{
    vec3 o = v3_add(s->hitp[i], v3_scale(s->hitn[i], s->offs));
    if (kind == RAY_BENCH_DIFFUSE) {
        ray r = {o, diffuse_dir(s->hitn[i], i), INFINITY};
        hit h;
        return bvh_intersect(s->b, &r, &h);
    } else {
        vec3 to = v3_sub(s->light, o);
        float dist = sqrtf(v3_dot(to, to));
        ray r = {o, v3_scale(to, 1.0f / dist), dist * (1.0f - 1e-4f)};
        return bvh_occluded(s->b, &r);
    }
}

/* parallel_body: the rays of rows [begin, end). Secondary rays start where primary rays hit. */
static void trace_rows(void *ctx, int thread, int begin, int end)
{
    trace_job *j = ctx;
    const bench_scene *s = j->s;
    long rays = 0, hits = 0;   /* counted here, stored once: the threads' counters share cache lines */
    int row, px;
    for (row = begin; row < end; row++)
        for (px = 0; px < s->res; px++) {
            if (j->kind == RAY_BENCH_PRIMARY) rays++, hits += trace_primary(s, px, row);
            else if (s->hitok[row * s->res + px]) rays++, hits += trace_secondary(s, j->kind, row * s->res + px);
        }
    j->rays[thread] += rays;
    j->hits[thread] += hits;
}

/* Traces one ray kind on `threads` threads, rows handed out one at a time; returns the seconds taken. */
static double trace(const bench_scene *s, int kind, int threads, long *rays, long *hits)
{
    trace_job j;
    double t0, secs;
    int t;
    j.s = s; j.kind = kind;
    for (t = 0; t < PARALLEL_MAX_THREADS; t++) j.rays[t] = j.hits[t] = 0;
    t0 = now(s->cpu_time);
    parallel_for(s->res, 1, threads, trace_rows, &j);
    secs = now(s->cpu_time) - t0;
    *rays = 0; *hits = 0;
    for (t = 0; t < PARALLEL_MAX_THREADS; t++) { *rays += j.rays[t]; *hits += j.hits[t]; }
    return secs;
}

/* The recipe's camera: eye c + D (0.35, 0.25, 0.9) looking at the centre c, 40 degrees vertical
 * field of view; the light for shadow rays at c + (0, 2D, 0). Bounds are over every vertex. */
static void setup_camera(bench_scene *s, const vec3 *P, int nverts)
{
    vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY), c;
    float D, th;
    int i;
    for (i = 0; i < nverts; i++) {
        lo = v3(fminf(lo.x, P[i].x), fminf(lo.y, P[i].y), fminf(lo.z, P[i].z));
        hi = v3(fmaxf(hi.x, P[i].x), fmaxf(hi.y, P[i].y), fmaxf(hi.z, P[i].z));
    }
    c = v3_scale(v3_add(lo, hi), 0.5f);
    D = sqrtf(v3_dot(v3_sub(hi, lo), v3_sub(hi, lo)));
    s->eye = v3_add(c, v3_scale(v3(0.35f, 0.25f, 0.9f), D));
    s->light = v3_add(c, v3(0, 2.0f * D, 0));
    s->offs = 1e-4f * D;
    s->cw = v3_normalize(v3_sub(c, s->eye));
    s->cu = v3_normalize(v3_cross(s->cw, v3(0, 1, 0)));
    s->cv = v3_cross(s->cu, s->cw);
    th = tanf(0.5f * 40.0f * PI_F / 180.0f);
    s->cu = v3_scale(s->cu, th); s->cv = v3_scale(s->cv, th);
}

/* Builds RAY_BENCH_BUILDS times and keeps the last bvh; *ms = the fastest build. NULL if out of memory. */
static bvh *timed_build(const vec3 *P, const int *tri, int ntris, const ray_bench_options *opt, double *ms)
{
    bvh *b = NULL;
    double t0, t;
    int rep;
    *ms = INFINITY;
    for (rep = 0; rep < RAY_BENCH_BUILDS; rep++) {
        bvh_free(b);
        t0 = now(opt->cpu_time);
        b = bvh_build_quality(P, tri, ntris, opt->threads, opt->quality);
        t = (now(opt->cpu_time) - t0) * 1e3;
        if (!b) return NULL;
        if (t < *ms) *ms = t;
    }
    return b;
}

int ray_bench_run(const vec3 *P, int nverts, const int *tri, int ntris, const ray_bench_options *opt,
                  ray_bench_result *out)
{
    bench_scene s = {0};
    size_t npix = (size_t)opt->res * (size_t)opt->res;
    bvh *b;
    int kind, rc = 1;
    s.P = P, s.tri = tri, s.res = opt->res, s.cpu_time = opt->cpu_time;
    setup_camera(&s, P, nverts);
    s.b = b = timed_build(P, tri, ntris, opt, &out->build_ms);
    s.hitp = malloc(npix * sizeof(vec3)); s.hitn = malloc(npix * sizeof(vec3)); s.hitok = calloc(npix, 1);
    if (b && s.hitp && s.hitn && s.hitok) {
        out->bvh_bytes = (double)b->nnodes * sizeof(wnode) + (double)b->nblocks * sizeof(tri_block);
        for (kind = RAY_BENCH_PRIMARY; kind <= RAY_BENCH_SHADOW; kind++)
            out->secs[kind] = trace(&s, kind, opt->threads, &out->rays[kind], &out->hits[kind]);
        rc = 0;
    }
    free(s.hitp); free(s.hitn); free(s.hitok);
    bvh_free(b);
    return rc;
}
