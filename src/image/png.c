/* png.c — PNG files without zlib: the pixels go into "stored" (uncompressed) deflate blocks.
 *
 * A PNG file (ISO/IEC 15948, RFC 2083) is an 8-byte signature, then chunks, each
 *   length (4 bytes, big-endian) | type (4 ASCII letters) | data (length bytes) | CRC-32 of type + data.
 * We write IHDR (size, 8 bits per channel, colour type 2 = RGB, no interlace), sRGB (the bytes are
 * sRGB-encoded, which image.c has done), the IDAT chunks, and an empty IEND.
 *
 * The IDAT chunks, concatenated, hold one zlib stream (RFC 1950):
 *   0x78 0x01 (deflate, 32 KiB window, no dictionary; 0x7801 is a multiple of 31 as required),
 *   deflate blocks (RFC 1951), here all stored: one header byte (bit 0 = last block, bits 1-2 = 00
 *   "stored"), LEN and its one's complement NLEN (2 bytes each, little-endian), then LEN raw bytes,
 *   LEN <= 65535,
 *   the Adler-32 of the raw bytes (big-endian).
 * The raw bytes are the rows, top first, each prefixed by its filter type, 0 ("None").
 * We put one stored block in each IDAT chunk: the zlib header rides in the first, the Adler-32 in
 * the last. The file is about 3 w h bytes, like a PPM.
 *
 * Both checksums are computed bit by bit, without a table: no shared state between threads, and
 * the cost (8 shifts per byte) is small next to rendering. */
#include "image/png.h"
#include <stdlib.h>
#include <string.h>

#define STORED_MAX 65535u                          /* the most a stored block can hold */
#define ADLER_MOD 65521u                            /* the largest prime below 2^16 */

/* CRC-32 of ISO 3309 / PNG (polynomial 0xEDB88320, reflected), continued from crc: start at 0. */
static uint32_t png_crc32(uint32_t crc, const unsigned char *b, size_t n)
{
    size_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= b[i];
        for (k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/* Adler-32 of RFC 1950, continued from adler: start at 1. */
static uint32_t png_adler32(uint32_t adler, const unsigned char *b, size_t n)
{
    uint32_t s1 = adler & 0xffff, s2 = adler >> 16;
    size_t i;
    for (i = 0; i < n; i++) {
        s1 = (s1 + b[i]) % ADLER_MOD;
        s2 = (s2 + s1) % ADLER_MOD;
    }
    return s2 << 16 | s1;
}

static void put_u32_be(unsigned char *b, uint32_t v)
{
    b[0] = (unsigned char)(v >> 24);
    b[1] = (unsigned char)(v >> 16 & 0xff);
    b[2] = (unsigned char)(v >> 8 & 0xff);
    b[3] = (unsigned char)(v & 0xff);
}

/* One chunk: length, type, data, CRC of type and data. 1 when every byte was written. */
static int put_chunk(FILE *f, const char *type, const unsigned char *data, uint32_t len)
{
    unsigned char head[8], tail[4];
    uint32_t crc;
    put_u32_be(head, len);
    memcpy(head + 4, type, 4);
    crc = png_crc32(png_crc32(0, head + 4, 4), data, len);
    put_u32_be(tail, crc);
    return fwrite(head, 1, 8, f) == 8 && (len == 0 || fwrite(data, 1, len, f) == len) && fwrite(tail, 1, 4, f) == 4;
}

/* Copies n bytes of the raw stream (rows, each led by filter byte 0) from position pos into out. */
static void raw_bytes(const unsigned char *rgb, size_t row_bytes, size_t pos, size_t n, unsigned char *out)
{
    size_t stride = row_bytes + 1, done = 0;
    while (done < n) {
        size_t row = (pos + done) / stride, col = (pos + done) % stride, k;
        if (col == 0) {
            out[done++] = 0;                       /* filter type None */
            continue;
        }
        k = stride - col < n - done ? stride - col : n - done;
        memcpy(out + done, rgb + row * row_bytes + (col - 1), k);
        done += k;
    }
}

/* The IDAT chunks: the zlib stream of the raw rows, one stored block per chunk. */
static int put_idat(FILE *f, const unsigned char *rgb, int w, int h)
{
    size_t row_bytes = (size_t)w * 3, total = (row_bytes + 1) * (size_t)h, pos = 0;
    unsigned char *buf = malloc(2 + 5 + STORED_MAX + 4);
    uint32_t adler = 1;
    int ok = buf != NULL;
    while (ok && pos < total) {
        size_t len = total - pos < STORED_MAX ? total - pos : STORED_MAX, n = 0;
        int last = pos + len == total;
        if (pos == 0) { buf[n++] = 0x78; buf[n++] = 0x01; }         /* zlib header */
        buf[n++] = (unsigned char)last;                            /* BFINAL, BTYPE = 00 stored */
        buf[n++] = (unsigned char)(len & 0xff);
        buf[n++] = (unsigned char)(len >> 8);
        buf[n++] = (unsigned char)(~len & 0xff);
        buf[n++] = (unsigned char)(~len >> 8 & 0xff);
        raw_bytes(rgb, row_bytes, pos, len, buf + n);
        adler = png_adler32(adler, buf + n, len);
        n += len;
        pos += len;
        if (last) { put_u32_be(buf + n, adler); n += 4; }           /* zlib trailer */
        ok = put_chunk(f, "IDAT", buf, (uint32_t)n);
    }
    free(buf);
    return ok;
}

int png_write_rgb8(FILE *f, const unsigned char *rgb, int w, int h)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char srgb_intent[1] = {0};   /* rendering intent: perceptual */
    unsigned char ihdr[13];
    put_u32_be(ihdr, (uint32_t)w);
    put_u32_be(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;     /* bits per channel */
    ihdr[9] = 2;     /* colour type: RGB */
    ihdr[10] = 0;    /* compression: deflate */
    ihdr[11] = 0;    /* filtering: adaptive (we use None on every row) */
    ihdr[12] = 0;    /* no interlace */
    if (fwrite(signature, 1, 8, f) != 8) return 1;
    if (!put_chunk(f, "IHDR", ihdr, 13) || !put_chunk(f, "sRGB", srgb_intent, 1)) return 1;
    if (!put_idat(f, rgb, w, h)) return 1;
    return put_chunk(f, "IEND", NULL, 0) ? 0 : 1;
}
