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
#include "sys/shown.h"
#include "sys/atomic_file.h"
#include "sys/input_file.h"
#include <ctype.h>
#include <errno.h>
#include <float.h>
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

static int image_ok(const image *im, const char *path)
{
    if (im && im->px && dims_ok(im->w, im->h)) return 1;
    fprintf(stderr, "%s: cannot write an empty image\n", shown(path));
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
        fprintf(stderr, "%s: out of memory\n", shown(path));
        return 1;
    }
    f = atomic_file_open(path, &tmp);
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
    if (!ok) fprintf(stderr, "%s: cannot write: %s\n", shown(atomic_file_shown(path)), strerror(errno));
    free(row);
    return atomic_file_close(f, tmp, path, ok);
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

/* The PFM header is read strictly, because a file that is almost right would otherwise be read
 * with its pixels shifted by a byte or in the wrong byte order, and graded as garbage:
 *   "PF" or "Pf" at the very start of the file, then the width, the height and the scale, separated
 *   by spaces, tabs or single line feeds (no blank line, no '#' comment, no CR), then exactly ONE
 *   whitespace character, then exactly w*h*channels*4 bytes of pixels and nothing after them. */
#define HDR_SPACE(c) ((c) == ' ' || (c) == '\t' || (c) == '\n' || (c) == '\r' || (c) == '\v' || (c) == '\f')

typedef struct {
    int channels, big_endian;
    long w, h;
    double scale;
    char scale_text[64];   /* the scale as written in the header */
} pfm_header;

/* Reads one header token (at most size-1 printable characters) and, into *end, the character that
 * ended it (whitespace or EOF). Returns 0; -1 at the end of the file before any character; -2 when
 * the token is too long; -3 at a byte that is neither printable nor whitespace (binary data). */
static int read_token(FILE *f, char *tok, size_t size, int *end)
{
    size_t n = 0;
    int c = getc(f);
    tok[0] = '\0';
    *end = c;
    if (c == EOF) return -1;
    while (c != EOF && !HDR_SPACE(c)) {
        *end = c;
        if (c < 0x21 || c > 0x7e) return -3;
        if (n + 1 >= size) return -2;
        tok[n++] = (char)c;
        tok[n] = '\0';
        c = getc(f);
    }
    *end = c;
    return 0;
}

static int crlf_error(const char *path)
{
    fprintf(stderr, "%s: the header's lines end with CR LF (a file written in text mode on Windows?): "
            "PFM headers end lines with LF only, and the data is shifted by a byte; open the file in "
            "binary mode (\"wb\")\n", shown(path));
    return 1;
}

/* Skips the whitespace between two header tokens, from c, the character that ended the previous
 * token. A CR, a blank line or a '#' comment is an error: printed, and 1 returned. */
static int skip_separator(FILE *f, const char *path, int c)
{
    int newlines = 0;
    while (c != EOF && HDR_SPACE(c)) {
        if (c == '\r') return crlf_error(path);
        if (c == '\n' && ++newlines == 2) {
            fprintf(stderr, "%s: the header has a blank line: a PFM header is \"PF\" (or \"Pf\"), "
                    "\"WIDTH HEIGHT\" and the scale, one per line, with nothing between them\n", shown(path));
            return 1;
        }
        c = getc(f);
    }
    if (c == '#') {
        fprintf(stderr, "%s: the header has a comment ('#'): PFM headers have none, only \"PF\" (or "
                "\"Pf\"), \"WIDTH HEIGHT\" and the scale, one per line\n", shown(path));
        return 1;
    }
    if (c != EOF) ungetc(c, f);
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

/* "PF" (colour) or "Pf" (greyscale), at the start of the file; *end: the character after it. */
static int read_magic(FILE *f, const char *path, pfm_header *hd, int *end)
{
    char magic[8];
    int r = read_token(f, magic, sizeof magic, end);
    if (r == -1 && ferror(f)) {                 /* e.g. a directory */
        fprintf(stderr, "%s: cannot read: %s\n", shown(path), strerror(errno));
        return 1;
    }
    if (r != 0 || (strcmp(magic, "PF") != 0 && strcmp(magic, "Pf") != 0)) {
        fprintf(stderr, "%s: not a PFM file (it must begin with \"PF\" or \"Pf\")\n", shown(path));
        return 1;
    }
    hd->channels = magic[1] == 'F' ? 3 : 1;
    return 0;
}

/* The scale, then exactly one whitespace character: the pixels start right after it. */
static int read_scale(FILE *f, const char *path, pfm_header *hd)
{
    char *num_end;
    int end, r = read_token(f, hd->scale_text, sizeof hd->scale_text, &end);
    if (r == -1) {
        fprintf(stderr, "%s: truncated or malformed PFM header\n", shown(path));
        return 1;
    }
    hd->scale = strtod(hd->scale_text, &num_end);
    if (r == -3 && num_end != hd->scale_text && *num_end == '\0') {
        fprintf(stderr, "%s: no line feed after the scale '%s': the pixel data must follow the scale "
                "and exactly one whitespace character (a line feed)\n", shown(path), shown(hd->scale_text));
        return 1;
    }
    if (r != 0 || num_end == hd->scale_text || *num_end != '\0' || !(hd->scale - hd->scale == 0.0)
        || hd->scale == 0.0) {
        fprintf(stderr, "%s: bad scale '%s' (a nonzero number; negative means little-endian)\n", shown(path),
                shown(hd->scale_text));
        return 1;
    }
    if (end == '\r') return crlf_error(path);
    hd->big_endian = hd->scale > 0.0;
    return 0;
}

/* Reads "PF"/"Pf", width, height and scale. Returns 0 or prints the error and returns 1. */
static int read_pfm_header(FILE *f, const char *path, pfm_header *hd)
{
    char ws[32], hs[32];
    int end, r;
    if (read_magic(f, path, hd, &end) || skip_separator(f, path, end)) return 1;
    r = read_token(f, ws, sizeof ws, &end);
    if (r == 0 && skip_separator(f, path, end)) return 1;
    if (r == 0) r = read_token(f, hs, sizeof hs, &end);
    if (r == 0 && skip_separator(f, path, end)) return 1;
    if (r != 0) {
        fprintf(stderr, "%s: truncated or malformed PFM header\n", shown(path));
        return 1;
    }
    if (!parse_long(ws, &hd->w) || !parse_long(hs, &hd->h) || !dims_ok(hd->w, hd->h)) {
        fprintf(stderr, "%s: bad dimensions %s x %s (each side 1 to %ld, at most %ld pixels)\n",
                shown(path), shown(ws), shown(hs), IMG_MAX_SIDE, IMG_MAX_PIXELS);
        return 1;
    }
    return read_scale(f, path, hd);
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

/* "2 x 2 x 3 x 4 = 48 bytes" */
static void size_text(char *buf, size_t n, const pfm_header *hd, size_t need)
{
    snprintf(buf, n, "%ld x %ld x %d x 4 = %zu bytes", hd->w, hd->h, hd->channels, need);
}

static int truncated_error(const char *path, const pfm_header *hd, size_t need, size_t found)
{
    char s[160];
    size_t missing = need - found, pixel = 4 * (size_t)hd->channels;
    size_text(s, sizeof s, hd, need);
    fprintf(stderr, "%s: truncated: expected %s of pixels (width x height x channels x 4), found %zu: "
            "%zu bytes missing (%.*f pixel%s)\n", shown(path), shown(s), found, missing, missing % pixel ? 2 : 0,
            (double)missing / (double)pixel, missing == pixel ? "" : "s");
    return 1;
}

/* first: the first byte of the pixel data, which hints at one whitespace too many after the scale. */
static int trailing_error(const char *path, const pfm_header *hd, size_t need, long extra, int first)
{
    char s[160];
    size_text(s, sizeof s, hd, need);
    fprintf(stderr, "%s: %ld byte%s after the pixel data: expected exactly %s (width x height x channels x 4); a second image or a "
            "header written twice?%s\n", shown(path), extra, extra == 1 ? "" : "s", shown(s),
            extra < 4 && HDR_SPACE(first) ? " (or the data starts with a whitespace byte: a space before "
            "the header's last line feed? after the scale, PFM allows exactly one whitespace character)" : "");
    return 1;
}

/* Reads the need bytes of pixels (left: the bytes after the header, -1 if unknown) and makes sure
 * nothing follows them. Returns 0 or prints the error and returns 1. */
static int read_pixels(FILE *f, const char *path, const pfm_header *hd, size_t need, long left,
                       unsigned char *data)
{
    size_t got = fread(data, 1, need, f);
    long extra = 0;
    if (got < need) {
        if (ferror(f)) fprintf(stderr, "%s: read error: %s\n", shown(path), strerror(errno));
        else truncated_error(path, hd, need, got);
        return 1;
    }
    if (left >= 0) extra = left - (long)need;
    else
        while (getc(f) != EOF) extra++;
    if (extra > 0) return trailing_error(path, hd, need, extra, data[0]);
    return 0;
}

/* The values of the pixel data read in one byte order: how many are nonzero, how many of those
 * are NaN or infinite, how many are absurd for radiance (denormal, or beyond 1e20 in size), how
 * many negative, how many denormal. */
typedef struct { size_t nonzero, nonfinite, absurd, negative, denormal; double max_abs, lo, hi; } order_stats;

static void order_stats_of(const unsigned char *data, size_t n, int big_endian, order_stats *s)
{
    size_t i;
    s->nonzero = s->nonfinite = s->absurd = s->negative = s->denormal = 0;
    s->max_abs = 0.0;
    s->lo = FLT_MAX;
    s->hi = -FLT_MAX;
    for (i = 0; i < n; i++) {
        float v = get_f32(data + 4 * i, big_endian);
        double a = v < 0.0f ? -(double)v : (double)v;
        if (!(v - v == 0.0f)) { s->nonzero++; s->nonfinite++; continue; }
        if (v < s->lo) s->lo = v;
        if (v > s->hi) s->hi = v;
        if (v == 0.0f) continue;
        s->nonzero++;
        if (a > 1e20 || a < FLT_MIN) s->absurd++;
        s->negative += v < 0.0f;
        s->denormal += a < FLT_MIN;
        if (a > s->max_abs) s->max_abs = a;
    }
}

/* The header's byte order is wrong when over 1% of the nonzero values read in it are NaN,
 * infinite or absurd, and at most 1% are absurd and fewer than half negative read in the other order
 * (a 1x1 image of 3e38 reads -0.106 swapped: no advice to swap it). When over 10% are absurd in both
 * orders, and at least 8 of them or, in an image of under 64 values, any denormal, the data is not
 * float radiance (a firefly of 3e38 in a 3x3 image, 3 values of 27 and none denormal, is radiance,
 * left to the caller; so is a black 256x256 image with 5 values, one of them 2e-39). Otherwise the values are left to the caller
 * (image/radiance.h finds NaN, infinite and negative values). Returns 0 or prints and returns 1. */
static int check_byte_order(const unsigned char *data, size_t n, const pfm_header *hd, const char *path)
{
    static const char *const order[2] = { "little", "big" };
    const char *sign = hd->scale_text[0] == '-' || hd->scale_text[0] == '+' ? "" : "+";
    order_stats as, other;
    order_stats_of(data, n, hd->big_endian, &as);
    if ((as.absurd + as.nonfinite) * 100 <= as.nonzero) return 0;
    order_stats_of(data, n, !hd->big_endian, &other);
    if (other.absurd * 100 <= other.nonzero && other.negative * 2 < other.nonzero) {
        fprintf(stderr, "%s: the header's scale %s%s says %s-endian, but read so the values are absurd "
                "(up to %.2g; %zu of the %zu nonzero values are NaN, infinite, denormal or beyond 1e20); "
                "read %s-endian they are ordinary (%.3g to %.3g): write the scale as %s for %s-endian data\n",
                shown(path), sign, shown(hd->scale_text), order[hd->big_endian], as.max_abs, as.absurd + as.nonfinite,
                as.nonzero, order[!hd->big_endian], other.lo, other.hi, hd->big_endian ? "-1.0" : "1.0",
                order[!hd->big_endian]);
        return 1;
    }
    if (as.absurd * 10 > as.nonzero && (as.absurd >= 8 || (as.denormal > 0 && n < 64))) {
        fprintf(stderr, "%s: the pixel data is not float radiance: read %s-endian (as the header's scale "
                "%s%s says), %zu of the %zu nonzero values are NaN, infinite, denormal or beyond 1e20, and "
                "read %s-endian %zu are\n", shown(path), order[hd->big_endian], sign, shown(hd->scale_text),
                as.absurd + as.nonfinite, as.nonzero, order[!hd->big_endian], other.absurd + other.nonfinite);
        return 1;
    }
    return 0;
}

/* The pixel data, read into the image's own buffer (data == im->px), made the image in place: rows
 * turned top to bottom, values to native floats, and Pf's one channel spread to R, G and B from the
 * last pixel back (pixel i's three floats start at 12 i, past the 4 i of every value not yet
 * spread). No second buffer: a reader allocates only the image it returns. */
static void decode_pfm(image *im, unsigned char *data, const pfm_header *hd)
{
    size_t x, y, i, w = (size_t)hd->w, h = (size_t)hd->h, row = w * (size_t)hd->channels * 4, n = w * h;
    for (y = 0; y < h / 2; y++) {   /* bottom row first in the file */
        unsigned char *a = data + y * row, *b = data + (h - 1 - y) * row, t;
        for (x = 0; x < row; x++) t = a[x], a[x] = b[x], b[x] = t;
    }
    if (hd->channels == 3)
        for (i = 0; i < 3 * n; i++) im->px[i] = get_f32(data + 4 * i, hd->big_endian);
    else
        for (i = n; i-- > 0;) {
            float v = get_f32(data + 4 * i, hd->big_endian);
            im->px[3 * i] = im->px[3 * i + 1] = im->px[3 * i + 2] = v;
        }
}

/* What img_read_pfm_info and img_read_pfm_header tell of a file's header. */
static void pfm_info_of(const pfm_header *hd, img_pfm_info *info)
{
    info->w = (int)hd->w;
    info->h = (int)hd->h;
    info->channels = hd->channels;
    info->big_endian = hd->big_endian;
    info->scale = hd->scale;
}

int img_read_pfm_info(image *im, const char *path, img_pfm_info *info)
{
    pfm_header hd;
    unsigned char *data;
    size_t need;
    long left;
    int err = 1;
    FILE *f;
    im->w = im->h = 0;
    im->px = NULL;
    f = input_file_open(path, 1);   /* a FIFO or a device in a class folder must not hang grade */
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", shown(path), input_file_why(errno));
        return 1;
    }
    if (read_pfm_header(f, path, &hd)) goto out;
    need = (size_t)hd.w * (size_t)hd.h * (size_t)hd.channels * 4;
    /* Check the size before allocating, so a lying header cannot make us allocate gigabytes. */
    left = bytes_left(f);
    if (left >= 0 && (size_t)left < need) {
        truncated_error(path, &hd, need, (size_t)left);
        goto out;
    }
    if (img_alloc(im, (int)hd.w, (int)hd.h)) {
        fprintf(stderr, "%s: out of memory\n", shown(path));
        goto out;
    }
    data = (unsigned char *)im->px;   /* need <= its size: 4 bytes a value, 1 or 3 values a pixel */
    if (read_pixels(f, path, &hd, need, left, data) || check_byte_order(data, need / 4, &hd, path)) goto out;
    decode_pfm(im, data, &hd);
    if (info) pfm_info_of(&hd, info);
    err = 0;
out:
    if (err) img_free(im);   /* data is its buffer */
    fclose(f);
    return err;
}

int img_read_pfm_header(const char *path, img_pfm_info *info)
{
    pfm_header hd;
    size_t need;
    long left;
    int err = 1;
    FILE *f = input_file_open(path, 1);
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", shown(path), input_file_why(errno));
        return 1;
    }
    if (read_pfm_header(f, path, &hd)) goto out;
    need = (size_t)hd.w * (size_t)hd.h * (size_t)hd.channels * 4;
    left = bytes_left(f);
    if (left >= 0 && (size_t)left < need) truncated_error(path, &hd, need, (size_t)left);
    else if (left >= 0 && (size_t)left > need) trailing_error(path, &hd, need, left - (long)need, 0);
    else {
        pfm_info_of(&hd, info);
        err = 0;
    }
out:
    fclose(f);
    return err;
}

int img_read_pfm(image *im, const char *path)
{
    return img_read_pfm_info(im, path, NULL);
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
        fprintf(stderr, "%s: out of memory\n", shown(path));
        return 1;
    }
    for (y = 0; y < im->h; y++)
        encode_ppm_row(im->px + (size_t)y * im->w * 3, im->w, rgb + (size_t)y * im->w * 3, gain);
    f = atomic_file_open(path, &tmp);
    if (!f) {
        free(rgb);
        return 1;
    }
    ok = png_write_rgb8(f, rgb, im->w, im->h) == 0;
    if (!ok) fprintf(stderr, "%s: cannot write: %s\n", shown(atomic_file_shown(path)), strerror(errno));
    free(rgb);
    return atomic_file_close(f, tmp, path, ok);
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

const char *const IMG_EXTENSIONS[] = {".pfm", ".ppm", ".png", NULL};
const char *const IMG_PFM_EXTENSION[] = {".pfm", NULL};
const char *const IMG_PICTURE_EXTENSIONS[] = {".png", ".ppm", NULL};

img_format img_format_of(const char *path)
{
    const char *e = img_extension(path);
    if (same_ignoring_case(e, ".pfm")) return IMG_PFM;
    if (same_ignoring_case(e, ".ppm")) return IMG_PPM;
    if (same_ignoring_case(e, ".png")) return IMG_PNG;
    if (same_ignoring_case(e, ".hdr")) return IMG_HDR;
    return IMG_UNKNOWN;
}

int img_is_picture(const char *path)
{
    img_format f = img_format_of(path);
    return f == IMG_PNG || f == IMG_PPM;
}

int img_write(const image *im, const char *path, float exposure)
{
    switch (img_format_of(path)) {
    case IMG_PFM: return img_write_pfm(im, path);
    case IMG_PPM: return img_write_ppm(im, path, exposure);
    case IMG_PNG: return img_write_png(im, path, exposure);
    case IMG_HDR:   /* read only */
    case IMG_UNKNOWN: break;
    }
    fprintf(stderr, "%s: unknown image format (use .pfm, .ppm or .png)\n", shown(path));
    return 1;
}
