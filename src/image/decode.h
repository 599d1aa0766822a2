/* decode.h — any image file read into a float RGB image, its format told by its first bytes (never
 * by its name): PFM, Radiance HDR, PNG, TGA, PPM/PGM (P3, P6, P2, P5) and JPEG. Written here from the
 * specifications (RFC 1950/1951, PNG, Truevision TGA, Netpbm, ITU T.81), with no library.
 *
 * Integer formats are returned as the file's integers / maxval (255, 65535, a PPM's maxval) and NOT
 * linearised: the caller decides whether they are sRGB-encoded (a texture, a photograph) or raw.
 * Floats (PFM, HDR) are returned as they are (HDR unbiased, see rgbe.h). Alpha is dropped, after
 * saying so in img_decoded. Greyscale is replicated into R, G and B; a palette is looked up.
 *
 * Every decoder refuses a file whose declared size its data cannot fill BEFORE allocating the image
 * (the most compact encoding of the pixels the header declares must fit in the file), keeps its
 * memory within the file plus the decoded image (plus a row or a block), reads nothing out of
 * bounds, and caps an image at IMG_DECODE_MAX_PIXELS pixels and 2^20 per side. */
#ifndef PATHLAB_DECODE_H
#define PATHLAB_DECODE_H
#include <stddef.h>
#include "image/image.h"

#define IMG_DECODE_MAX_PIXELS (1L << 28)   /* 268 million pixels: 3 GiB of floats */
#define IMG_DECODE_MAX_FILE (1L << 30)     /* a file over 1 GiB is refused before it is read */

typedef enum {
    IMG_ENC_LINEAR,    /* float radiance (PFM, HDR) */
    IMG_ENC_INTEGER    /* integers / maxval, as stored: sRGB-encoded or raw, the caller says which */
} img_encoding;

typedef struct {
    const char *format;     /* "PFM", "HDR", "PNG", "TGA", "PPM", "JPEG" */
    img_encoding encoding;
    int bits;               /* bits per channel in the file: 1..16 for integers, 32 for PFM, 8 (+ shared exponent) for HDR */
    long maxval;            /* IMG_ENC_INTEGER: the code of 1.0 (2^bits - 1, or a PPM's maxval); 0 otherwise */
    int channels;           /* colour channels in the file: 1 (grey) or 3 (colour, a palette's too) */
    int had_alpha;          /* an alpha channel (or PNG transparency) was dropped */
} img_decoded;

/* Reads path (a regular file only: never waits on a FIFO) by its magic bytes. 0 on success; on
 * error prints "path: reason" on stderr, returns nonzero, with im empty. info may be NULL. */
int img_decode_file(image *im, const char *path, img_decoded *info);

/* The same, refusing before it decodes anything an image of more than max_pixels pixels (at most
 * IMG_DECODE_MAX_PIXELS whatever it says): a scene's textures share one budget (scene/texture.h). */
int img_decode_file_within(image *im, const char *path, img_decoded *info, long max_pixels);

/* The decoders on a whole file in memory (b, n bytes), for img_decode_file and the fuzz harnesses:
 * the same contract (path names the file in messages; info is filled, never NULL; at most
 * max_pixels pixels, capped at IMG_DECODE_MAX_PIXELS). */
int img_decode_ppm(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels);
/* PNG: png_decode.c; JPEG: jpeg.c; TGA: tga.c; PPM/PGM: pnm.c */
int img_decode_png(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels);
int img_decode_jpeg(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels);
int img_decode_tga(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels);
/* max_pixels within [0, IMG_DECODE_MAX_PIXELS] (0: a budget spent, nothing allowed) */
static inline long img_decode_cap(long max_pixels) { return max_pixels < 0 ? 0 : max_pixels < IMG_DECODE_MAX_PIXELS ? max_pixels : IMG_DECODE_MAX_PIXELS; }
/* 1 when b (n bytes) starts like a TGA header (TGA has no magic number: its fields are checked). */
int img_looks_like_tga(const unsigned char *b, size_t n);
#endif
