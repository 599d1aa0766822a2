/* render_adaptive.c — the adaptive flags of pathlab render (render_adaptive.h). */
#include "cmd/render_adaptive.h"
#include "files/render_meta.h"
#include <stdio.h>
#include <string.h>

void render_adaptive_flag_table(render_args *a, cli_flag t[RENDER_ADAPTIVE_NFLAGS])
{
    const cli_flag flags[RENDER_ADAPTIVE_NFLAGS] = {
        {"--target-error", CLI_DOUBLE, &a->ao.target_error, 1e-6, 100, NULL, NULL, &a->target_given},
        {"--adaptive", CLI_SWITCH, &a->adaptive, 0, 0, NULL, NULL, NULL},
        {"--pilot", CLI_INT, &a->ao.pilot, 2, 1 << 20, NULL, NULL, &a->pilot_given},
        {"--min-spp", CLI_INT, &a->ao.min_spp, 2, 1 << 30, NULL, NULL, &a->min_given},
        {"--sample-count", CLI_STRING, &a->sample_count, 0, 0, NULL, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    memcpy(t, flags, sizeof flags);
}

/* The flags that need adaptive sampling, and those it cannot go with; 0, or 1 after printing why. */
static int check_combinations(const render_args *a)
{
    const char *needs = a->pilot_given ? "--pilot" : a->min_given ? "--min-spp" : a->sample_count ? "--sample-count" : NULL;
    if (!a->adaptive && needs) {
        fprintf(stderr, "pathlab render: %s is for adaptive sampling: add --target-error E or --adaptive --time SEC\n", needs);
        return 1;
    }
    if (!a->adaptive) return 0;
    if (!a->target_given && a->ro.time_limit <= 0) {
        fprintf(stderr, "pathlab render: --adaptive needs --target-error E (e.g. 0.01) or --time SEC to say when to stop\n");
        return 1;
    }
    if (a->samples_given || a->resume) {
        fprintf(stderr, "pathlab render: adaptive sampling renders each pixel's samples from 0 on: not with %s "
                        "(merge and --resume cannot combine pixels of different sample counts)\n", a->resume ? "--resume" : "--samples");
        return 1;
    }
    if (a->sample_count && img_format_of(a->sample_count) != IMG_PFM) {
        fprintf(stderr, "pathlab render: --sample-count %s: the counts are written as .pfm\n", a->sample_count);
        return 1;
    }
    return 0;
}

int render_adaptive_check(render_args *a)
{
    if (a->target_given) a->adaptive = 1;
    if (check_combinations(a)) return 1;
    if (!a->adaptive) return 0;
    if (a->spp_given && a->ao.min_spp > a->spp) {
        fprintf(stderr, "pathlab render: --min-spp %d is over the cap --spp %d\n", a->ao.min_spp, a->spp);
        return 1;
    }
    return 0;
}

void render_adaptive_describe(const render_args *a, sidecar *m)
{
    if (a->adaptive) render_meta_describe_adaptive(m, &a->ao, a->target_given, a->ro.time_limit);
}
