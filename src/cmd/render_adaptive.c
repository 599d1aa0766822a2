/* render_adaptive.c — the adaptive flags of pathlab render (render_adaptive.h). */
#include "cmd/render_adaptive.h"
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
    char target[48] = "", time[48] = "";
    m->adaptive[0] = '\0';
    if (!a->adaptive) return;
    if (a->target_given) snprintf(target, sizeof target, " --target-error %.9g", a->ao.target_error);
    if (a->ro.time_limit > 0) snprintf(time, sizeof time, " --time %.9g", a->ro.time_limit);   /* it shapes n(x) */
    snprintf(m->adaptive, sizeof m->adaptive, "--adaptive%s%s --pilot %d --min-spp %d", target, time, a->ao.pilot, a->ao.min_spp);
}

void render_adaptive_print(const adaptive_result *ar, double seconds)
{
    size_t npx = (size_t)ar->count.w * (size_t)ar->count.h, p;
    float lo = npx ? ar->count.px[0] : 0, hi = lo;
    for (p = 0; p < npx; p++) {
        float n = ar->count.px[3 * p];
        lo = n < lo ? n : lo;
        hi = n > hi ? n : hi;
    }
    fprintf(stderr, "adaptive: pilot %d spp in %.2f s (not kept), then %.0f..%.0f spp per pixel, mean %.1f, in %.2f s; "
                    "%.2f Msamples/s kept\n", ar->pilot_spp, ar->pilot_seconds, lo, hi, ar->mean_spp, seconds,
            seconds > 0 ? ar->mean_spp * (double)npx / seconds * 1e-6 : 0.0);
}
