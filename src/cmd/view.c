/* view.c — pathlab view: the flags, then the images read (compare/view_images.h) and the viewer's
 * page written (image/html_page.h). */
#include "cmd/view.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "compare/view_images.h"
#include "sys/output_path.h"
#include "sys/shown.h"
#include "util/cli.h"
#include "util/path.h"

typedef struct {
    const char *words[VIEW_MAX_IMAGES];
    int nwords;
    const char *ref, *var, *layers, *out, *title;
} view_args;

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

int view_main(int argc, char **argv)
{
    view_args a;
    view_data *d;
    html_page page;
    int rc;
    if (parse_args(&a, argc, argv)) return 2;
    d = calloc(1, sizeof *d);
    if (!d) { fprintf(stderr, "pathlab view: out of memory\n"); return 2; }
    rc = view_data_read(d, a.words, a.nwords, a.ref, a.var, a.layers);
    if (!rc) {
        memset(&page, 0, sizeof page);
        page.title = a.title ? a.title : path_file_name(a.words[0]);
        page.images = d->im;
        page.nimages = a.nwords;
        page.ref = a.ref ? &d->refim : NULL;
        page.strip = d->strip;
        page.nstrip = d->nlayers;
        rc = html_page_write(a.out, &page) ? 2 : 0;   /* said why: "PAGE: cannot write: No space left on device" */
        if (!rc) fprintf(stderr, "pathlab view: wrote %s (%d image%s%s, %d layer%s; open it in any browser)\n", shown(a.out), a.nwords,
                         a.nwords > 1 ? "s" : "", a.ref ? " and the reference" : "", d->nlayers, d->nlayers == 1 ? "" : "s");
    }
    view_data_free(d);
    return rc;
}
