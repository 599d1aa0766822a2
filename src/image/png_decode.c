/* png_decode.c — PNG files read (see decode.h), from the PNG specification (ISO/IEC 15948):
 * every colour type (0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA) at every bit depth it allows
 * (1, 2, 4, 8, 16), Adam7 interlacing, the five row filters. Chunks: IHDR, PLTE (used), IDAT
 * (concatenated, inflated by inflate.c), IEND; tRNS only marks the image as having had
 * transparency (alpha is dropped anyway); other ancillary chunks are skipped; an unknown critical
 * chunk is refused. Every chunk's CRC-32 is checked: a corrupted file is refused, not guessed at.
 * The IDAT data must be able to fill the rows (deflate's best ratio is 1032 to 1) before anything
 * is allocated; memory is the file, the filtered rows and the image. */
#include "image/decode.h"
#include "image/inflate.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    long w, h;
    int depth, type, interlace, channels;   /* channels: samples per pixel in the file */
    unsigned char plte[256][3];
    int plte_len, trns;
    unsigned char *idat;                    /* the IDAT chunks' data, concatenated */
    size_t idat_len;
} png_info;

static uint32_t be32(const unsigned char *b)
{
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
}

static uint32_t crc32_of(const unsigned char *b, size_t n)
{
    uint32_t table[256], c = 0xffffffffu, k, v;
    size_t i;
    int j;
    for (k = 0; k < 256; k++) {   /* the reflected polynomial 0xedb88320 (2 K steps: nothing next to a chunk) */
        for (v = k, j = 0; j < 8; j++) v = v & 1 ? 0xedb88320u ^ (v >> 1) : v >> 1;
        table[k] = v;
    }
    for (i = 0; i < n; i++) c = table[(c ^ b[i]) & 255] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

static int fail(const char *path, const char *what)
{
    fprintf(stderr, "%s: %s\n", path, what);
    return 1;
}

static int fail_chunk(const char *path, const char *what)
{
    fail(path, what);
    return -1;
}

static int ihdr(png_info *p, const unsigned char *d, uint32_t len, const char *path)
{
    static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
    int depth_ok;
    if (len != 13) return fail(path, "IHDR chunk of the wrong length (13 bytes)");
    p->w = (long)be32(d);
    p->h = (long)be32(d + 4);
    p->depth = d[8];
    p->type = d[9];
    p->interlace = d[12];
    if (p->w < 1 || p->h < 1 || p->w > (1L << 20) || p->h > (1L << 20) || p->w > IMG_DECODE_MAX_PIXELS / p->h) {
        fprintf(stderr, "%s: PNG of %ld x %ld pixels: each side 1 to 1048576 and at most %ld pixels here\n",
                path, p->w, p->h, IMG_DECODE_MAX_PIXELS);
        return 1;
    }
    depth_ok = p->type == 0 ? (p->depth == 1 || p->depth == 2 || p->depth == 4 || p->depth == 8 || p->depth == 16)
             : p->type == 3 ? (p->depth == 1 || p->depth == 2 || p->depth == 4 || p->depth == 8)
             : (p->type == 2 || p->type == 4 || p->type == 6) && (p->depth == 8 || p->depth == 16);
    if (!depth_ok || d[10] != 0 || d[11] != 0 || p->interlace > 1)
        return fail(path, "IHDR: a colour type and bit depth PNG does not allow, or an unknown compression, filter or interlace method");
    p->channels = channels[p->type];
    return 0;
}

/* One chunk at b[*pos]: checked, then used or skipped. 1 for IEND, 0 to go on, -1 on error. */
static int chunk(png_info *p, const unsigned char *b, size_t n, size_t *pos, const char *path)
{
    uint32_t len;
    const unsigned char *type, *d;
    if (n - *pos < 12 || (len = be32(b + *pos)) > n - *pos - 12) return fail_chunk(path, "truncated: a chunk runs past the end of the file");
    type = b + *pos + 4;
    d = type + 4;
    if (crc32_of(type, len + 4) != be32(d + len)) {
        fprintf(stderr, "%s: chunk %.4s at byte %zu: its CRC does not match (a corrupted file)\n", path, (const char *)type, *pos);
        return -1;
    }
    *pos += 12 + (size_t)len;
    if (p->w == 0 && memcmp(type, "IHDR", 4) != 0) return fail_chunk(path, "the first chunk is not IHDR");
    if (memcmp(type, "IHDR", 4) == 0) return p->w ? fail_chunk(path, "a second IHDR chunk") : -ihdr(p, d, len, path);
    if (memcmp(type, "IEND", 4) == 0) return 1;
    if (memcmp(type, "IDAT", 4) == 0) {
        memcpy(p->idat + p->idat_len, d, len);   /* the buffer is as large as the file */
        p->idat_len += len;
    } else if (memcmp(type, "PLTE", 4) == 0) {
        if (len % 3 || len == 0 || len > 768) return fail_chunk(path, "PLTE chunk: 1 to 256 entries of 3 bytes");
        memcpy(p->plte, d, len);
        p->plte_len = (int)(len / 3);
    } else if (memcmp(type, "tRNS", 4) == 0) p->trns = 1;
    else if (!(type[0] & 0x20)) {
        fprintf(stderr, "%s: unknown critical chunk '%.4s': cannot be skipped\n", path, (const char *)type);
        return -1;
    }
    return 0;
}

static int read_chunks(png_info *p, const unsigned char *b, size_t n, const char *path)
{
    size_t pos = 8;
    int r = 0;
    p->idat = malloc(n);
    if (!p->idat) return fail(path, "out of memory");
    while (r == 0) r = chunk(p, b, n, &pos, path);
    if (r < 0) return 1;
    if (p->type == 3 && p->plte_len == 0) return fail(path, "a palette image without a PLTE chunk");
    if (p->idat_len == 0) return fail(path, "no IDAT chunk: no pixel data");
    return 0;
}

/* Adam7: the passes' first column and row and their steps; one pass without interlacing. */
static const int ADAM7[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};

static void pass_size(const png_info *p, int k, long *pw, long *ph)
{
    if (!p->interlace) { *pw = p->w; *ph = p->h; return; }
    *pw = (p->w - ADAM7[k][0] + ADAM7[k][2] - 1) / ADAM7[k][2];
    *ph = (p->h - ADAM7[k][1] + ADAM7[k][3] - 1) / ADAM7[k][3];
    if (*pw <= 0 || *ph <= 0) *pw = *ph = 0;
}

static size_t row_bytes(const png_info *p, long pw)
{
    return ((size_t)pw * (size_t)p->channels * (size_t)p->depth + 7) / 8;
}

/* The filtered rows' bytes: each pass's rows, one filter byte before each. */
static size_t raw_size(const png_info *p)
{
    size_t total = 0;
    long pw, ph;
    int k;
    for (k = 0; k < (p->interlace ? 7 : 1); k++) {
        pass_size(p, k, &pw, &ph);
        if (pw) total += (size_t)ph * (1 + row_bytes(p, pw));
    }
    return total;
}

static int paeth(int a, int b, int c)
{
    int pa = abs(b - c), pb = abs(a - c), pc = abs(a + b - 2 * c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Undoes a row's filter in place (prev: the row above, unfiltered, or NULL for the first). */
static int unfilter(unsigned char *row, const unsigned char *prev, size_t len, size_t bpp, int filter)
{
    size_t i;
    for (i = 0; i < len; i++) {
        int a = i >= bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0, c = prev && i >= bpp ? prev[i - bpp] : 0;
        switch (filter) {
        case 0: break;
        case 1: row[i] = (unsigned char)(row[i] + a); break;
        case 2: row[i] = (unsigned char)(row[i] + b); break;
        case 3: row[i] = (unsigned char)(row[i] + ((a + b) >> 1)); break;
        case 4: row[i] = (unsigned char)(row[i] + paeth(a, b, c)); break;
        default: return -1;
        }
    }
    return 0;
}

/* Sample j of an unfiltered row (depth bits each, packed from the most significant bit). */
static unsigned sample(const unsigned char *row, size_t j, int depth)
{
    if (depth == 16) return (unsigned)row[2 * j] << 8 | row[2 * j + 1];
    if (depth == 8) return row[j];
    return (unsigned)(row[j * (size_t)depth / 8] >> (8 - depth - (int)(j * (size_t)depth % 8))) & ((1u << depth) - 1);
}

/* One unfiltered row of pass k, row r, into the image. -1 for a palette index past PLTE. */
static int put_row(image *im, const png_info *p, const unsigned char *row, int k, long r, long pw)
{
    long x0 = p->interlace ? ADAM7[k][0] : 0, dx = p->interlace ? ADAM7[k][2] : 1;
    long y = (p->interlace ? ADAM7[k][1] + r * ADAM7[k][3] : r), i;
    float maxval = (float)((1u << p->depth) - 1);
    for (i = 0; i < pw; i++) {
        float *px = im->px + 3 * ((size_t)y * p->w + (size_t)(x0 + i * dx));
        size_t j = (size_t)i * p->channels;
        int c;
        if (p->type == 3) {
            unsigned idx = sample(row, j, p->depth);
            if ((int)idx >= p->plte_len) return -1;
            for (c = 0; c < 3; c++) px[c] = (float)p->plte[idx][c] / 255.0f;
        } else if (p->channels >= 3)
            for (c = 0; c < 3; c++) px[c] = (float)sample(row, j + (size_t)c, p->depth) / maxval;
        else px[0] = px[1] = px[2] = (float)sample(row, j, p->depth) / maxval;
    }
    return 0;
}

static int unfilter_all(image *im, const png_info *p, unsigned char *raw, const char *path)
{
    size_t bpp = ((size_t)p->channels * p->depth + 7) / 8, at = 0, len;
    long pw, ph, r;
    int k;
    for (k = 0; k < (p->interlace ? 7 : 1); k++) {
        pass_size(p, k, &pw, &ph);
        len = row_bytes(p, pw);
        for (r = 0; pw && r < ph; r++, at += 1 + len) {
            unsigned char *row = raw + at + 1;
            if (unfilter(row, r ? row - 1 - len : NULL, len, bpp, raw[at])) {
                fprintf(stderr, "%s: row %ld%s: unknown filter type %d (0 to 4)\n", path, r, p->interlace ? " of an Adam7 pass" : "", raw[at]);
                return 1;
            }
            if (put_row(im, p, row, k, r, pw)) return fail(path, "a palette index past the end of PLTE");
        }
    }
    return 0;
}

static int decode_rows(image *im, png_info *p, const char *path)
{
    size_t need = raw_size(p);
    unsigned char *raw;
    const char *why;
    int err;
    if (p->idat_len < need / INFLATE_MAX_RATIO) {
        fprintf(stderr, "%s: truncated: %ld x %ld pixels take %zu bytes of rows, which %zu bytes of compressed "
                "data cannot hold (deflate compresses at most %d to 1)\n", path, p->w, p->h, need, p->idat_len, INFLATE_MAX_RATIO);
        return 1;
    }
    raw = malloc(need);
    if (!raw || img_alloc(im, (int)p->w, (int)p->h)) {
        free(raw);
        return fail(path, "out of memory");
    }
    err = zlib_inflate(p->idat, p->idat_len, raw, need, &why);
    if (err) fprintf(stderr, "%s: the pixel data (IDAT): %s\n", path, why);
    else err = unfilter_all(im, p, raw, path);
    free(raw);
    return err;
}

int img_decode_png(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    png_info p;
    int err;
    im->w = im->h = 0;
    im->px = NULL;
    memset(&p, 0, sizeof p);
    if (n < 8 || memcmp(b, sig, 8) != 0) return fail(path, "not a PNG file");
    err = read_chunks(&p, b, n, path);
    if (!err && p.w * p.h > img_decode_cap(max_pixels))   /* before inflating: 55 KB can hold 16384^2 pixels */
        err = fprintf(stderr, "%s: PNG of %ld x %ld pixels, over the %ld allowed here\n", path, p.w, p.h, img_decode_cap(max_pixels)) > 0;
    if (!err) err = decode_rows(im, &p, path);
    free(p.idat);
    if (err) {
        img_free(im);
        return 1;
    }
    info->format = "PNG";
    info->encoding = IMG_ENC_INTEGER;
    info->bits = p.type == 3 ? 8 : p.depth;
    info->maxval = (1L << info->bits) - 1;
    info->channels = p.type == 0 || p.type == 4 ? 1 : 3;
    info->had_alpha = p.type == 4 || p.type == 6 || p.trns;
    return 0;
}
