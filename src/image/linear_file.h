/* linear_file.h — an image file of linear radiance read by its name: a PFM, or a Radiance RGBE
 * file (".hdr", image/rgbe.h: decoded with the half step), for the commands that compare
 * radiance (grade, diff, view). Students' gKit renderers write .hdr as often as PFM. */
#ifndef PATHLAB_LINEAR_FILE_H
#define PATHLAB_LINEAR_FILE_H
#include "image/image.h"

/* img_read_pfm_info for a PFM; for an .hdr, img_read_hdr with *info (may be NULL) set to 3 channels.
 * 0, or nonzero after printing "path: reason". */
int img_read_linear(image *im, const char *path, img_pfm_info *info);
/* 1 if path names an RGBE file (.hdr, any case). */
int img_is_rgbe(const char *path);
#endif
