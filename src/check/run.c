/* run.c — a case run by the runner of its kind, and the cases on threads (run.h). */
#include "check/run.h"
#include "check/brdf_check.h"
#include "check/light_check.h"
#include "check/sky_check.h"
#include "check/warp_check.h"
#include "sys/parallel.h"
#include <stdio.h>
#include <string.h>

/* Runs one case with n samples (times its share) from the streams of seed. */
static void run_case(const sampling_case *c, long n, uint64_t seed, sampling_result *r)
{
    long m = (long)(c->share * (double)n);
    memset(r, 0, sizeof *r);
    snprintf(r->routine, sizeof r->routine, "%s", c->name);
    switch (c->kind) {
    case CASE_WARP: check_warp(&c->warp, m, seed, r); break;
    case CASE_TRIANGLE: check_triangle(&c->triangle, m, seed, r); break;
    case CASE_BRDF: check_brdf(&c->brdf, m, seed, r); break;
    case CASE_LIGHT_CHOICE: check_light_choice(&c->light, m, seed, r); break;
    case CASE_LIGHT_POINT: check_light_point(&c->light, m, seed, r); break;
    case CASE_SKY: check_sky(&c->sky, m, seed, r); break;
    }
}

/* The seed of case i: the cases' streams are unrelated */
static uint64_t case_seed(uint64_t seed, int i) { return splitmix64_at(seed, (uint64_t)i + 1); }

typedef struct {
    const sampling_case *c;
    sampling_result *r;
    long n;
    uint64_t seed;
} run_job;

/* parallel_for's body: cases [begin, end) */
static void run_cases(void *ctx, int thread, int begin, int end)
{
    const run_job *job = ctx;
    int i;
    (void)thread;
    for (i = begin; i < end; i++) run_case(&job->c[i], job->n, case_seed(job->seed, i), &job->r[i]);
}

void check_sampling_run_all(const sampling_case *c, int ncases, long n, uint64_t seed, int threads, sampling_result *r)
{
    run_job job;
    job.c = c, job.r = r, job.n = n, job.seed = seed;
    parallel_for(ncases, 1, threads, run_cases, &job);   /* one case per chunk: their costs differ widely */
}
