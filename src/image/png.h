/* png.h — the PNG format, written without compression: 8-bit RGB, one IDAT chunk per stored
 * deflate block. image.c calls it after encoding the pixels to sRGB bytes. */
#ifndef PATHLAB_PNG_H
#define PATHLAB_PNG_H
#include <stdint.h>
#include <stdio.h>

/* Writes a whole PNG file to f: rgb holds w*h*3 bytes, rows top to bottom. 0 on success, nonzero
 * on a write error (the caller reports it and discards the file). */
int png_write_rgb8(FILE *f, const unsigned char *rgb, int w, int h);
#endif
