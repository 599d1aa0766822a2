/* rgbe.h — Radiance RGBE (.hdr) images, read (G. Ward, "Real Pixels", Graphics Gems II).
 * A text header ("#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe, optional EXPOSURE= and
 * COLORCORR= lines, a blank line), a resolution line in any of its 8 orientations ("-Y H +X W" is
 * the usual: top row first, left to right), then scanlines flat (4 bytes a pixel), new-style
 * run-length encoded (per channel) or old-style (a 1,1,1,n pixel repeats the one before). Decoded
 * without bias, with Ward's half-step centring: value = (m + 0.5) / 256 * 2^(e - 128), 0 for e = 0,
 * then divided by the EXPOSURE (and COLORCORR) the header declares: they say what the writer
 * multiplied. Values are linear RGB; image row 0 is the top row, whatever the orientation. */
#ifndef PATHLAB_RGBE_H
#define PATHLAB_RGBE_H
#include "image/image.h"

/* Same contract as img_read_pfm: 0 on success; on error prints "path: reason" on stderr and
 * returns nonzero, with im empty. Only regular files (a FIFO is refused, never waited on). A file
 * is refused before anything is allocated when it cannot hold the pixels its resolution line
 * declares (at least as many bytes as the most compact encoding of its scanlines) or holds more
 * than their least compact encoding; memory is the file plus the image. */
int img_read_hdr(image *im, const char *path);
/* The header only (the image's size into *w, *h; the file's length checked against it), nothing
 * decoded: a small file that claims gigabytes of the wrong size is refused unread. 0, or 1 after
 * printing "path: reason". */
int img_read_hdr_size(const char *path, int *w, int *h);
#endif
