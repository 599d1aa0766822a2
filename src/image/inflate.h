/* inflate.h — zlib streams (RFC 1950) of deflate data (RFC 1951) decompressed into a buffer of a
 * size known in advance (a PNG's filtered rows): stored, fixed-Huffman and dynamic-Huffman blocks;
 * the zlib header (method 8, window <= 32 KiB, no preset dictionary, FCHECK) and the Adler-32 of
 * the output are checked. Written from the RFCs. Never writes past out[cap - 1] nor reads past
 * in[n - 1]; deflate's best ratio is 1032 to 1, so a stream shorter than cap / INFLATE_MAX_RATIO
 * bytes cannot fill cap: callers refuse it before allocating. */
#ifndef PATHLAB_INFLATE_H
#define PATHLAB_INFLATE_H
#include <stddef.h>

#define INFLATE_MAX_RATIO 1032

/* 0 when the stream decompresses to exactly cap bytes, with a valid header and Adler-32; else
 * nonzero and *why says what was wrong ("truncated", "more data than expected", ...). */
int zlib_inflate(const unsigned char *in, size_t n, unsigned char *out, size_t cap, const char **why);
#endif
