/* view.c — pathlab view: reads the images, the reference, their variances and layers, checks that
 * they have one size, and writes the viewer's page (image/html_page.h). */
#include "cmd/view.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "files/render_files.h"
#include "files/sidecar.h"
#include "image/html_page.h"
#include "sys/output_path.h"
#include "util/cli.h"

#define VIEW_MAX_IMAGES 64
#define VIEW_MAX_LAYERS 16
#define VIEW_PATH 4200

typedef struct {
    const char *words[VIEW_MAX_IMAGES];
    int nwords;
    const char *ref, *var, *layers, *out, *title;
} view_args;

/* Everything read, and the page's view of it. */
typedef struct {
    image img[VIEW_MAX_IMAGES], var[VIEW_MAX_IMAGES], ref, ref_var, layer[VIEW_MAX_LAYERS];
    html_image im[VIEW_MAX_IMAGES], refim, strip[VIEW_MAX_LAYERS];
    char layer_name[VIEW_MAX_LAYERS][16];
    int nlayers;
} view_data;

static int exists(const char *path) { return access(path, F_OK) == 0; }

static const char *base_name(const char *path) { return strrchr(path, '/') ? strrchr(path, '/') + 1 : path; }

/* Reads path into im; the first image read sets the size (*first), later ones must match it. 0 or 2. */
static int read_sized(image *im, const char *path, const char **first, const image *first_img)
{
    if (img_read_pfm(im, path)) return 2;
    if (!*first) { *first = path; return 0; }
    if (im->w == first_img->w && im->h == first_img->h) return 0;
    fprintf(stderr, "pathlab view: %s is %dx%d, %s is %dx%d: the images of a page must have one size\n", path, im->w,
            im->h, *first, first_img->w, first_img->h);
    return 2;
}

/* The variance of the image at path: STEM_var.pfm beside it, else the one its sidecar names. 1 if found. */
static int variance_of(const char *path, char *out, size_t cap)
{
    size_t n = strlen(path), stem = n > 4 && !strcmp(path + n - 4, ".pfm") ? n - 4 : n;
    sidecar m;
    snprintf(out, cap, "%.*s_var.pfm", (int)stem, path);
    if (exists(out)) return 1;
    if (sidecar_read(&m, path) || !m.variance[0]) return 0;
    render_files_variance_path(out, cap, path, m.variance);
    return out[0] && exists(out);
}

/* Reads one image (and its variance, given or found) into slot i of the page. 0 or 2. */
static int read_image(view_data *d, html_image *h, image *im, image *var, const char *path, const char *var_path,
                      const char **first)
{
    char found[VIEW_PATH];
    h->name = base_name(path);
    h->img = im;
    if (read_sized(im, path, first, &d->img[0])) return 2;
    if (!var_path && variance_of(path, found, sizeof found)) var_path = found;
    if (!var_path) return 0;
    if (read_sized(var, var_path, first, &d->img[0])) return 2;
    h->var = var;
    return 0;
}

/* The strip: PREFIX_Lk.pfm as far as they exist, or the first image's layers A:B (its sidecar). 0 or 2. */
static int read_layers(view_data *d, const view_args *a, const char **first)
{
    sidecar m;
    int k, lo = 0, hi = VIEW_MAX_LAYERS - 1;
    char path[VIEW_PATH];
    if (!a->layers && (sidecar_read(&m, a->words[0]) || m.layers_n == 0)) return 0;
    if (!a->layers) lo = m.layers_first, hi = m.layers_first + m.layers_n - 1;
    for (k = lo; k <= hi && k < VIEW_MAX_LAYERS && d->nlayers < VIEW_MAX_LAYERS; k++) {
        html_image *h = &d->strip[d->nlayers];
        if (a->layers) snprintf(path, sizeof path, "%s_L%d.pfm", a->layers, k);
        else render_files_layer_path(path, sizeof path, a->words[0], k);
        if (!exists(path)) continue;   /* a layer deleted since, or a gap in PREFIX_Lk: the others are shown */
        if (read_sized(&d->layer[d->nlayers], path, first, &d->img[0])) return 2;
        snprintf(d->layer_name[d->nlayers], sizeof d->layer_name[0], "L%d", k);
        h->name = d->layer_name[d->nlayers];
        h->img = &d->layer[d->nlayers++];
    }
    if (a->layers && !d->nlayers) { fprintf(stderr, "pathlab view: no layer %s_L0.pfm, %s_L1.pfm ...\n", a->layers, a->layers); return 2; }
    return 0;
}

static const char *const HTML_EXTS[] = {".html", ".htm", NULL};

static int parse_args(view_args *a, int argc, char **argv)
{
    const cli_flag flags[] = {
        {"-o", CLI_STRING, &a->out, 0, 0, NULL, NULL, NULL},
        {"--ref", CLI_STRING, &a->ref, 0, 0, NULL, NULL, NULL},
        {"--var", CLI_STRING, &a->var, 0, 0, NULL, NULL, NULL},
        {"--layers", CLI_STRING, &a->layers, 0, 0, NULL, NULL, NULL},
        {"--title", CLI_STRING, &a->title, 0, 0, NULL, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    memset(a, 0, sizeof *a);
    if (cli_parse("view", argc, argv, tables, NULL, a->words, VIEW_MAX_IMAGES, &a->nwords)) return 2;
    if (!a->nwords || !a->out) { fprintf(stderr, "pathlab view: needs an image and -o PAGE.html\nusage:\n" VIEW_USAGE); return 2; }
    return output_path_check("view", "-o", a->out, HTML_EXTS) ? 2 : 0;   /* before reading anything */
}

static void free_data(view_data *d)
{
    int i;
    for (i = 0; i < VIEW_MAX_IMAGES; i++) img_free(&d->img[i]), img_free(&d->var[i]);
    for (i = 0; i < VIEW_MAX_LAYERS; i++) img_free(&d->layer[i]);
    img_free(&d->ref);
    img_free(&d->ref_var);
    free(d);
}

int view_main(int argc, char **argv)
{
    view_args a;
    view_data *d;
    html_page page;
    const char *first = NULL;
    int i, rc = 0;
    if (parse_args(&a, argc, argv)) return 2;
    d = calloc(1, sizeof *d);
    if (!d) { fprintf(stderr, "pathlab view: out of memory\n"); return 2; }
    for (i = 0; i < a.nwords && !rc; i++) rc = read_image(d, &d->im[i], &d->img[i], &d->var[i], a.words[i], i ? NULL : a.var, &first);
    if (!rc && a.ref) rc = read_image(d, &d->refim, &d->ref, &d->ref_var, a.ref, NULL, &first);
    if (!rc) rc = read_layers(d, &a, &first);
    if (!rc) {
        memset(&page, 0, sizeof page);
        page.title = a.title ? a.title : base_name(a.words[0]);
        page.images = d->im;
        page.nimages = a.nwords;
        page.ref = a.ref ? &d->refim : NULL;
        page.strip = d->strip;
        page.nstrip = d->nlayers;
        rc = html_page_write(a.out, &page) ? 1 : 0;
    }
    free_data(d);
    return rc;
}
