/* render_files.h — a render on disk: FILE.pfm (the mean of each pixel), optionally its variance
 * (of the mean) and its L_k layers FILE_Lk.pfm (--split), each file with its sidecar FILE.meta.
 * Written by render and merge, read back by merge and render --resume. */
#ifndef PATHLAB_RENDER_FILES_H
#define PATHLAB_RENDER_FILES_H
#include "files/sidecar.h"
#include "image/image.h"
#include "scene/mesh.h"

typedef struct {
    sidecar meta;       /* of FILE.pfm */
    int nlayers;        /* 1 + the L_k layers */
    int bmin;           /* layer 1 is L_bmin */
    image *mean, *var;  /* [nlayers]; var == NULL when the variance was not read */
} render_files;

/* A file a render reads, named on its command line (or beside its scene): what names it, its path
 * (NULL: none). */
typedef struct { const char *what, *path; } render_input;
#define RENDER_MAX_INPUTS 6
/* Every file a render will write, checked before any work: -o out, --variance var_out, --sample-count
 * count_out, --write-view view_out (each NULL if not given) and with split the layers of bounces
 * bmin .. bmax beside out and var_out (none if bmax is BOUNCES_NO_END: render refuses that): the
 * folder exists and can be written, the extension is known, no two are the same file (whatever
 * their spelling) and none is one of the ninputs inputs (the scene, its view or orbiter file, the
 * sky, the MTL: --write-view over the orbiter file replaced the student's camera). 0, or 1 after
 * printing why ("pathlab render: ..."). */
int render_files_check_outputs(const render_input *inputs, int ninputs, const char *out, const char *var_out, const char *count_out,
                               const char *view_out, int split, int bmin, int bmax);
/* One key per file whatever its spelling (o/a.pfm, ./o/a.pfm, o/../o/a.pfm): its folder's real path and
 * its name (a folder that does not resolve kept as written). */
void render_files_key(char *dst, size_t cap, const char *path);
/* 1 (said "pathlab CMD: ...") if --write-view's name is one of an image, a texture, an OBJ or an MTL
 * (any case: mtllib T.MTL), which a camera must not replace. */
int render_files_view_name_bad(const char *cmd, const char *view_out);
/* 1 (said) if one of the n outputs (NULL: none) is a texture or an MTL file of the scene m (known once
 * it is read, before any pixel is rendered): -o tex.ppm replaced a map_Kd image. */
int render_files_scene_clash(const char *cmd, const char *const *outs, int n, const mesh *m);
/* out.pfm, layer k -> out_Lk.pfm */
void render_files_layer_path(char *dst, size_t cap, const char *out, int k);
/* The variance file that the sidecar of image_path names (name), into dst[cap]: an input, resolved
 * against the image's folder and confined to it (sys/input_file.h, input_file_beside: no absolute
 * path, no "..", no link leading out, a regular file). NULL, or the reason it is refused (errno
 * ENOENT if it does not exist). Never a file to write: an output is named on the command line. */
const char *render_files_variance_path(char *dst, size_t cap, const char *image_path, const char *name);
/* The variance of the image at image_path (m its sidecar, NULL if it has none), for grade, compare
 * and view: the file its sidecar names, else STEM_var.pfm beside it; each confined to the image's
 * folder (render_files_variance_path) and taken when it has no sidecar or its sidecar says it is
 * this render's variance (a REF_var.pfm left from an earlier render of REF.pfm is not: a note says
 * so). A renamed pair (the sidecar still naming tmp_var.pfm) is found beside. how: FIND_VARIANCE_TRUSTED
 * (a user's own reference) follows links wherever they lead (input_file_beside_trusted),
 * FIND_VARIANCE_QUIET says nothing of a named variance that is not there. 0 (its path in dst),
 * -1 none, 1 refused (said, "pathlab CMD: ..."). */
enum { FIND_VARIANCE_TRUSTED = 1, FIND_VARIANCE_QUIET = 2 };
int render_files_find_variance(char *dst, size_t cap, const char *image_path, const sidecar *m, int how, const char *cmd);
/* Writes mean[0..nlayers-1] to out (layer i >= 1 to out_L{bmin+i-1}) and, if var_out, var[] the same
 * way, each with its sidecar: meta with kind, layer and variance filled in per file. All files are
 * written under temporary names first and renamed together: a failure or a second Ctrl-C leaves
 * none of them (and the previous files, if any, whole). 0, or 1 after printing why. */
int render_files_write(const char *out, const char *var_out, float exposure, const sidecar *meta,
                       const image *mean, const image *var, int nlayers, int bmin);
/* The same, and if count_out the per-pixel sample counts of an adaptive render (`count`, kind
 * sample-count, named in the image's sidecar), written and renamed together with the others. */
int render_files_write_all(const char *out, const char *var_out, const char *count_out, const image *count,
                           float exposure, const sidecar *meta, const image *mean, const image *var, int nlayers, int bmin);
/* Reads the render at path (a .pfm with its sidecar), its layers if its sidecar lists some, and its
 * variance files if with_var (render_files_variance_path). Each layer and variance must say in its
 * own sidecar that it is of this render (kind, samples, scene-id, seed, flags, camera) and be of its
 * size (from its header, before its pixels are read). 0, or 1 after printing why (messages start
 * with "pathlab CMD: "). */
int render_files_read(render_files *rf, const char *path, int with_var, const char *cmd);
void render_files_free(render_files *rf);
#endif
