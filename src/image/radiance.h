/* radiance.h — is an image plausible radiance? Radiance is a finite number >= 0 in every
 * pixel-channel; img_check_radiance finds the NaN, +Inf, -Inf and negative ones and says where.
 * The rule for negative values: v < -1e-6 x m, where m is the image's typical value
 * (img_typical_abs), is an error; a negative value closer to 0 (float rounding in a sum, e.g.
 * -1e-8 in an image of values near 0.5) is only a warning, and -0.0 is fine. */
#ifndef PATHLAB_RADIANCE_H
#define PATHLAB_RADIANCE_H
#include "image/image.h"

#define RADIANCE_NEG_TOL 1e-6   /* relative to img_typical_abs */
#define RADIANCE_MAX_LISTED 16  /* max_listed is clamped to it */

/* Prints on stderr one line per kind found, e.g.
 *   "x.pfm: 3 pixel-channels are NaN, first at x 12, y 40 (red), x 13, y 40 (green), ...; y = 0 is the top row"
 *   "x.pfm: 2 pixel-channels are negative (below -1e-06 x the mean 0.42, down to -0.5), first at x 1, y 0 (red -0.5), ..."
 *   "x.pfm: warning: 1 pixel-channel is slightly negative (...: float rounding?), at x 3, y 3 (blue -2e-08)..."
 * listing the first max_listed positions of each kind (row by row from the top), then, after an
 * error, a line on what radiance must be. Returns nonzero when there is an error (NaN, infinite or
 * negative beyond the tolerance), 0 when the image is clean or has only warnings. */
int img_check_radiance(const image *im, const char *path, int max_listed);
/* The median of |v| over the finite nonzero values, rounded down to a power of 2 (0 if there is
 * none): the scale of the tolerance for negative values. Not the mean, which one huge value moves:
 * a pixel of 1e11 made -0.5 look like float rounding. */
double img_typical_abs(const image *im);
#endif
