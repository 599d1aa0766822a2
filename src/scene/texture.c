/* texture.c — the textures of texture.h: read once, stored bottom row first, looked up as gKit does. */
#include "scene/texture.h"
#include "image/decode.h"
#include "sys/shown.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const TEXTURE_DECODE_NAMES[] = {"raw", "srgb", 0};
const char *const TEXTURE_FILTER_NAMES[] = {"nearest", "bilinear", 0};

/* sRGB-encoded [0, 1] -> linear (IEC 61966-2-1). */
static float srgb_decode(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

/* The file's pixels into *im, by its magic bytes (image/decode.h); *integer: its values are integers
 * over a maxval (PNG, JPEG, TGA, PPM), to which --texture-decode applies. */
static int read_texels(image *im, const char *path, int *integer, long max_texels)
{
    img_decoded info;
    if (img_decode_file_within(im, path, &info, max_texels)) return 1;
    *integer = info.encoding == IMG_ENC_INTEGER;
    return 0;
}

/* 0 if every value of im is a number >= 0 (a PFM or HDR file can hold any float: a NaN texel would
 * blacken every path that meets it, a negative one make a negative image); else 1, said. */
static int texels_valid(const image *im, const char *path)
{
    size_t i, n = (size_t)3 * (size_t)im->w * (size_t)im->h;
    for (i = 0; i < n && isfinite(im->px[i]) && im->px[i] >= 0.0f; i++) continue;
    if (i == n) return 0;
    fprintf(stderr, "%s: pixel (%d, %d) of the file is %g: a texture's values must be finite and >= 0\n", shown(path),
            (int)(i / 3 % (size_t)im->w), (int)(i / 3 / (size_t)im->w), (double)im->px[i]);
    return 1;
}

int texture_load(texture *t, const char *path, texture_decode decode, long max_texels)
{
    image im;
    int integer, x, y, c;
    memset(t, 0, sizeof *t);
    if (read_texels(&im, path, &integer, max_texels)) return 1;
    if (texels_valid(&im, path)) { img_free(&im); return 1; }
    t->w = im.w, t->h = im.h;
    t->rgb = im.px;   /* the same layout, rows flipped in place below */
    if (!(t->path = malloc(strlen(path) + 1))) {
        img_free(&im);
        memset(t, 0, sizeof *t);
        return 1;
    }
    strcpy(t->path, path);
    for (y = 0; y < t->h / 2; y++)
        for (x = 0; x < 3 * t->w; x++) {
            float *a = t->rgb + (size_t)y * 3 * t->w + x, *b = t->rgb + (size_t)(t->h - 1 - y) * 3 * t->w + x, s = *a;
            *a = *b, *b = s;
        }
    if (integer && decode == TEXTURE_SRGB)
        for (c = 0; c < 3 * t->w * t->h; c++) t->rgb[c] = srgb_decode(t->rgb[c]);
    return 0;
}

void texture_free(texture *t)
{
    free(t->rgb);
    free(t->path);
    memset(t, 0, sizeof *t);
}

static vec3 texel(const texture *t, int x, int y)
{
    const float *p = t->rgb + 3 * ((size_t)y * (size_t)t->w + (size_t)x);
    return v3(p[0], p[1], p[2]);
}

/* Texcoords as far out as this are brought back by fmod (slow) before they are cast to an integer. */
#define TEXCOORD_FAR 1e9

/* gKit's index: int(s n) % n, made positive (fmod first for a far texcoord: the same result without
 * overflowing an int). */
static int nearest_index(float s, int n)
{
    double x = (double)s * n;
    long long i;
    if (fabs(x) > TEXCOORD_FAR) x = fmod(x, (double)n);
    i = (long long)x % n;
    return (int)(i < 0 ? -i : i);
}

/* floor(x) modulo n, in [0, n), and the fraction of x above its floor. */
static int wrap_floor(double x, int n, float *frac)
{
    double f;
    long long i;
    if (fabs(x) > TEXCOORD_FAR) x = fmod(x, (double)n);
    f = floor(x);
    *frac = (float)(x - f);
    i = (long long)f % n;
    return (int)(i < 0 ? i + n : i);
}

vec3 texture_lookup(const texture *t, float u, float v, texture_filter filter)
{
    int x0, y0, x1, y1;
    float fx, fy;
    vec3 a, b;
    if (!isfinite(u) || !isfinite(v)) u = v = 0.0f;
    if (filter == TEXTURE_NEAREST) return texel(t, nearest_index(u, t->w), nearest_index(v, t->h));
    x0 = wrap_floor((double)u * t->w - 0.5, t->w, &fx);
    y0 = wrap_floor((double)v * t->h - 0.5, t->h, &fy);
    x1 = x0 + 1 == t->w ? 0 : x0 + 1;
    y1 = y0 + 1 == t->h ? 0 : y0 + 1;
    a = v3_add(v3_scale(texel(t, x0, y0), 1.0f - fx), v3_scale(texel(t, x1, y0), fx));
    b = v3_add(v3_scale(texel(t, x0, y1), 1.0f - fx), v3_scale(texel(t, x1, y1), fx));
    return v3_add(v3_scale(a, 1.0f - fy), v3_scale(b, fy));
}
