/* render_merge.c — pathlab merge's work: check that the inputs are pieces of one render (their
 * sidecars), then combine them one at a time, so that memory holds one input and the sums whatever
 * their number. */
#include "files/render_merge.h"
#include "sys/shown.h"
#include "files/render_files.h"
#include "image/radiance.h"
#include "stats/combine.h"
#include "sys/output_path.h"
#include "tracer/integrator.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct {
    const char *path;
    sidecar meta;
} input;

static int by_first_sample(const void *a, const void *b)
{
    int64_t x = ((const input *)a)->meta.range[0][0], y = ((const input *)b)->meta.range[0][0];
    return x < y ? -1 : x > y;
}

/* Reads every sidecar, sorts the inputs by their first sample (the same merge whatever their order
 * on the command line) and checks them against the first; the union of their samples into *all. */
static int check_inputs(input *in, int n, sidecar *all)
{
    int i, warned = 0;
    for (i = 0; i < n; i++) {
        int rc = sidecar_read(&in[i].meta, in[i].path);
        if (rc < 0) fprintf(stderr, "pathlab merge: %s has no sidecar %s.meta: merge needs to know its samples "
                                    "(was it written by pathlab render? copy the .meta with it)\n", shown(in[i].path), shown(in[i].path));
        if (rc) return 1;
        if (sidecar_is_sobol(&in[i].meta)) {
            fprintf(stderr, "pathlab merge: %s was rendered with --sampler %s: Sobol renders cannot be merged: the file "
                            "keeps the mean and the variance, not the sums of each scrambling that the variance needs, "
                            "and pieces of one scrambled sequence are not independent. Render pieces to merge with "
                            "--sampler independent\n", shown(in[i].path), shown(in[i].meta.sampler));
            return 1;
        }
        if (strcmp(in[i].meta.kind, "mean")) {
            fprintf(stderr, "pathlab merge: %s is a %s image: give the images, their variances come along\n", shown(in[i].path), shown(in[i].meta.kind));
            return 1;
        }
    }
    qsort(in, (size_t)n, sizeof *in, by_first_sample);
    *all = in[0].meta;
    for (i = 1; i < n; i++) {
        if (sidecar_check_same(&in[0].meta, &in[i].meta, "merge", in[0].path, in[i].path)) return 1;
        if (sidecar_add_ranges(all, &in[i].meta, in[0].path, in[i].path)) return 1;
        if (strcmp(in[0].meta.revision, in[i].meta.revision) && !warned++)
            fprintf(stderr, "pathlab merge: warning: %s and %s were made by different pathlab revisions (%s, %s): "
                            "merge them only if the estimator did not change between them\n",
                    shown(in[0].path), shown(in[i].path), shown(in[0].meta.revision), shown(in[i].meta.revision));
    }
    return 0;
}

/* "'A:B'", or "none" */
static const char *layers_text(const sidecar *m, char *buf, size_t cap)
{
    if (m->layers_n > 0) snprintf(buf, cap, "'%d:%d'", m->layers_first, m->layers_first + m->layers_n - 1);
    else snprintf(buf, cap, "none");
    return buf;
}

/* The layers to merge: those of the first input if every input has the same, else none (said so). */
static int common_layers(const input *in, int n)
{
    char a[32], b[32];
    int i;
    for (i = 1; i < n; i++)
        if (in[i].meta.layers_n != in[0].meta.layers_n || (in[0].meta.layers_n && in[i].meta.layers_first != in[0].meta.layers_first)) {
            fprintf(stderr, "pathlab merge: note: %s has layers %s and %s %s: merging the totals only\n", shown(in[0].path),
                    layers_text(&in[0].meta, a, sizeof a), shown(in[i].path), layers_text(&in[i].meta, b, sizeof b));
            return 0;
        }
    return in[0].meta.layers_n > 0;
}

/* Adds every input to the sums (one combine_acc per layer), reading one input at a time. */
/* 0 if every layer of rf (and its variance) is finite and >= 0, else 1, said: a NaN in one piece
 * would make the merged image NaN, a negative variance a negative one. */
static int values_valid(const render_files *rf, int nlayers, int with_var, const char *path)
{
    char what[4400];
    int k;
    for (k = 0; k < nlayers; k++) {
        snprintf(what, sizeof what, k ? "%s, its layer %d," : "%s", path, k);
        if (img_check_radiance(&rf->mean[k], what, 5) || (with_var && img_check_radiance(&rf->var[k], k ? what : "its variance", 5)))
            return 1;
    }
    return 0;
}

static int add_inputs(const input *in, int n, int nlayers, int with_var, combine_acc *acc, render_files *first)
{
    int i, k;
    for (i = 0; i < n; i++) {
        render_files rf;
        if (render_files_read(&rf, in[i].path, with_var, "merge")) return 1;
        if (rf.nlayers < nlayers || rf.mean[0].w != first->mean[0].w || rf.mean[0].h != first->mean[0].h) {
            fprintf(stderr, "pathlab merge: %s does not have the size or the layers of %s\n", shown(in[i].path), shown(in[0].path));
            render_files_free(&rf);
            return 1;
        }
        if (values_valid(&rf, nlayers, with_var, in[i].path)) {
            fprintf(stderr, "pathlab merge: %s: nothing merged\n", shown(in[i].path));
            render_files_free(&rf);
            return 1;
        }
        for (k = 0; k < nlayers; k++)
            combine_add(&acc[k], rf.mean[k].px, with_var ? rf.var[k].px : NULL, (double)sidecar_spp(&in[i].meta));
        render_files_free(&rf);
    }
    return 0;
}

/* The files of a render at path (NULL: none): the image and, with the layers of m, its layers, each
 * with its sidecar; keys (render_files_key) appended to keys[*n] (room for cap). */
static void render_keys(char (*keys)[PATH_CAP], int *n, int cap, const char *path, const sidecar *m)
{
    char name[PATH_CAP];
    int k;
    for (k = -1; path && k < (m->layers_n > 0 ? m->layers_n : 0); k++) {
        if (k < 0) snprintf(name, sizeof name, "%s", path);
        else render_files_layer_path(name, sizeof name, path, m->layers_first + k);
        if (*n + 2 > cap) return;
        render_files_key(keys[(*n)++], PATH_CAP, name);
        strncat(name, ".meta", sizeof name - strlen(name) - 1);
        render_files_key(keys[(*n)++], PATH_CAP, name);
    }
}

/* 1 (said) if a file the merge writes (the image, its variance, their layers and sidecars) is another
 * of them (--variance the output) or a file of an input (its variance, a layer: merging over
 * p0_var.pfm destroyed the pieces). */
static int writes_over_inputs(const char *out, const char *var_out, const input *in, int n, const sidecar *all)
{
    enum { CAP = 4 * (2 + BOUNCES_CAP) };
    static char outs[CAP][PATH_CAP], ins[CAP][PATH_CAP];   /* 300 kB: not on the stack */
    char var[PATH_CAP];
    int no = 0, ni, i, j, k;
    render_keys(outs, &no, CAP, out, all);
    render_keys(outs, &no, CAP, var_out, all);
    for (i = 0; i < no; i++)
        for (j = 0; j < i; j++)
            if (!strcmp(outs[i], outs[j])) {
                fprintf(stderr, "pathlab merge: the output and --variance write the same file %s: give each its own name\n", shown(outs[i]));
                return 1;
            }
    for (k = 0; k < n; k++) {
        ni = 0;
        render_keys(ins, &ni, CAP, in[k].path, &in[k].meta);
        if (in[k].meta.variance[0] && !render_files_variance_path(var, sizeof var, in[k].path, in[k].meta.variance))
            render_keys(ins, &ni, CAP, var, &in[k].meta);
        for (i = 0; i < no; i++)
            for (j = 0; j < ni; j++)
                if (!strcmp(outs[i], ins[j])) {
                    fprintf(stderr, "pathlab merge: it would write over %s, a file of the input %s: write the merge to a new file\n",
                            shown(outs[i]), shown(in[k].path));
                    return 1;
                }
    }
    return 0;
}

/* Combines the inputs and writes OUT (and its layers and variances) with the merged sidecar. */
static int merge_inputs(const char *out, const char *var_out, input *in, int n)
{
    render_files first;
    sidecar all;
    combine_acc acc[2 + BOUNCES_CAP];   /* the total and L0 .. L_BOUNCES_CAP */
    int k, nlayers, err = 0;
    if (check_inputs(in, n, &all) || writes_over_inputs(out, var_out, in, n, &all)) return 2;
    if (render_files_read(&first, in[0].path, var_out != NULL, "merge")) return 2;   /* the size and the layers */
    nlayers = common_layers(in, n) ? first.nlayers : 1;
    for (k = 0; k < nlayers && !err; k++) err = combine_init(&acc[k], 3 * (size_t)first.mean[0].w * (size_t)first.mean[0].h);
    if (err) fprintf(stderr, "pathlab merge: out of memory\n");
    err = err ? 2 : add_inputs(in, n, nlayers, var_out != NULL, acc, &first) ? 2 : 0;
    for (k = 0; k < nlayers && !err; k++) combine_result(&acc[k], first.mean[k].px, var_out ? first.var[k].px : NULL);
    all.stopped[0] = '\0';
    if (nlayers == 1) all.layers_n = 0;
    if (!err && render_files_write(out, var_out, 0.0f, &all, first.mean, first.var, nlayers, first.bmin)) err = 1;
    if (!err) {
        char ranges[SIDECAR_RANGES_TEXT];
        sidecar_ranges_text(&all, ranges, sizeof ranges);
        fprintf(stderr, "pathlab merge: %d renders, samples %s (%" PRId64 " spp) -> %s%s%s\n", n, ranges, sidecar_spp(&all), out,
                var_out ? " and " : "", var_out ? var_out : "");
    }
    for (k = 0; k < nlayers; k++) combine_free(&acc[k]);
    render_files_free(&first);
    return err;
}

/* 1 (said) if out names the same file as one of the inputs (a link or another spelling too). */
static int overwrites_input(const char *flag, const char *out, const char *const *paths, int n)
{
    struct stat o, p;
    int i;
    if (!out || stat(out, &o) != 0) return 0;   /* not there yet: not an input */
    for (i = 0; i < n; i++)
        if (stat(paths[i], &p) == 0 && p.st_dev == o.st_dev && p.st_ino == o.st_ino) {
            fprintf(stderr, "pathlab merge: %s %s is the input %s: write the merge to a new file\n", flag, shown(out), shown(paths[i]));
            return 1;
        }
    return 0;
}

int render_merge(const char *out, const char *var_out, const char *const *paths, int n)
{
    input *in;
    int i, rc;
    if (overwrites_input("-o", out, paths, n) || overwrites_input("--variance", var_out, paths, n)) return 2;
    if (!(in = calloc((size_t)n, sizeof *in))) { fprintf(stderr, "pathlab merge: out of memory\n"); return 2; }
    for (i = 0; i < n; i++) in[i].path = paths[i];
    rc = merge_inputs(out, var_out, in, n);
    free(in);
    return rc;
}
