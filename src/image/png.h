/* png.h — the PNG format, written without compression: 8-bit RGB, one IDAT chunk per stored
 * deflate block. image.c calls it after encoding the pixels to sRGB bytes. */
#ifndef PATHLAB_PNG_H
#define PATHLAB_PNG_H
#include <stdint.h>
#include <stdio.h>

/* Writes a whole PNG file to f: rgb holds w*h*3 bytes, rows top to bottom. 0 on success, nonzero
 * on a write error (the caller reports it and discards the file). */
int png_write_rgb8(FILE *f, const unsigned char *rgb, int w, int h);
/* CRC-32 of ISO 3309 / PNG (polynomial 0xEDB88320, reflected), continued from crc: start at 0. */
uint32_t png_crc32(uint32_t crc, const unsigned char *b, size_t n);
/* Adler-32 of RFC 1950, continued from adler: start at 1. */
uint32_t png_adler32(uint32_t adler, const unsigned char *b, size_t n);
#endif
