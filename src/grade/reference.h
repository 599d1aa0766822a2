/* reference.h — the reference of a grading and what lies beside it: its variance (--var, else
 * REF_var.pfm, else the variance its sidecar REF.pfm.meta names), its layers (--layers PREFIX, else
 * REF_split_L0.pfm ..., or render --split's own REF_L0.pfm ...) and its sidecar, which says what
 * made it (render --variance and --split write them all). */
#ifndef PATHLAB_GRADE_REFERENCE_H
#define PATHLAB_GRADE_REFERENCE_H
#include "grade/grade_diagnose.h"
#include "files/sidecar.h"
#include "sys/output_path.h"

typedef struct {
    image ref, var, layer[GRADE_MAX_LAYERS];
    grade_refs refs;                /* the images above, as the tests and the diagnosis take them */
    const char *var_path;           /* the variance read (--var, or var_found), or NULL */
    char var_found[PATH_CAP];       /* the variance found beside the reference */
    char layer_prefix[PATH_CAP];    /* the layers are PREFIX_L0.pfm, PREFIX_L1.pfm ... */
    sidecar meta;                   /* REF.pfm.meta, when pathlab render wrote the reference */
    int has_meta;
} grade_reference;

/* Reads the reference at path, its variance (var, or found beside it) and its layers (layers, or
 * found beside it); checks that all are finite and of one size. 0, or 2 after saying why. Free R
 * with grade_reference_free in both cases; R must not be copied (var_path may point into it). */
int grade_reference_read(grade_reference *R, const char *path, const char *var, const char *layers);
void grade_reference_free(grade_reference *R);
/* What made the reference, from its sidecar: a teacher checks the spp, seed and camera at a glance. */
void grade_reference_print_provenance(const grade_reference *R, const char *path);
#endif
