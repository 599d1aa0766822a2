/* plan.c — the choices a render plan makes by itself: the default sampler, and what a sampler refuses. */
#include "render/plan.h"
#include "sys/shown.h"
#include <stdio.h>

sampler_kind render_plan_default_sampler(int needs_independent) { return needs_independent ? SAMPLER_INDEPENDENT : SAMPLER_SOBOL1; }

int render_plan_check_sampler(const render_plan *p, const char *variance)
{
    const char *name = SAMPLER_NAMES[p->ro.sampler];
    if (p->ro.first + p->ro.spp > sampler_max_index(p->ro.sampler)) {
        fprintf(stderr, "pathlab render: --sampler %s takes sample indices below %lld (2^32 points in each of its %d "
                "scrambling(s); past that the points would repeat): use --sampler independent\n",
                name, (long long)sampler_max_index(p->ro.sampler), sampler_groups(p->ro.sampler));
        return 1;
    }
    if (p->ro.sampler == SAMPLER_SOBOL1 && variance) {
        fprintf(stderr, "pathlab render: --variance %s: --sampler sobol1 draws one scrambled sequence per pixel, whose "
                "samples are not independent: no variance of the mean can be estimated from them. Use --sampler sobol "
                "(4 independent scramblings a pixel: a variance with 3 degrees of freedom) or independent\n", shown(variance));
        return 1;
    }
    return 0;
}
