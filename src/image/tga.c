/* tga.c — Truevision TGA (see decode.h): image types 1 and 9 (colour-mapped, 8- or 16-bit indices
 * into a map of 15-, 16-, 24- or 32-bit entries), 2 and 10 (true colour, 15, 16, 24 or 32 bits:
 * BGR, BGRA, or 5-5-5 with one attribute bit) and 3 and 11 (grey, 8 bits, or 16 with alpha); 9, 10
 * and 11 run-length encoded (a packet byte: high bit set, one pixel repeated (low 7 bits) + 1 times;
 * clear, (low 7 bits) + 1 literal pixels; packets may cross rows). The descriptor's bit 5 says the
 * first row is the top (else the bottom, the format's default), bit 4 that rows run right to left.
 * Bytes after the pixels (a TGA 2.0 extension area and footer) are allowed and ignored. */
#include "image/decode.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int type, depth, cmap_type, cmap_first, cmap_len, cmap_depth, top, right_to_left;
    long w, h;
    size_t data;       /* offset of the pixel data */
    size_t cmap;       /* offset of the colour map */
} tga_header;

static int u16(const unsigned char *b) { return b[0] | b[1] << 8; }

static int depth_ok(int type, int depth)
{
    switch (type & 7) {
    case 1: return depth == 8 || depth == 16;
    case 2: return depth == 15 || depth == 16 || depth == 24 || depth == 32;
    case 3: return depth == 8 || depth == 16;
    default: return 0;
    }
}

static int map_depth_ok(int d) { return d == 15 || d == 16 || d == 24 || d == 32; }

int img_looks_like_tga(const unsigned char *b, size_t n)
{
    int type;
    if (n < 18) return 0;
    type = b[2];
    if (b[1] > 1 || !(type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11)) return 0;
    if ((type & 7) == 1 && (b[1] != 1 || !map_depth_ok(b[7]) || u16(b + 5) == 0)) return 0;
    if (b[1] == 1 && !map_depth_ok(b[7])) return 0;
    return u16(b + 12) > 0 && u16(b + 14) > 0 && depth_ok(type, b[16]) && (b[17] & 0xc0) == 0;
}

/* One pixel of `bytes` bytes at q, of depth bits, into rgb (0..255 or 0..31 codes) and *alpha. */
static void pixel(const unsigned char *q, int depth, int grey, int *rgb)
{
    if (grey) { rgb[0] = rgb[1] = rgb[2] = q[0]; return; }
    if (depth <= 16) {
        int v = q[0] | q[1] << 8;
        rgb[0] = v >> 10 & 31; rgb[1] = v >> 5 & 31; rgb[2] = v & 31;
        return;
    }
    rgb[0] = q[2]; rgb[1] = q[1]; rgb[2] = q[0];
}

static int parse(const unsigned char *b, size_t n, tga_header *hd, const char *path)
{
    size_t map_bytes;
    if (!img_looks_like_tga(b, n)) {
        fprintf(stderr, "%s: not a TGA file this reader takes (types 1, 2, 3, 9, 10, 11; depths 8, 15, 16, 24, 32)\n", path);
        return 1;
    }
    hd->cmap_type = b[1]; hd->type = b[2];
    hd->cmap_first = u16(b + 3); hd->cmap_len = u16(b + 5); hd->cmap_depth = b[7];
    hd->w = u16(b + 12); hd->h = u16(b + 14); hd->depth = b[16];
    hd->top = b[17] >> 5 & 1; hd->right_to_left = b[17] >> 4 & 1;
    hd->cmap = 18 + (size_t)b[0];
    map_bytes = hd->cmap_type ? (size_t)hd->cmap_len * (((size_t)hd->cmap_depth + 7) / 8) : 0;
    hd->data = hd->cmap + map_bytes;
    if (hd->data > n) {
        fprintf(stderr, "%s: truncated: the file ends in its %s\n", path, hd->cmap_type ? "colour map" : "image ID");
        return 1;
    }
    return 0;
}

/* The pixel of value code (an index into the map for types 1 and 9) as codes into rgb; -1 for an
 * index outside the map. */
static int lookup(const tga_header *hd, const unsigned char *b, const unsigned char *q, int *rgb)
{
    long index;
    if ((hd->type & 7) != 1) {
        pixel(q, hd->depth, (hd->type & 7) == 3, rgb);
        return 0;
    }
    index = (hd->depth == 16 ? (q[0] | q[1] << 8) : q[0]) - hd->cmap_first;
    if (index < 0 || index >= hd->cmap_len) return -1;
    pixel(b + hd->cmap + (size_t)index * ((hd->cmap_depth + 7) / 8), hd->cmap_depth, 0, rgb);
    return 0;
}

static void store(image *im, const tga_header *hd, size_t k, const int *rgb, float maxval)
{
    long x = (long)(k % (size_t)hd->w), y = (long)(k / (size_t)hd->w);
    float *px;
    if (hd->right_to_left) x = hd->w - 1 - x;
    if (!hd->top) y = hd->h - 1 - y;
    px = im->px + 3 * ((size_t)y * hd->w + x);
    px[0] = (float)rgb[0] / maxval; px[1] = (float)rgb[1] / maxval; px[2] = (float)rgb[2] / maxval;
}

/* The pixels, raw or run-length encoded. */
static int read_pixels(image *im, const unsigned char *b, size_t n, const tga_header *hd, float maxval, const char *path)
{
    size_t total = (size_t)hd->w * hd->h, k = 0, p = hd->data, bpp = ((size_t)hd->depth + 7) / 8;
    int rgb[3];
    while (k < total) {
        size_t count = 1, i;
        int run = 0;
        if (hd->type >= 9) {
            if (p >= n) break;
            run = b[p] >> 7;
            count = (size_t)(b[p++] & 127) + 1;
            if (count > total - k) count = total - k;   /* a packet past the last pixel: cut */
        }
        for (i = 0; i < count; i++) {
            if (n - p < bpp) goto truncated;
            if (lookup(hd, b, b + p, rgb)) {
                fprintf(stderr, "%s: pixel %zu: colour index outside the colour map\n", path, k);
                return 1;
            }
            store(im, hd, k++, rgb, maxval);
            if (!run || i + 1 == count) p += bpp;
        }
    }
    if (k == total) return 0;
truncated:
    fprintf(stderr, "%s: truncated: pixel data ends after %zu of %zu pixels\n", path, k, total);
    return 1;
}

int img_decode_tga(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels)
{
    tga_header hd;
    size_t total, bpp, need;
    int depth;
    im->w = im->h = 0;
    im->px = NULL;
    if (parse(b, n, &hd, path)) return 1;
    total = (size_t)hd.w * hd.h;
    bpp = ((size_t)hd.depth + 7) / 8;
    need = hd.type >= 9 ? (total + 127) / 128 * (1 + bpp) : total * bpp;   /* the most compact encoding */
    if (n - hd.data < need) {
        fprintf(stderr, "%s: truncated: %ld x %ld pixels need %s%zu bytes, the file has %zu after its header\n",
                path, hd.w, hd.h, hd.type >= 9 ? "at least " : "", need, n - hd.data);
        return 1;
    }
    if (hd.w * hd.h > img_decode_cap(max_pixels)) {
        fprintf(stderr, "%s: %ld x %ld pixels, over the %ld allowed here\n", path, hd.w, hd.h, img_decode_cap(max_pixels));
        return 1;
    }
    depth = (hd.type & 7) == 1 ? hd.cmap_depth : hd.depth;
    if (img_alloc(im, (int)hd.w, (int)hd.h)) {
        fprintf(stderr, "%s: out of memory\n", path);
        return 1;
    }
    if (read_pixels(im, b, n, &hd, depth <= 16 && (hd.type & 7) != 3 ? 31.0f : 255.0f, path)) {
        img_free(im);
        return 1;
    }
    info->format = "TGA";
    info->encoding = IMG_ENC_INTEGER;
    info->bits = depth <= 16 && (hd.type & 7) != 3 ? 5 : 8;
    info->maxval = (1L << info->bits) - 1;
    info->channels = (hd.type & 7) == 3 ? 1 : 3;
    info->had_alpha = depth == 32 || ((hd.type & 7) == 3 && depth == 16);
    return 0;
}
