/* reference.c — the reference, its variance, its layers and its sidecar read (reference.h). */
#include "grade/reference.h"
#include "sys/shown.h"
#include "image/linear_file.h"
#include <stdio.h>
#include <string.h>
#include "files/render_files.h"
#include "grade/grade_class.h"
#include "util/path.h"
#include "sys/input_file.h"
#include <stdlib.h>

/* The variance: --var, else as render_files_find_variance finds it (the one the reference's sidecar
 * names, else STEM_var.pfm beside it, each only if of this render: a REF_var.pfm left from an
 * earlier render of REF.pfm is not). 0 or 2. */
static int read_variance(grade_reference *R, const char *path, const char *var)
{
    int rc = -1;
    if (!var) {   /* --ref is the teacher's: links followed; beside it, else beside the file it leads to (a store) */
        char *real = input_file_resolved(path);
        int link = real && strcmp(real, path);
        sidecar mr;
        rc = render_files_find_variance(R->var_found, sizeof R->var_found, path, R->has_meta ? &R->meta : NULL,
                                        FIND_VARIANCE_TRUSTED | (link ? FIND_VARIANCE_QUIET : 0), "grade");
        if (rc < 0 && link)   /* the sidecar beside the file it leads to, if the link has none */
            rc = render_files_find_variance(R->var_found, sizeof R->var_found, real,
                                            R->has_meta ? &R->meta : sidecar_read(&mr, real) == 0 ? &mr : NULL, FIND_VARIANCE_TRUSTED, "grade");
        free(real);
        if (rc > 0) return 2;
    }
    R->var_path = var ? var : rc == 0 ? R->var_found : NULL;
    if (!R->var_path) return 0;
    if (img_read_pfm(&R->var, R->var_path)) return 2;
    if (R->var.w != R->ref.w || R->var.h != R->ref.h) {
        fprintf(stderr, "pathlab grade: %s is %dx%d, the reference %s %dx%d\n", shown(R->var_path), R->var.w, R->var.h, shown(path), R->ref.w, R->ref.h);
        return 2;
    }
    R->refs.var = &R->var;
    return 0;
}

/* The layers PREFIX_L0.pfm, PREFIX_L1.pfm ... as far as they exist. 0 or 2. */
static int read_layers(grade_reference *R, const char *path, const char *layers, size_t stem)
{
    char file[PATH_CAP];
    int k;
    if (layers) snprintf(R->layer_prefix, sizeof R->layer_prefix, "%s", layers);
    else snprintf(R->layer_prefix, sizeof R->layer_prefix, "%.*s_split", (int)stem, path);
    if (!layers && R->has_meta && R->meta.layers_n > 0 && R->meta.layers_first == 0) {   /* render --split's own REF_L0.pfm ... */
        if (snprintf(file, sizeof file, "%s_L0.pfm", R->layer_prefix) >= (int)sizeof file || !path_is_readable(file)) snprintf(R->layer_prefix, sizeof R->layer_prefix, "%.*s", (int)stem, path);
    }
    for (k = 0; k < GRADE_MAX_LAYERS; k++) {
        if (snprintf(file, sizeof file, "%s_L%d.pfm", R->layer_prefix, k) >= (int)sizeof file || !path_is_readable(file)) break;
        if (img_read_pfm(&R->layer[k], file)) return 2;
        if (R->layer[k].w != R->ref.w || R->layer[k].h != R->ref.h) {
            fprintf(stderr, "pathlab grade: the layer %s is %dx%d, the reference %dx%d\n", shown(file), R->layer[k].w, R->layer[k].h, R->ref.w, R->ref.h);
            return 2;
        }
        R->refs.layer[k] = &R->layer[k];
        R->refs.nlayers = k + 1;
    }
    return 0;
}

int grade_reference_read(grade_reference *R, const char *path, const char *var, const char *layers)
{
    size_t stem = path_ends_with(path, ".pfm") ? strlen(path) - 4 : strlen(path);
    img_pfm_info info;
    memset(R, 0, sizeof *R);
    if (img_read_linear(&R->ref, path, &info)) return 2;
    R->refs.ref = &R->ref;
    R->refs.channels = info.channels;
    R->has_meta = sidecar_read(&R->meta, path) == 0;
    R->refs.pixel_center = R->has_meta ? strstr(R->meta.flags, "--pixel-center") != NULL : -1;
    if (read_variance(R, path, var) || read_layers(R, path, layers, stem)) return 2;
    return grade_check_reference(&R->refs, path, R->var_path);
}

void grade_reference_free(grade_reference *R)
{
    int k;
    img_free(&R->ref);
    img_free(&R->var);
    for (k = 0; k < GRADE_MAX_LAYERS; k++) img_free(&R->layer[k]);
}

void grade_reference_print_provenance(const grade_reference *R, const char *path)
{
    const sidecar *m = &R->meta;
    char ranges[256], spp[96];
    sidecar_ranges_text(m, ranges, sizeof ranges);
    if (m->adaptive[0]) snprintf(spp, sizeof spp, "adaptive, a mean of %.1f spp per pixel", m->spp_mean);   /* not the range's width */
    else snprintf(spp, sizeof spp, "%lld spp", (long long)sidecar_spp(m));
    printf("reference %s: %s (samples %s), seed %llu, %s %s, camera %s, pathlab %s%s%s\n", shown(path),
           spp, ranges, (unsigned long long)m->seed, shown(m->scene), shown(m->flags), shown(m->camera), shown(m->revision),
           m->stopped[0] ? ", stopped by " : "", m->stopped);
}
