/* decode.c — img_decode_file: the format from the first bytes, then the decoder of that format
 * (see decode.h). PFM and HDR are read by their own readers (image.h, rgbe.h), which check the
 * size before reading the pixels; the others get the whole file in memory, at most
 * IMG_DECODE_MAX_FILE bytes. */
#include "image/decode.h"
#include "sys/shown.h"
#include "image/rgbe.h"
#include "sys/input_file.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum { FMT_UNKNOWN, FMT_PFM, FMT_HDR, FMT_PNG, FMT_JPEG, FMT_PPM, FMT_TGA } file_format;

static int is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/* The format of a file from its first n bytes (TGA, which has no magic number, last). */
static file_format sniff(const unsigned char *b, size_t n)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (n >= 3 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f') && is_space(b[2])) return FMT_PFM;
    if (n >= 2 && b[0] == '#' && b[1] == '?') return FMT_HDR;
    if (n >= 8 && memcmp(b, png, 8) == 0) return FMT_PNG;
    if (n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff) return FMT_JPEG;
    if (n >= 3 && b[0] == 'P' && strchr("2356", b[1]) && b[1] && (is_space(b[2]) || b[2] == '#')) return FMT_PPM;
    if (img_looks_like_tga(b, n)) return FMT_TGA;
    return FMT_UNKNOWN;
}

/* The whole file, or NULL after printing why (too large, a read error). */
static unsigned char *read_all(FILE *f, const char *path, size_t *n)
{
    unsigned char *b;
    long size;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fprintf(stderr, "%s: cannot find the file's size\n", path);
        return NULL;
    }
    if (size > IMG_DECODE_MAX_FILE) {
        fprintf(stderr, "%s: %ld bytes: over the %ld this reader takes\n", path, size, IMG_DECODE_MAX_FILE);
        return NULL;
    }
    b = malloc(size ? (size_t)size : 1);
    if (!b) fprintf(stderr, "%s: out of memory\n", path);
    else if (fread(b, 1, (size_t)size, f) != (size_t)size) {
        fprintf(stderr, "%s: read error: %s\n", path, strerror(errno));
        free(b);
        return NULL;
    }
    *n = (size_t)size;
    return b;
}

static int unknown_format(const char *path, const unsigned char *b, size_t n)
{
    size_t i;
    fprintf(stderr, "%s: unknown image format (not PFM, Radiance HDR, PNG, JPEG, PPM/PGM or TGA); it begins with", path);
    for (i = 0; i < n && i < 8; i++) fprintf(stderr, " %02x", b[i]);
    fprintf(stderr, "%s\n", n ? "" : " nothing (an empty file)");
    return 1;
}

static int decode_float(image *im, const char *path, file_format fmt, img_decoded *info, long max_pixels)
{
    img_pfm_info pfm;
    int w, h;
    /* the size from the header first: an .hdr's run-length scanlines can claim 64 times its bytes */
    if (fmt == FMT_HDR ? img_read_hdr_size(path, &w, &h) : img_read_pfm_header(path, &pfm)) return 1;
    if (fmt != FMT_HDR) w = pfm.w, h = pfm.h;
    if ((long)w * h > img_decode_cap(max_pixels)) {
        fprintf(stderr, "%s: %d x %d pixels, over the %ld allowed here\n", shown(path), w, h, img_decode_cap(max_pixels));
        return 1;
    }
    if (fmt == FMT_HDR ? img_read_hdr(im, path) : img_read_pfm_info(im, path, &pfm)) return 1;
    info->format = fmt == FMT_HDR ? "HDR" : "PFM";
    info->encoding = IMG_ENC_LINEAR;
    info->bits = fmt == FMT_HDR ? 8 : 32;
    info->channels = fmt == FMT_HDR ? 3 : pfm.channels;
    return 0;
}

static int decode_bytes(image *im, const unsigned char *b, size_t n, const char *path, file_format fmt,
                        img_decoded *info, long max_pixels)
{
    switch (fmt) {
    case FMT_PPM: return img_decode_ppm(im, b, n, path, info, max_pixels);
    case FMT_TGA: return img_decode_tga(im, b, n, path, info, max_pixels);
    case FMT_PNG: return img_decode_png(im, b, n, path, info, max_pixels);
    case FMT_JPEG: return img_decode_jpeg(im, b, n, path, info, max_pixels);
    default: return unknown_format(path, b, n);
    }
}

int img_decode_file(image *im, const char *path, img_decoded *info) { return img_decode_file_within(im, path, info, IMG_DECODE_MAX_PIXELS); }

int img_decode_file_within(image *im, const char *path, img_decoded *info, long max_pixels)
{
    unsigned char head[32], *b;
    img_decoded mine;
    size_t n = 0;
    file_format fmt;
    int err;
    char name[SHOWN_CAP];   /* the name in messages: a student's file name, shown escaped */
    FILE *f = input_file_open(path, 1);
    snprintf(name, sizeof name, "%s", shown(path));
    im->w = im->h = 0;
    im->px = NULL;
    if (!info) info = &mine;
    memset(info, 0, sizeof *info);
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", name, input_file_why(errno));
        return 1;
    }
    fmt = sniff(head, fread(head, 1, sizeof head, f));
    if (fmt == FMT_PFM || fmt == FMT_HDR) {
        fclose(f);
        return decode_float(im, path, fmt, info, max_pixels);
    }
    b = read_all(f, name, &n);
    fclose(f);
    if (!b) return 1;
    err = decode_bytes(im, b, n, name, sniff(b, n), info, max_pixels);
    free(b);
    if (err) img_free(im);
    return err;
}
