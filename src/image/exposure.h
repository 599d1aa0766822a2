/* exposure.h — the automatic exposure of an image (convert --exposure auto, render --exposure auto,
 * and the viewer's, web/viewer.js, by the same rule): the median luminance (0.2126 R + 0.7152 G +
 * 0.0722 B) of the pixels that are not black brought to mid-grey, 0.18 (46% in sRGB). The black
 * pixels (the background, or everything but the lamp in L0) do not count, and the few pixels of an
 * emitter cannot move a median: every L_k shows its surfaces, not its brightest light. */
#ifndef PATHLAB_EXPOSURE_H
#define PATHLAB_EXPOSURE_H
#include "image/image.h"

#define EXPOSURE_MID_GREY 0.18
/* The exposure in stops (rounded to 0.1), 0 for an image with no pixel above 0. */
float img_auto_exposure(const image *im);
#endif
