/* pnm.c — Netpbm colour and grey maps (see decode.h): P6 and P5 (binary: one byte a sample up to
 * maxval 255, two bytes big-endian above), P3 and P2 (decimal text). A header of four tokens (magic,
 * width, height, maxval) separated by whitespace and '#' comments, then one whitespace byte, then
 * the samples, row 0 at the top. Samples above maxval and bytes after the pixels are refused. */
#include "image/decode.h"
#include <stdio.h>
#include <string.h>

typedef struct { long w, h, maxval; int channels, binary; } pnm_header;

static int is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/* Whitespace and comments from *p. */
static void skip_blank(const unsigned char *b, size_t n, size_t *p)
{
    while (*p < n && (is_space(b[*p]) || b[*p] == '#')) {
        if (b[*p] == '#')
            while (*p < n && b[*p] != '\n' && b[*p] != '\r') (*p)++;
        else (*p)++;
    }
}

/* A decimal number at *p (after blanks), at most max; -1 when there is none or it is larger. */
static long number(const unsigned char *b, size_t n, size_t *p, long max)
{
    long v = 0;
    size_t start;
    skip_blank(b, n, p);
    start = *p;
    while (*p < n && b[*p] >= '0' && b[*p] <= '9') {
        v = v * 10 + (b[*p] - '0');
        if (v > max) return -1;
        (*p)++;
    }
    return *p == start ? -1 : v;
}

static int parse_header(const unsigned char *b, size_t n, size_t *p, pnm_header *hd, const char *path)
{
    hd->channels = b[1] == '3' || b[1] == '6' ? 3 : 1;
    hd->binary = b[1] == '5' || b[1] == '6';
    *p = 2;
    hd->w = number(b, n, p, 1L << 20);
    hd->h = hd->w < 1 ? -1 : number(b, n, p, 1L << 20);
    if (hd->w < 1 || hd->h < 1 || hd->w > IMG_DECODE_MAX_PIXELS / hd->h) {
        fprintf(stderr, "%s: bad PPM/PGM size (each side 1 to 1048576, at most %ld pixels)\n", path, IMG_DECODE_MAX_PIXELS);
        return 1;
    }
    hd->maxval = number(b, n, p, 65535);
    if (hd->maxval < 1) {
        fprintf(stderr, "%s: bad PPM/PGM maxval (1 to 65535)\n", path);
        return 1;
    }
    if (*p >= n || !is_space(b[*p])) {
        fprintf(stderr, "%s: no whitespace byte after the maxval: the header ends with one\n", path);
        return 1;
    }
    (*p)++;
    return 0;
}

/* Sample k of the binary raster (big-endian when two bytes). */
static long binary_sample(const unsigned char *b, size_t k, int two)
{
    return two ? (long)b[2 * k] << 8 | b[2 * k + 1] : b[k];
}

static int read_samples(image *im, const unsigned char *b, size_t n, size_t p, const pnm_header *hd, const char *path)
{
    size_t count = (size_t)hd->w * (size_t)hd->h * (size_t)hd->channels, k;
    int two = hd->maxval > 255, c;
    for (k = 0; k < count; k++) {
        long v = hd->binary ? binary_sample(b + p, k, two) : number(b, n, &p, 65535);
        if (v < 0 || v > hd->maxval) {
            fprintf(stderr, "%s: sample %zu (x %zu, y %zu) is %s the maxval %ld\n", path, k, k / hd->channels % hd->w,
                    k / hd->channels / hd->w, v < 0 ? "missing, not a number or far above" : "above", hd->maxval);
            return 1;
        }
        if (hd->channels == 3) im->px[k] = (float)v / (float)hd->maxval;
        else
            for (c = 0; c < 3; c++) im->px[3 * k + (size_t)c] = (float)v / (float)hd->maxval;
    }
    if (hd->binary) p += count * (two ? 2 : 1);
    else skip_blank(b, n, &p);
    if (p != n) {
        fprintf(stderr, "%s: %zu bytes after the pixels (a second image?)\n", path, n - p);
        return 1;
    }
    return 0;
}

int img_decode_ppm(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels)
{
    pnm_header hd;
    size_t p, count, need;
    im->w = im->h = 0;
    im->px = NULL;
    if (n < 3 || b[0] != 'P' || !b[1] || !strchr("2356", b[1])) {
        fprintf(stderr, "%s: not a PPM/PGM file (P2, P3, P5 or P6)\n", path);
        return 1;
    }
    if (parse_header(b, n, &p, &hd, path)) return 1;
    if (hd.w * hd.h > img_decode_cap(max_pixels)) {
        fprintf(stderr, "%s: %ld x %ld pixels, over the %ld allowed here\n", path, hd.w, hd.h, img_decode_cap(max_pixels));
        return 1;
    }
    count = (size_t)hd.w * (size_t)hd.h * (size_t)hd.channels;
    /* binary: exactly the samples' bytes; text: at least one digit and one separator a sample */
    need = hd.binary ? count * (hd.maxval > 255 ? 2 : 1) : 2 * count - 1;
    if (n - p < need) {
        fprintf(stderr, "%s: truncated: %ld x %ld pixels of %d sample%s need %s%zu bytes, the file has %zu after its header\n",
                path, hd.w, hd.h, hd.channels, hd.channels > 1 ? "s" : "", hd.binary ? "" : "at least ", need, n - p);
        return 1;
    }
    if (img_alloc(im, (int)hd.w, (int)hd.h)) {
        fprintf(stderr, "%s: out of memory\n", path);
        return 1;
    }
    if (read_samples(im, b, n, p, &hd, path)) {
        img_free(im);
        return 1;
    }
    info->format = "PPM";
    info->encoding = IMG_ENC_INTEGER;
    for (info->bits = 1; (1L << info->bits) - 1 < hd.maxval; info->bits++) {}
    info->maxval = hd.maxval;
    info->channels = hd.channels;
    info->had_alpha = 0;
    return 0;
}
