/* texture.h — the images a material names (map_Kd, map_Ks, map_Ke), as gKit reads and samples them.
 * A texture's row 0 is the image's bottom row (gKit's read_image flips the file, origin at the bottom
 * left), so texcoord (u, v) with v up falls on column u w, row v h.
 * - decode raw (gKit's): an 8-bit file's values divided by 255 (its maxval), no sRGB curve: what the
 *   students' renderers multiply Kd by; srgb: those values through the sRGB curve to linear (Blender's
 *   Color images). Files of floats (PFM, HDR) are linear either way. Any format image/decode.h reads,
 *   told by its magic bytes.
 * - nearest (gKit's sample_texture): column int(u w) % w, negative ones made positive, likewise the row;
 *   bilinear: the four texels around (u w - 1/2, v h - 1/2), repeated past the edges (OpenGL's
 *   GL_LINEAR with GL_REPEAT). docs/gkit.md cites gKit's lines. */
#ifndef PATHLAB_TEXTURE_H
#define PATHLAB_TEXTURE_H
#include "math/vec.h"

typedef enum { TEXTURE_RAW, TEXTURE_SRGB } texture_decode;          /* --texture-decode */
typedef enum { TEXTURE_NEAREST, TEXTURE_BILINEAR } texture_filter;  /* --texture-filter */
extern const char *const TEXTURE_DECODE_NAMES[];
extern const char *const TEXTURE_FILTER_NAMES[];

typedef struct {
    int w, h;
    float *rgb;      /* 3 floats a texel, row 0 at the bottom */
    char *path;      /* resolved (realpath): one texture per file, whatever number of materials name it */
} texture;

/* A scene's textures together hold at most this many texels (6 GiB of floats): each file is capped
 * at IMG_DECODE_MAX_PIXELS, but 55 KB of PNG can claim 16384^2 pixels, and a scene can name many. */
#define TEXTURE_SCENE_MAX_TEXELS (1L << 29)

/* Reads the image at path (resolved already) into t, refused unread past max_texels texels; 0, or 1
 * after printing "path: why". */
int texture_load(texture *t, const char *path, texture_decode decode, long max_texels);
void texture_free(texture *t);
/* The texture's value at texcoord (u, v). */
vec3 texture_lookup(const texture *t, float u, float v, texture_filter filter);
#endif
