/* view.h — the command `pathlab view IMAGE.pfm [MORE.pfm...] [--ref REF.pfm] [--var VAR.pfm]
 * [--layers PREFIX] -o PAGE.html`: one self-contained HTML page (image/html_page.h) that shows the
 * images in pathlab's viewer, against the reference if given. Variances (for the probe's z-score):
 * --var for the first image, else each image's STEM_var.pfm or the one its sidecar names. Layers
 * (a strip, one exposure each): PREFIX_L0.pfm, PREFIX_L1.pfm... with --layers, else the first
 * image's own --split layers when its sidecar lists some (layers A:B). */
#ifndef PATHLAB_VIEW_H
#define PATHLAB_VIEW_H

#define VIEW_USAGE "  pathlab view IMAGE.pfm [MORE.pfm ...] [--ref REF.pfm] [--var VAR.pfm] [--layers PREFIX] [--title T] -o PAGE.html\n" \
                   "                one HTML page, offline, any browser: exposure, zoom, the pixel's values, split view\n" \
                   "                and signed difference against REF, the images cycled with the keys (docs/guide.md)\n"

/* Exit status 0, 1 when the page could not be written, 2 for bad arguments or unreadable inputs. */
int view_main(int argc, char **argv);
#endif
