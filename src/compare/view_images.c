/* view_images.c — the images of a viewer page read with what lies beside them (view_images.h). */
#include "compare/view_images.h"
#include <errno.h>
#include "sys/shown.h"
#include "image/linear_file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "files/render_files.h"
#include "files/sidecar.h"
#include "sys/input_file.h"
#include "sys/output_path.h"
#include "util/path.h"

static int exists(const char *path) { return access(path, F_OK) == 0; }

/* Reads path into im; the first image read sets the size (*first), later ones must match it. 0 or 2. */
static int read_sized(image *im, const char *path, const char **first, const image *first_img)
{
    if (img_read_linear(im, path, NULL)) return 2;
    if (!*first) { *first = path; return 0; }
    if (im->w == first_img->w && im->h == first_img->h) return 0;
    fprintf(stderr, "pathlab view: %s is %dx%d, %s is %dx%d: the images of a page must have one size\n", shown(path), im->w,
            im->h, shown(*first), first_img->w, first_img->h);
    return 2;
}

/* The variance of the image at path (render_files_find_variance). 1 if found, 0 if none, 2 after
 * printing why it is refused. */
int view_find_variance(const char *path, char *out, size_t cap, const char *cmd, int how)
{
    sidecar m;
    int rc = sidecar_read(&m, path);
    if (rc > 0) return 2;
    rc = render_files_find_variance(out, cap, path, rc == 0 ? &m : NULL, how, cmd);
    return rc < 0 ? 0 : rc ? 2 : 1;
}

/* Reads one image (and its variance, given or found) into slot i of the page. 0 or 2. */
static int read_image(view_data *d, html_image *h, image *im, image *var, const char *path, const char *var_path,
                      const char **first)
{
    char found[PATH_CAP];
    int rc = 0;
    h->name = path_file_name(path);
    h->img = im;
    if (read_sized(im, path, first, &d->img[0])) return 2;
    if (!var_path && (rc = view_find_variance(path, found, sizeof found, "view", 0)) == 2) return 2;
    if (!var_path && rc == 1) var_path = found;
    if (!var_path) return 0;
    if (read_sized(var, var_path, first, &d->img[0])) return 2;
    h->var = var;
    return 0;
}

/* 1 (said) if a layer found beside image0 through its sidecar is not a regular file of its folder
 * (a link planted there to a teacher's file): a page may go back to the student who made image0. */
static int layer_leads_out(const char *image0, const char *path)
{
    char found[PATH_CAP];
    const char *why = input_file_beside(found, sizeof found, image0, path_file_name(path));
    if (why) fprintf(stderr, "pathlab view: %s: %s\n", path, why);
    return why != NULL;
}

/* The strip: PREFIX_Lk.pfm as far as they exist, or the first image's layers A:B (its sidecar). 0 or 2. */
static int read_layers(view_data *d, const char *image0, const char *layers, const char **first)
{
    sidecar m;
    int k, lo = 0, hi = VIEW_MAX_LAYERS - 1;
    char path[PATH_CAP];
    if (!layers && (sidecar_read(&m, image0) || m.layers_n == 0)) return 0;
    if (!layers) lo = m.layers_first, hi = m.layers_first + m.layers_n - 1;
    for (k = lo; k <= hi && k < VIEW_MAX_LAYERS && d->nlayers < VIEW_MAX_LAYERS; k++) {
        html_image *h = &d->strip[d->nlayers];
        if (layers) snprintf(path, sizeof path, "%s_L%d.pfm", layers, k);
        else render_files_layer_path(path, sizeof path, image0, k);
        if (!exists(path)) continue;   /* a layer deleted since, or a gap in PREFIX_Lk: the others are shown */
        if (!layers && layer_leads_out(image0, path)) return 2;
        if (read_sized(&d->layer[d->nlayers], path, first, &d->img[0])) return 2;
        snprintf(d->layer_name[d->nlayers], sizeof d->layer_name[0], "L%d", k);
        h->name = d->layer_name[d->nlayers];
        h->img = &d->layer[d->nlayers++];
    }
    if (layers && !d->nlayers) { fprintf(stderr, "pathlab view: no layer %s_L0.pfm, %s_L1.pfm ...\n", shown(layers), shown(layers)); return 2; }
    return 0;
}

void view_data_free(view_data *d)
{
    int i;
    for (i = 0; i < VIEW_MAX_IMAGES; i++) img_free(&d->img[i]), img_free(&d->var[i]);
    for (i = 0; i < VIEW_MAX_LAYERS; i++) img_free(&d->layer[i]);
    img_free(&d->ref);
    img_free(&d->ref_var);
    free(d);
}


int view_data_read(view_data *d, const char *const *images, int n, const char *ref, const char *var, const char *layers)
{
    const char *first = NULL;
    int i, rc = 0;
    for (i = 0; i < n && !rc; i++) rc = read_image(d, &d->im[i], &d->img[i], &d->var[i], images[i], i ? NULL : var, &first);
    if (!rc && ref) rc = read_image(d, &d->refim, &d->ref, &d->ref_var, ref, NULL, &first);
    if (!rc) rc = read_layers(d, images[0], layers, &first);
    return rc;
}
