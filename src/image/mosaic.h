/* mosaic.h — images of one size side by side on a grid, each under its label, to compare at a glance.
 * Panels under 128 pixels wide are magnified 2x to 4x (each pixel a square); over each row a band
 * as high as its longest label, wrapped at spaces to at most 3 lines of the font of font.h, white on
 * dark grey; 4 pixels of background between the panels and around them. */
#ifndef PATHLAB_MOSAIC_H
#define PATHLAB_MOSAIC_H
#include "image/image.h"

typedef struct {
    const image *im;      /* every panel the size of the first */
    const char *label;    /* drawn over the panel ("..", when cut short) */
    float gain;           /* multiplies the pixels: 2^exposure for a render, 1 for a heatmap */
} mosaic_panel;

/* The mosaic of rows x cols panels, given row by row, into m (allocated). 0, or 1 if memory ran out. */
int mosaic_make(image *m, const mosaic_panel *panels, int rows, int cols);
#endif
