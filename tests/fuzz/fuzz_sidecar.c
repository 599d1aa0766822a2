/* fuzz_sidecar.c — libFuzzer harness: one sidecar FILE.pfm.meta, as merge, render --resume, grade
 * and view read it. An accepted sidecar must have sorted, disjoint ranges within 0 .. 2^62 whose
 * spp does not overflow, its counts within the bounds of the command line, and survive a write and
 * a read back. Then what the commands do with it runs without memory errors or UB: the resume's
 * arithmetic (resume_samples for the smallest and the largest --spp, and the sidecar that the
 * resumed render writes, which must read back), the merge of its ranges, the command that renders it
 * again, and the files it names (render_files_read, render_files_named_variance: any name, since a
 * name leading out of the image's folder, to a FIFO or a device, must be refused before it is opened). */
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "fuzz_common.h"
#include "files/render_files.h"
#include "files/resume.h"
#include "files/sidecar.h"

static const uint8_t PFM1[] = "PF\n1 1\n-1.0\n\0\0\0\0\0\0\0\0\0\0\0";   /* 1x1, 12 bytes of zeros */

/* Aborts unless m is within the sidecar's bounds (sidecar.h). */
static void check_bounds(const sidecar *m)
{
    int i;
    if (m->nranges < 1 || m->nranges > SIDECAR_MAX_RANGES) abort();
    for (i = 0; i < m->nranges; i++) {
        if (m->range[i][0] < 0 || m->range[i][1] <= m->range[i][0] || m->range[i][1] > SIDECAR_INDEX_MAX) abort();
        if (i && m->range[i][0] < m->range[i - 1][1]) abort();
    }
    if (sidecar_spp(m) <= 0 || sidecar_spp(m) > SIDECAR_INDEX_MAX) abort();
    if (m->adaptive[0] && (m->spp_cap < 1 || m->spp_cap > SIDECAR_SPP_MAX)) abort();
}

/* Aborts unless b, written and read back, is a (every field that the file holds). */
static void round_trip(const sidecar *a, const char *img)
{
    static sidecar b;
    char path[4200];
    (void)img;
    snprintf(path, sizeof path, "%s", fuzz_absent(4, "y.pfm.meta"));   /* slot 4: removed at exit */
    if (sidecar_write_to(a, "y.pfm", path) != 0) abort();
    path[strlen(path) - 5] = '\0';
    if (sidecar_read(&b, path) != 0) abort();
    if (b.nranges != a->nranges || memcmp(b.range, a->range, sizeof(a->range[0]) * (size_t)a->nranges) || b.seed != a->seed
        || strcmp(b.kind, a->kind) || strcmp(b.layer, a->layer) || strcmp(b.scene, a->scene) || strcmp(b.flags, a->flags)
        || strcmp(b.camera, a->camera) || strcmp(b.variance, a->variance) || strcmp(b.sampler, a->sampler)
        || strcmp(b.adaptive, a->adaptive) || strcmp(b.revision, a->revision))
        abort();
}

/* render --resume -o x.pfm --spp total: the samples it adds, and the sidecar it writes (the new
 * range joined to the old ones), which must be within bounds and read back. */
static void resume(const sidecar *had, int64_t total, const char *img)
{
    static sidecar m;
    int64_t first = 0;
    int spp = 0;
    if (resume_samples(had, total, "x.pfm", &first, &spp) != 0) return;
    if (spp < 1 || spp > SIDECAR_SPP_MAX || first < 0 || first > SIDECAR_INDEX_MAX - spp) abort();
    m = *had;
    m.adaptive[0] = '\0';
    m.nranges = 1;
    m.range[0][0] = first;
    m.range[0][1] = first + spp;
    if (sidecar_add_ranges(&m, had, "this render", "x.pfm") != 0) return;   /* too many ranges: said so */
    check_bounds(&m);
    if (sidecar_spp(&m) != total) abort();
    round_trip(&m, img);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static sidecar m, sum;
    static uint8_t vmeta[8192 + 16];
    char cmd[4096], text[64], var[4200];
    const char *img;
    render_files rf;
    img = fuzz_write(0, "x.pfm", PFM1, 12 + 12);
    fuzz_write(1, "x.pfm.meta", data, size);
    fuzz_write(2, "x_var.pfm", PFM1, 12 + 12);
    if (size < 8192) {   /* its variance's sidecar: the same lines, then "kind variance" (the last line of a key wins) */
        memcpy(vmeta, data, size);
        memcpy(vmeta + size, "\nkind variance\n", 15);
        fuzz_write(3, "x_var.pfm.meta", vmeta, size + 15);
    }
    if (sidecar_read(&m, img) != 0) return 0;
    check_bounds(&m);
    sidecar_ranges_text(&m, text, sizeof text);
    sidecar_render_command(&m, 0, 0, "stem", cmd, sizeof cmd);
    sidecar_render_command(&m, 7, 9, "stem", cmd, 40);
    sum = m;
    if (sidecar_add_ranges(&sum, &m, "a", "b") == 0) abort();   /* the same samples twice must be refused */
    sidecar_check_same(&m, &m, "fuzz", "a", "b");
    round_trip(&m, img);
    resume(&m, 1, img);
    resume(&m, sidecar_spp(&m) < SIDECAR_SPP_MAX ? sidecar_spp(&m) + 1 : 1, img);
    resume(&m, SIDECAR_SPP_MAX, img);
    if (render_files_read(&rf, img, m.variance[0] != 0, "fuzz") == 0) render_files_free(&rf);
    render_files_find_variance(var, sizeof var, img, &m, 0, "fuzz");
    return 0;
}
