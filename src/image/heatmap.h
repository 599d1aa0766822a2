/* heatmap.h — where two images differ, as a picture: |a - ref| per pixel (the mean over R, G, B)
 * on a colour ramp black-red-yellow-white, and the ramp itself as a legend. pathlab diff --heatmap
 * writes one; pathlab compare one per estimator, all on one scale so that their colours compare. */
#ifndef PATHLAB_HEATMAP_H
#define PATHLAB_HEATMAP_H
#include "image/image.h"

/* The heatmap of a against ref: each pixel's |a - ref| averaged over RGB, black at 0, white at `scale`
 * (or, when scale <= 0, at the largest of those averages), the scale used in *used (if not NULL).
 * 0, or 1 if the sizes differ or memory runs out. */
int img_heatmap(image *out, const image *a, const image *ref, double scale, double *used);
/* The ramp, w x h, 0 at the left to white at the right: the heatmap of a gradient. 0, or 1. */
int img_heatmap_legend(image *legend, int w, int h);
#endif
