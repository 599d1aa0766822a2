/* resume.c — the checks of render --resume, and the sums of the old and the new samples. */
#include "files/resume.h"
#include "sys/shown.h"
#include "stats/combine.h"
#include <stdio.h>
#include <unistd.h>

/* A Sobol render cannot be resumed: 1 after saying why. */
static int refuse_sobol(const char *out, sampler_kind sampler, const sidecar *had)
{
    if (!sidecar_is_sobol(had) && sampler == SAMPLER_INDEPENDENT) return 0;
    fprintf(stderr, "pathlab render: --resume: %s%s%s%s: a Sobol render cannot be resumed: its file keeps the mean and the "
            "variance, not the sums of each scrambling that the variance needs, and more points of the same "
            "scrambled sequences are not independent of those it has. Render it again with the --spp wanted, "
            "or use --sampler independent for renders to resume\n", shown(out),
            sidecar_is_sobol(had) ? " was rendered with --sampler " : " (this render: --sampler ",
            sidecar_is_sobol(had) ? had->sampler : SAMPLER_NAMES[sampler], sidecar_is_sobol(had) ? "" : ")");
    return 1;
}

int resume_read(render_files *prev, sidecar *had, const char *out, const sidecar *now, sampler_kind sampler,
                int with_variance, int split)
{
    int rc = sidecar_read(had, out);
    if (rc < 0 && access(out, F_OK) != 0) {
        fprintf(stderr, "pathlab render: --resume: %s does not exist: there is nothing to resume (leave out --resume)\n", shown(out));
        return 1;
    }
    if (rc < 0) render_files_read(prev, out, 0, "render");   /* says that it has no sidecar */
    if (rc || refuse_sobol(out, sampler, had)) return 1;
    if (render_files_read(prev, out, had->variance[0] != '\0', "render")) return 1;
    if (sidecar_check_same(&prev->meta, now, "render --resume", out, "this render")) return 1;
    if (with_variance && !had->variance[0]) {
        fprintf(stderr, "pathlab render: %s was rendered without --variance: its variance cannot be resumed\n", shown(out));
        return 1;
    }
    if ((prev->nlayers > 1) != (split != 0)) {
        fprintf(stderr, "pathlab render: %s was rendered %s --split: resume it %s --split\n", shown(out),
                prev->nlayers > 1 ? "with" : "without", prev->nlayers > 1 ? "with" : "without");
        return 1;
    }
    return 0;
}

int resume_combine(const render_files *prev, int64_t n, render_result *r)
{
    int i;
    for (i = 0; i < r->nlayers; i++) {
        size_t count = 3 * (size_t)r->mean[i].w * (size_t)r->mean[i].h;
        combine_acc c;
        if (combine_init(&c, count)) { fprintf(stderr, "pathlab render: out of memory\n"); return 1; }
        combine_add(&c, prev->mean[i].px, prev->var ? prev->var[i].px : NULL, (double)n);
        combine_add(&c, r->mean[i].px, r->var[i].px, r->spp);
        combine_result(&c, r->mean[i].px, r->var[i].px);
        combine_free(&c);
    }
    return 0;
}
