/* image.h — linear RGB float images and their files.
 * PFM: little-endian (scale -1) on write, rows bottom to top; read also big-endian and greyscale Pf.
 * PPM: P6, 8 bits, exposure (x 2^stops) then the sRGB curve. PNG: the same bytes as the PPM, in an
 * 8-bit RGB PNG with stored (uncompressed) deflate blocks. Writes are atomic: a temporary file
 * in the same folder, renamed over the target only when complete. */
#ifndef PATHLAB_IMAGE_H
#define PATHLAB_IMAGE_H
#include "math/vec.h"

typedef struct { int w, h; float *px; } image;   /* px: 3 floats per pixel, row 0 = top row */

int img_alloc(image *im, int w, int h);          /* zero-filled; 0 on success */
void img_free(image *im);
/* The file formats, told apart by the file name's extension in any case: IMG_UNKNOWN for another
 * extension or none. IMG_HDR (".hdr", Radiance RGBE) is read only (image/rgbe.h). img_extension: ".pfm" of "dir/x.pfm" (dot included), "" without one. */
typedef enum { IMG_UNKNOWN, IMG_PFM, IMG_PPM, IMG_PNG, IMG_HDR } img_format;
img_format img_format_of(const char *path);
/* The extensions of those formats, NULL-terminated, for output_path_check: every image format, PFM
 * alone (the files that carry values: variances, layers, sample counts), or the pictures (PNG, PPM:
 * heatmaps, which a .pfm without its sidecar would make pass for a render). */
extern const char *const IMG_EXTENSIONS[];
extern const char *const IMG_PFM_EXTENSION[];
extern const char *const IMG_PICTURE_EXTENSIONS[];
/* 1 for a .png or .ppm name: a picture (what a heatmap may be), not a render */
int img_is_picture(const char *path);
const char *img_extension(const char *path);
/* Writes by extension (img_format_of); prints "path: reason" on stderr and returns nonzero on error. */
int img_write(const image *im, const char *path, float exposure);
int img_write_pfm(const image *im, const char *path);
int img_write_ppm(const image *im, const char *path, float exposure);
int img_write_png(const image *im, const char *path, float exposure);
/* Reads a PFM (PF or Pf, either byte order; Pf is replicated into R, G and B); on error prints
 * "path: reason" and returns nonzero, with im empty. The reader is strict, and names the cause of
 * the usual mistakes: a header with CR LF line ends, a blank line, a comment or no single whitespace
 * after the scale; pixel data cut short or followed by more bytes (exactly w*h*channels*4 bytes);
 * a scale whose sign gives the wrong byte order (the values read in it are absurd, the other order
 * gives ordinary ones). img_read_pfm_info also reports the header's facts into *info (may be NULL). */
typedef struct {
    int channels;     /* 3 for "PF" (colour), 1 for "Pf" (greyscale) */
    int big_endian;   /* the scale is positive */
    double scale;     /* as written in the header */
    int w, h;         /* the header's size */
} img_pfm_info;
int img_read_pfm_info(image *im, const char *path, img_pfm_info *info);
/* The header only, and the file's length checked against it (no pixel read, nothing allocated): what
 * a caller compares with what it expects (a reference's size and channels) before reading a file
 * that may claim gigabytes. 0, or 1 after printing "path: reason" as img_read_pfm would. */
int img_read_pfm_header(const char *path, img_pfm_info *info);
int img_read_pfm(image *im, const char *path);   /* img_read_pfm_info(im, path, NULL) */
/* Linear [0,1] -> sRGB-encoded [0,1]. */
float srgb_encode(float linear);
#endif
