/* resume.c — the checks of render --resume, and the sums of the old and the new samples. */
#include "files/resume.h"
#include "sys/shown.h"
#include "stats/combine.h"
#include "sys/output_path.h"
#include "util/path.h"
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
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

int resume_variance_out(char *dst, size_t cap, const char *out, const sidecar *had)
{
    char named[PATH_CAP];
    const char *ext = strrchr(out, '.');
    size_t stem = ext && !strchr(ext, '/') ? (size_t)(ext - out) : strlen(out);
    static const char *const pfm[] = {".pfm", NULL};
    if (snprintf(dst, cap, "%.*s_var.pfm", (int)stem, out) >= (int)cap) {
        fprintf(stderr, "pathlab render: --resume: %s: the name of its variance is too long\n", out);
        return 1;
    }
    if (render_files_variance_path(named, sizeof named, out, had->variance) || !path_same_file(named, dst)) {
        fprintf(stderr, "pathlab render: --resume: %s.meta names its variance '%s', but the variance --resume rewrites is the one "
                "the command line names: %s beside -o, or --variance FILE (a name read from a file is never written)\n",
                out, had->variance, dst);
        return 1;
    }
    return output_path_check("render", "--resume (its variance)", dst, pfm);
}

int resume_samples(const sidecar *had, int64_t total, const char *out, int64_t *first, int *spp)
{
    int64_t have = sidecar_spp(had);
    if (have >= total) return 1;
    *first = had->range[had->nranges - 1][1];
    *spp = (int)(total - have);
    if (*first <= SIDECAR_INDEX_MAX - *spp) return 0;   /* the sidecar's bound, that of --samples: no index overflows */
    fprintf(stderr, "pathlab render: --resume: %s holds samples up to index %" PRId64 ": %d more would pass 2^62, the limit of "
            "a sample index\n", out, *first, *spp);
    return 2;
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
