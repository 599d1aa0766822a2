/* image.c — linear RGB float images and their files (PFM, PPM, PNG).
 *
 * PFM ("portable float map"): a text header "PF\n<w> <h>\n<scale>\n" (or "Pf" for one channel),
 * then w*h pixels of IEEE 754 binary32 floats, rows from the BOTTOM of the image to the top.
 * The sign of the scale gives the byte order (negative: little-endian); its magnitude is
 * informational in practice and we ignore it on read (pixels are returned exactly as stored).
 * We always write little-endian with scale -1.0. Bytes are encoded and decoded explicitly, so the
 * files are the same on any host; we only assume that float is binary32 (true wherever pathlab runs).
 *
 * PPM: "P6\n<w> <h>\n255\n" then 8-bit RGB, rows top to bottom, sRGB-encoded.
 * PNG: the same bytes as the PPM, in an uncompressed PNG file (png.c).
 *
 * Every write goes to "<path>.tmp.XXXXXX" in the same folder and is renamed over <path> only
 * after fflush and fclose succeeded: a crash or a full disk never leaves a half-written image, and
 * an existing image stays untouched when the write fails. */
#include "image/image.h"
#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "image/png.h"

/* Limits that keep every size computation far from overflow and refuse absurd headers before we
 * try to allocate: 2^20 pixels per side, 2^28 pixels in all (3 GiB of floats). */
#define IMG_MAX_SIDE (1L << 20)
#define IMG_MAX_PIXELS (1L << 28)

static int dims_ok(long w, long h)
{
    return w >= 1 && h >= 1 && w <= IMG_MAX_SIDE && h <= IMG_MAX_SIDE && w <= IMG_MAX_PIXELS / h;
}

int img_alloc(image *im, int w, int h)
{
    im->w = im->h = 0;
    im->px = NULL;
    if (!dims_ok(w, h)) return 1;
    im->px = calloc((size_t)w * (size_t)h * 3, sizeof(float));
    if (!im->px) return 1;
    im->w = w;
    im->h = h;
    return 0;
}

void img_free(image *im)
{
    free(im->px);
    im->px = NULL;
    im->w = im->h = 0;
}

/* The exact piecewise sRGB curve (IEC 61966-2-1). Inputs outside [0,1] are clamped, NaN gives 0,
 * so that a stray NaN pixel shows black instead of poisoning the 8-bit conversion. */
float srgb_encode(float linear)
{
    if (!(linear > 0.0f)) return 0.0f;        /* also catches NaN */
    if (linear >= 1.0f) return 1.0f;
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * powf(linear, 1.0f / 2.4f) - 0.055f;
}

/* ---- atomic file writes ---- */

/* The permissions fopen would have given the file: 0666 minus the umask. mkstemp creates files
 * 0600, which would make every image private. umask can only be read by setting it, so this is
 * not thread-safe; images are written from the main thread after rendering. */
static mode_t creation_mode(void)
{
    mode_t mask = umask(022);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

/* Opens a temporary file next to path; *tmp receives its name (to free). NULL on error. */
static FILE *atomic_open(const char *path, char **tmp)
{
    size_t n = strlen(path);
    int fd;
    FILE *f;
    *tmp = malloc(n + sizeof ".tmp.XXXXXX");
    if (!*tmp) {
        fprintf(stderr, "%s: out of memory\n", path);
        return NULL;
    }
    memcpy(*tmp, path, n);
    memcpy(*tmp + n, ".tmp.XXXXXX", sizeof ".tmp.XXXXXX");
    fd = mkstemp(*tmp);
    if (fd < 0) {
        fprintf(stderr, "%s: cannot create a temporary file: %s\n", path, strerror(errno));
        free(*tmp);
        *tmp = NULL;
        return NULL;
    }
    if (fchmod(fd, creation_mode()) != 0 || !(f = fdopen(fd, "wb"))) {
        fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
        close(fd);
        unlink(*tmp);
        free(*tmp);
        *tmp = NULL;
        return NULL;
    }
    return f;
}

/* Finishes an atomic write: when ok and the data reached the file, renames tmp over path.
 * Otherwise removes tmp. Frees tmp. Returns 0 when path now holds the new image. */
static int atomic_close(FILE *f, char *tmp, const char *path, int ok)
{
    int err = 0;
    if (ok && fflush(f) != 0) err = errno;
    if (ok && !err && ferror(f)) err = EIO;
    if (fclose(f) != 0 && ok && !err) err = errno;
    if (ok && !err && rename(tmp, path) != 0) err = errno;
    if (ok && err) fprintf(stderr, "%s: cannot write: %s\n", path, strerror(err));
    if (!ok || err) unlink(tmp);
    free(tmp);
    return (ok && !err) ? 0 : 1;
}

static int image_ok(const image *im, const char *path)
{
    if (im && im->px && dims_ok(im->w, im->h)) return 1;
    fprintf(stderr, "%s: cannot write an empty image\n", path);
    return 0;
}

/* One row of linear floats (3 per pixel) into the bytes of a file format. */
typedef void (*row_encoder)(const float *src, int w, unsigned char *out, float gain);

/* The shared body of every image writer: a header (printf format taking w and h), then the rows,
 * top first or bottom first, each encoded into bytes_per_pixel * w bytes; written atomically. */
static int write_rows(const image *im, const char *path, const char *header, size_t bytes_per_pixel,
                      int bottom_up, row_encoder encode, float gain)
{
    size_t row_bytes;
    unsigned char *row;
    char *tmp;
    FILE *f;
    int y, ok;
    if (!image_ok(im, path)) return 1;
    row_bytes = (size_t)im->w * bytes_per_pixel;
    row = malloc(row_bytes);
    if (!row) {
        fprintf(stderr, "%s: out of memory\n", path);
        return 1;
    }
    f = atomic_open(path, &tmp);
    if (!f) {
        free(row);
        return 1;
    }
    ok = fprintf(f, header, im->w, im->h) > 0;
    for (y = 0; ok && y < im->h; y++) {
        int src_y = bottom_up ? im->h - 1 - y : y;
        encode(im->px + (size_t)src_y * im->w * 3, im->w, row, gain);
        ok = fwrite(row, 1, row_bytes, f) == row_bytes;
    }
    if (!ok) fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
    free(row);
    return atomic_close(f, tmp, path, ok);
}

/* ---- PFM ---- */

static void put_f32_le(unsigned char *b, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    b[0] = (unsigned char)(u & 0xff);
    b[1] = (unsigned char)(u >> 8 & 0xff);
    b[2] = (unsigned char)(u >> 16 & 0xff);
    b[3] = (unsigned char)(u >> 24 & 0xff);
}

static float get_f32(const unsigned char *b, int big_endian)
{
    uint32_t u;
    float v;
    if (big_endian)
        u = (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | (uint32_t)b[3];
    else
        u = (uint32_t)b[3] << 24 | (uint32_t)b[2] << 16 | (uint32_t)b[1] << 8 | (uint32_t)b[0];
    memcpy(&v, &u, 4);
    return v;
}

static void encode_pfm_row(const float *src, int w, unsigned char *out, float gain)
{
    size_t i;
    (void)gain;   /* PFM keeps the linear values as they are */
    for (i = 0; i < (size_t)w * 3; i++) put_f32_le(out + 4 * i, src[i]);
}

int img_write_pfm(const image *im, const char *path)
{
    /* PFM stores the bottom row first; our row 0 is the top. */
    return write_rows(im, path, "PF\n%d %d\n-1.0\n", 12, 1, encode_pfm_row, 1.0f);
}

/* Reads one whitespace-separated header token into tok (at most size-1 chars).
 * Returns 0 on success, -1 at end of file, -2 when the token is too long. */
static int read_token(FILE *f, char *tok, size_t size)
{
    size_t n = 0;
    int c;
    do c = getc(f); while (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f');
    if (c == EOF) return -1;
    while (c != EOF && !(c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f')) {
        if (n + 1 >= size) return -2;
        tok[n++] = (char)c;
        c = getc(f);
    }
    tok[n] = '\0';
    /* The single whitespace after the last token was consumed here: pixel data starts next. */
    return 0;
}

/* Parses a whole token as a long; 0 on failure or trailing junk. */
static int parse_long(const char *tok, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(tok, &end, 10);
    return end != tok && *end == '\0' && errno == 0;
}

typedef struct { int channels, big_endian; long w, h; } pfm_header;

/* Reads "PF"/"Pf", width, height and scale. Returns 0 or prints the error and returns 1. */
static int read_pfm_header(FILE *f, const char *path, pfm_header *hd)
{
    char magic[8], ws[32], hs[32], ss[64], *end;
    double scale;
    int r = read_token(f, magic, sizeof magic);
    if (r == -1 && ferror(f)) {                 /* e.g. a directory */
        fprintf(stderr, "%s: cannot read: %s\n", path, strerror(errno));
        return 1;
    }
    if (r != 0 || (strcmp(magic, "PF") != 0 && strcmp(magic, "Pf") != 0)) {
        fprintf(stderr, "%s: not a PFM file\n", path);
        return 1;
    }
    hd->channels = magic[1] == 'F' ? 3 : 1;
    if (read_token(f, ws, sizeof ws) || read_token(f, hs, sizeof hs) || read_token(f, ss, sizeof ss)) {
        fprintf(stderr, "%s: truncated or malformed PFM header\n", path);
        return 1;
    }
    if (!parse_long(ws, &hd->w) || !parse_long(hs, &hd->h) || !dims_ok(hd->w, hd->h)) {
        fprintf(stderr, "%s: bad dimensions %s x %s (each side 1 to %ld, at most %ld pixels)\n",
                path, ws, hs, IMG_MAX_SIDE, IMG_MAX_PIXELS);
        return 1;
    }
    scale = strtod(ss, &end);
    if (end == ss || *end != '\0' || !(scale == scale) || scale == 0.0) {
        fprintf(stderr, "%s: bad scale '%s' (a nonzero number; negative means little-endian)\n", path, ss);
        return 1;
    }
    hd->big_endian = scale > 0.0;
    return 0;
}

/* Bytes left in f from the current position, or -1 when f cannot seek (a pipe). */
static long bytes_left(FILE *f)
{
    long here = ftell(f), end;
    if (here < 0 || fseek(f, 0, SEEK_END) != 0) return -1;
    end = ftell(f);
    if (end < 0 || fseek(f, here, SEEK_SET) != 0) return -1;
    return end - here;
}

static void decode_pfm(image *im, const unsigned char *data, const pfm_header *hd)
{
    size_t x, y, c, w = (size_t)hd->w, h = (size_t)hd->h;
    for (y = 0; y < h; y++) {
        const unsigned char *src = data + (h - 1 - y) * w * hd->channels * 4;  /* bottom row first */
        float *dst = im->px + y * w * 3;
        for (x = 0; x < w; x++)
            for (c = 0; c < 3; c++)
                dst[3 * x + c] = get_f32(src + 4 * (x * hd->channels + (hd->channels == 3 ? c : 0)),
                                         hd->big_endian);
    }
}

int img_read_pfm(image *im, const char *path)
{
    pfm_header hd;
    unsigned char *data = NULL;
    size_t need, got;
    long left;
    int err = 1;
    FILE *f;
    im->w = im->h = 0;
    im->px = NULL;
    f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno));
        return 1;
    }
    if (read_pfm_header(f, path, &hd)) goto out;
    need = (size_t)hd.w * (size_t)hd.h * (size_t)hd.channels * 4;
    /* Check the size before allocating, so a lying header cannot make us allocate gigabytes. */
    left = bytes_left(f);
    if (left >= 0 && (size_t)left < need) {
        fprintf(stderr, "%s: truncated (expected %zu bytes of pixels, found %ld)\n", path, need, left);
        goto out;
    }
    data = malloc(need);
    if (!data || img_alloc(im, (int)hd.w, (int)hd.h)) {
        fprintf(stderr, "%s: out of memory\n", path);
        goto out;
    }
    got = fread(data, 1, need, f);
    if (got < need) {
        if (ferror(f)) fprintf(stderr, "%s: read error: %s\n", path, strerror(errno));
        else fprintf(stderr, "%s: truncated (expected %zu bytes of pixels, found %zu)\n", path, need, got);
        goto out;
    }
    decode_pfm(im, data, &hd);
    err = 0;
out:
    if (err) img_free(im);
    free(data);
    fclose(f);
    return err;
}

/* ---- PPM ---- */

static unsigned char to_byte(float linear, float gain)
{
    return (unsigned char)(srgb_encode(linear * gain) * 255.0f + 0.5f);
}

static void encode_ppm_row(const float *src, int w, unsigned char *out, float gain)
{
    size_t i;
    for (i = 0; i < (size_t)w * 3; i++) out[i] = to_byte(src[i], gain);
}

int img_write_ppm(const image *im, const char *path, float exposure)
{
    return write_rows(im, path, "P6\n%d %d\n255\n", 3, 0, encode_ppm_row, exp2f(exposure));
}

/* ---- PNG (the format itself is in png.c) ---- */

int img_write_png(const image *im, const char *path, float exposure)
{
    unsigned char *rgb;
    char *tmp;
    FILE *f;
    float gain = exp2f(exposure);
    int y, ok;
    if (!image_ok(im, path)) return 1;
    rgb = malloc((size_t)im->w * im->h * 3);
    if (!rgb) {
        fprintf(stderr, "%s: out of memory\n", path);
        return 1;
    }
    for (y = 0; y < im->h; y++)
        encode_ppm_row(im->px + (size_t)y * im->w * 3, im->w, rgb + (size_t)y * im->w * 3, gain);
    f = atomic_open(path, &tmp);
    if (!f) {
        free(rgb);
        return 1;
    }
    ok = png_write_rgb8(f, rgb, im->w, im->h) == 0;
    if (!ok) fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
    free(rgb);
    return atomic_close(f, tmp, path, ok);
}

/* ---- by extension ---- */

const char *img_extension(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    return dot && (!slash || dot > slash) ? dot : "";
}

/* 1 when a and b are the same ASCII text, ignoring case. */
static int same_ignoring_case(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
    return *a == *b;
}

img_format img_format_of(const char *path)
{
    const char *e = img_extension(path);
    if (same_ignoring_case(e, ".pfm")) return IMG_PFM;
    if (same_ignoring_case(e, ".ppm")) return IMG_PPM;
    if (same_ignoring_case(e, ".png")) return IMG_PNG;
    return IMG_UNKNOWN;
}

int img_write(const image *im, const char *path, float exposure)
{
    switch (img_format_of(path)) {
    case IMG_PFM: return img_write_pfm(im, path);
    case IMG_PPM: return img_write_ppm(im, path, exposure);
    case IMG_PNG: return img_write_png(im, path, exposure);
    case IMG_UNKNOWN: break;
    }
    fprintf(stderr, "%s: unknown image format (use .pfm, .ppm or .png)\n", path);
    return 1;
}
