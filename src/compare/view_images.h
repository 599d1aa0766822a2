/* view_images.h — the images of one viewer page (image/html_page.h) read from disk, as pathlab view
 * makes it: the images, the reference, their variances (given for the first image, else each
 * image's STEM_var.pfm or the one its sidecar names) and the layers of a strip (PREFIX_L0.pfm ...,
 * else the first image's own --split layers when its sidecar lists some), all of one size. */
#ifndef PATHLAB_VIEW_IMAGES_H
#define PATHLAB_VIEW_IMAGES_H
#include "image/html_page.h"

#define VIEW_MAX_IMAGES 64
#define VIEW_MAX_LAYERS 16

/* Everything read, and the page's view of it. */
typedef struct {
    image img[VIEW_MAX_IMAGES], var[VIEW_MAX_IMAGES], ref, ref_var, layer[VIEW_MAX_LAYERS];
    html_image im[VIEW_MAX_IMAGES], refim, strip[VIEW_MAX_LAYERS];
    char layer_name[VIEW_MAX_LAYERS][16];
    int nlayers;
} view_data;

/* Reads the n images (n >= 1), the reference ref (or NULL), the first image's variance var (or NULL:
 * found) and the layers PREFIX (or NULL: the first image's) into d (zeroed). 0, or 2 after saying why. */
int view_data_read(view_data *d, const char *const *images, int n, const char *ref, const char *var, const char *layers);
/* The variance of the image at path, into out[cap], as render_files_find_variance finds it (the one
 * its sidecar names, else STEM_var.pfm beside it, each only if of this render); cmd names the command
 * in messages, how the flags of render_files_find_variance. 1 if found (view, and compare's --ref without --ref-var), 0 if none, 2 after printing
 * why it is refused. */
int view_find_variance(const char *path, char *out, size_t cap, const char *cmd, int how);
/* Frees the images and d itself (allocated by the caller with calloc). */
void view_data_free(view_data *d);
#endif
