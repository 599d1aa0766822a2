/* plan.h — every decision of one render, taken once right after its flags are read, each field
 * with one meaning: the sample range, the bounces, the sampler, the roulette's T. render_cmd makes
 * it, render() or adaptive_render() runs it, its sidecar describes it. */
#ifndef PATHLAB_PLAN_H
#define PATHLAB_PLAN_H
#include "render/adaptive.h"

typedef struct {
    /* what render() runs: the sample range's first index (ro.first) and its count (ro.spp: the
     * samples drawn now, at most; RENDER_SPP_UNTIL_TIME with --time alone; adaptive: the cap of
     * n(x)); the sampler, chosen; the bounces ro.io.bmin .. ro.io.bmax (BOUNCES_NO_END: no last
     * one); the roulette's T ro.io.rr_below, resolved for that sampler */
    render_opts ro;
    int64_t had;          /* the samples the image holds already (--resume), else 0 */
    int64_t total;        /* the samples it holds when the count is reached: had + ro.spp */
    int adaptive;         /* adaptive sampling, with ao (ao.pilot_rr_below: T for the pilot's samples) */
    adaptive_opts ao;
} render_plan;

/* The sampler of a render that names none: sobol1, the least noise for a given time (docs/sampler.md,
 * "Which default"), or independent when the render needs independent samples. */
sampler_kind render_plan_default_sampler(int needs_independent);
/* What the plan's sampler cannot do: Sobol indices past sampler_max_index, a variance (`variance`,
 * the --variance file, or NULL) with sobol1. 0, or 1 after printing why. */
int render_plan_check_sampler(const render_plan *p, const char *variance);
#endif
