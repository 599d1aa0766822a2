/* linear_file.c — PFM or RGBE by the file's name (linear_file.h). */
#include "image/linear_file.h"
#include "image/rgbe.h"

int img_is_rgbe(const char *path) { return img_format_of(path) == IMG_HDR; }

int img_read_linear(image *im, const char *path, img_pfm_info *info)
{
    if (!img_is_rgbe(path)) return img_read_pfm_info(im, path, info);
    if (img_read_hdr(im, path)) return 1;
    if (info) info->channels = 3, info->big_endian = 0, info->scale = 1.0, info->w = im->w, info->h = im->h;
    return 0;
}
