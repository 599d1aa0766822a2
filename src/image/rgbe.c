/* rgbe.c — Radiance RGBE reader (see rgbe.h), written from Ward's description of the format
 * (Graphics Gems II, "Real Pixels", and the Radiance file format notes).
 *
 * A pixel is 4 bytes: three mantissas and a shared exponent. Its writer chose e so that the
 * largest channel is in [2^(e-129), 2^(e-128)) and stored m = floor(v * 256 / 2^(e-128)): every
 * value in [m, m+1) steps maps to m, so the centre of that interval, (m + 0.5) steps, is the
 * unbiased estimate (readers that return m steps are half a step low on every pixel).
 *
 * Scanlines: the resolution line's second pair gives a scanline's length L. A scanline is either
 *   - new-style RLE (8 <= L <= 32767): bytes 2, 2, L >> 8, L & 255, then the four channels one
 *     after the other, each as packets: a byte c > 128 then one byte repeated c - 128 times, or a
 *     byte 1 <= c <= 128 then c literal bytes;
 *   - flat: L pixels of 4 bytes, where a pixel 1, 1, 1, n (old-style RLE) repeats the pixel before
 *     it n << s times, s growing by 8 with each such pixel in a row (0 after a normal pixel).
 * The file is refused before allocating when it is shorter than its scanlines' most compact
 * encoding could be (old-style runs counted as at most 255 pixels for 4 bytes) or longer than
 * their least compact one: memory stays within the file plus the image. */
#include "image/rgbe.h"
#include "sys/shown.h"
#include "sys/input_file.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RGBE_HEADER_MAX 65536   /* bytes of header and resolution line, at most */
#define RGBE_RLE_MIN 8          /* new-style RLE only for scanlines of 8 to 32767 pixels */
#define RGBE_RLE_MAX 32767

typedef struct {
    long w, h;              /* the image */
    long lines, len;        /* scanlines in the file, pixels in each */
    int columns;            /* the first pair is X: scanlines are columns */
    char sign1, sign2;      /* the resolution line's signs */
    double scale[3];        /* 1 / (EXPOSURE x COLORCORR) per channel */
    size_t size;            /* bytes of header and resolution line */
} rgbe_header;

/* One header line from b[*pos] to its '\n' (excluded) into line (NUL-terminated, cut at size);
 * 0, or -1 when no '\n' comes within the header's limit. */
static int next_line(const unsigned char *b, size_t n, size_t *pos, char *line, size_t size)
{
    size_t i = *pos, k = 0, end = n < RGBE_HEADER_MAX ? n : RGBE_HEADER_MAX;
    while (i < end && b[i] != '\n') {
        if (k + 1 < size) line[k++] = b[i] ? (char)b[i] : '?';
        i++;
    }
    line[k] = '\0';
    if (i >= end) return -1;
    *pos = i + 1;
    return 0;
}

static int header_error(const char *path, const char *what)
{
    fprintf(stderr, "%s: %s\n", path, what);
    return 1;
}

/* A positive finite number at s (end: after it), or 0. */
static double positive(const char *s, char **end)
{
    double v = strtod(s, end);
    return *end != s && v > 0.0 && v < 1e30 ? v : 0.0;
}

/* EXPOSURE=x (all channels) or COLORCORR=r g b: the writer multiplied the pixels by them, so the
 * reader divides. Several lines multiply. */
static int exposure_line(const char *line, rgbe_header *hd, const char *path)
{
    int all = line[0] == 'E', c;
    const char *s = line + (all ? 9 : 10);
    char *end;
    double v[3];
    for (c = 0; c < 3; c++) {
        v[c] = all && c > 0 ? v[0] : positive(s, &end);
        if (v[c] == 0.0) {
            fprintf(stderr, "%s: bad %s line '%.80s' (%s)\n", path, all ? "EXPOSURE" : "COLORCORR", shown(line),
                    all ? "a positive number" : "three positive numbers");
            return 1;
        }
        s = end;
        hd->scale[c] /= v[c];
    }
    return 0;
}

/* FORMAT=, EXPOSURE= and COLORCORR= lines; anything else (comments, VIEW=, SOFTWARE=, PRIMARIES=,
 * PIXASPECT=) is informative and skipped. *format: set when a valid FORMAT line was seen. */
static int header_line(const char *line, rgbe_header *hd, int *format, const char *path)
{
    if (strncmp(line, "FORMAT=", 7) == 0) {
        const char *f = line + 7;
        size_t k = strlen(f);
        while (k > 0 && (f[k - 1] == ' ' || f[k - 1] == '\t')) k--;
        if (k == 15 && strncmp(f, "32-bit_rle_rgbe", 15) == 0) return *format = 1, 0;
        if (k == 15 && strncmp(f, "32-bit_rle_xyze", 15) == 0)
            return header_error(path, "FORMAT=32-bit_rle_xyze: the pixels are CIE XYZ, not RGB; this "
                                "reader takes RGB only (Radiance's ra_xyze -r converts the file)");
        fprintf(stderr, "%s: unknown pixel format '%.80s' (a Radiance file says FORMAT=32-bit_rle_rgbe)\n",
                path, shown(f));
        return 1;
    }
    if (strncmp(line, "EXPOSURE=", 9) == 0 || strncmp(line, "COLORCORR=", 10) == 0)
        return exposure_line(line, hd, path);
    return 0;
}

/* "-Y" or "+X" then one space then a count of digits, at *p: 0 and *p past it, or -1. */
static int axis(const char **p, char *sign, char *name, long *count)
{
    const char *s = *p;
    long v = 0;
    if ((s[0] != '-' && s[0] != '+') || (s[1] != 'X' && s[1] != 'Y') || s[2] != ' ' || !(s[3] >= '0' && s[3] <= '9'))
        return -1;
    *sign = s[0];
    *name = s[1];
    for (s += 3; *s >= '0' && *s <= '9'; s++)
        if ((v = v * 10 + (*s - '0')) > (1L << 20)) return -1;
    *count = v;
    *p = s;
    return 0;
}

/* "-Y 480 +X 640": sign and axis, size, then the other axis. 0, or prints and returns 1. */
static int resolution(const char *line, rgbe_header *hd, const char *path)
{
    char a1, a2;
    long n1, n2;
    const char *p = line;
    if (axis(&p, &hd->sign1, &a1, &n1) == 0 && *p++ == ' ' && axis(&p, &hd->sign2, &a2, &n2) == 0
        && a1 != a2 && n1 >= 1 && n2 >= 1 && n1 <= (1L << 28) / n2) {
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\0') {
            hd->lines = n1;
            hd->len = n2;
            hd->columns = a1 == 'X';
            hd->w = hd->columns ? n1 : n2;
            hd->h = hd->columns ? n2 : n1;
            return 0;
        }
    }
    fprintf(stderr, "%s: bad resolution line '%.80s' (e.g. \"-Y 480 +X 640\": 480 rows from the top, "
            "640 pixels from the left; each side 1 to 1048576, at most 268435456 pixels)\n", path, shown(line));
    return 1;
}

/* The magic line, the header lines up to the blank one, and the resolution line. */
static int parse_header(const unsigned char *b, size_t n, rgbe_header *hd, const char *path)
{
    char line[1024];
    size_t pos = 0;
    int format = 0;
    hd->scale[0] = hd->scale[1] = hd->scale[2] = 1.0;
    if (n < 2 || b[0] != '#' || b[1] != '?' || next_line(b, n, &pos, line, sizeof line)
        || (strcmp(line, "#?RADIANCE") != 0 && strcmp(line, "#?RGBE") != 0 && strcmp(line, "#?RADIANCE\r") != 0))
        return header_error(path, "not a Radiance HDR file (it must begin with a line \"#?RADIANCE\" or \"#?RGBE\")");
    while (line[0] != '\0') {
        if (line[strlen(line) - 1] == '\r')
            return header_error(path, "the header's lines end with CR LF (a file written in text mode on "
                                "Windows?): Radiance headers end lines with LF only; open the file in binary mode (\"wb\")");
        if (line[0] != '#' && header_line(line, hd, &format, path)) return 1;
        if (next_line(b, n, &pos, line, sizeof line))
            return header_error(path, "truncated header: no blank line ends it (within its first 65536 bytes)");
    }
    if (!format)
        return header_error(path, "no FORMAT line in the header: this reader wants FORMAT=32-bit_rle_rgbe "
                            "(RGB), to be sure the pixels are not XYZ");
    if (next_line(b, n, &pos, line, sizeof line))
        return header_error(path, "truncated: no resolution line (e.g. \"-Y 480 +X 640\") after the header");
    if (resolution(line, hd, path)) return 1;
    hd->size = pos;
    return 0;
}

/* Bytes a scanline of len pixels takes at least and at most, over its encodings. */
static size_t line_bytes_min(long len)
{
    size_t flat = 4 * (size_t)len, old = 4 * (1 + ((size_t)len - 1 + 254) / 255);
    size_t rle = 4 + 8 * (((size_t)len + 126) / 127), m = old < flat ? old : flat;
    return len >= RGBE_RLE_MIN && len <= RGBE_RLE_MAX && rle < m ? rle : m;
}

static size_t line_bytes_max(long len)
{
    size_t flat = 4 * (size_t)len, rle = 4 + 4 * ((size_t)len + ((size_t)len + 127) / 128);
    return len >= RGBE_RLE_MIN && len <= RGBE_RLE_MAX && rle > flat ? rle : flat;
}

/* One channel of a new-style RLE scanline into out[4 * i + c]; *p advances. 0, or -1 when the
 * data ends, a packet is empty or overruns the scanline. */
static int rle_channel(const unsigned char *b, size_t n, size_t *p, unsigned char *out, long len, int c)
{
    long i = 0, k, count;
    while (i < len) {
        if (*p >= n) return -1;
        count = b[(*p)++];
        if (count > 128) {
            count -= 128;
            if (count > len - i || *p >= n) return -1;
            for (k = 0; k < count; k++) out[4 * (i + k) + c] = b[*p];
            (*p)++;
        } else {
            if (count == 0 || count > len - i || (size_t)count > n - *p) return -1;
            for (k = 0; k < count; k++) out[4 * (i + k) + c] = b[*p + k];
            *p += (size_t)count;
        }
        i += count;
    }
    return 0;
}

/* A flat scanline, with old-style runs. 0, or -1 when the data ends or a run has no pixel
 * before it or overruns the scanline. */
static int flat_line(const unsigned char *b, size_t n, size_t *p, unsigned char *out, long len)
{
    long i = 0, count;
    int shift = 0;
    while (i < len) {
        if (n - *p < 4) return -1;
        if (b[*p] == 1 && b[*p + 1] == 1 && b[*p + 2] == 1) {
            if (i == 0 || shift > 16) return -1;
            count = (long)b[*p + 3] << shift;
            if (count > len - i) return -1;
            for (; count > 0; count--, i++) memcpy(out + 4 * i, out + 4 * (i - 1), 4);
            shift += 8;
        } else {
            memcpy(out + 4 * i, b + *p, 4);
            i++;
            shift = 0;
        }
        *p += 4;
    }
    return 0;
}

static int read_line(const unsigned char *b, size_t n, size_t *p, unsigned char *out, long len)
{
    int c;
    if (len >= RGBE_RLE_MIN && len <= RGBE_RLE_MAX && n - *p >= 4 && b[*p] == 2 && b[*p + 1] == 2
        && !(b[*p + 2] & 0x80)) {
        if (((long)b[*p + 2] << 8 | b[*p + 3]) != len) return -2;
        *p += 4;
        for (c = 0; c < 4; c++)
            if (rle_channel(b, n, p, out, len, c)) return -1;
        return 0;
    }
    return flat_line(b, n, p, out, len);
}

/* Scanline i's pixel j is image pixel base + j * step (pixel index, row 0 at the top). */
static void line_place(const rgbe_header *hd, long i, long *base, long *step)
{
    long w = hd->w, h = hd->h;
    if (!hd->columns) {       /* -Y: the first scanline is the top row; -X: right to left */
        long y = hd->sign1 == '-' ? i : h - 1 - i;
        *base = y * w + (hd->sign2 == '+' ? 0 : w - 1);
        *step = hd->sign2 == '+' ? 1 : -1;
    } else {                  /* +X: the first column is the left one; +Y: bottom to top */
        long x = hd->sign1 == '+' ? i : w - 1 - i;
        *base = x + (hd->sign2 == '+' ? (h - 1) * w : 0);
        *step = hd->sign2 == '+' ? -w : w;
    }
}

static void put_line(image *im, const rgbe_header *hd, long i, const unsigned char *rgbe)
{
    long j, base, step;
    int c;
    line_place(hd, i, &base, &step);
    for (j = 0; j < hd->len; j++) {
        const unsigned char *q = rgbe + 4 * j;
        float *px = im->px + 3 * (size_t)(base + j * step);
        for (c = 0; c < 3; c++)
            px[c] = q[3] ? ldexpf((float)q[c] + 0.5f, q[3] - 136) : 0.0f;   /* (m + 0.5)/256 2^(e-128) */
        if (hd->scale[0] != 1.0 || hd->scale[1] != 1.0 || hd->scale[2] != 1.0)
            for (c = 0; c < 3; c++) px[c] = (float)(px[c] * hd->scale[c]);
    }
}

/* Checks the size of the pixel data (n bytes) against what the scanlines can take. */
static int check_size(const rgbe_header *hd, size_t n, const char *path)
{
    size_t lo = (size_t)hd->lines * line_bytes_min(hd->len), hi = (size_t)hd->lines * line_bytes_max(hd->len);
    if (n < lo) {
        fprintf(stderr, "%s: truncated: the resolution line declares %ld x %ld pixels, which take at least "
                "%zu bytes even run-length encoded; the file has %zu after its header\n", path, hd->w, hd->h, lo, n);
        return 1;
    }
    if (n > hi) {
        fprintf(stderr, "%s: %zu bytes after the header, more than %ld x %ld pixels can take (at most %zu): "
                "a second image, or a wrong resolution line?\n", path, n, hd->w, hd->h, hi);
        return 1;
    }
    return 0;
}

static int decode_lines(image *im, const rgbe_header *hd, const unsigned char *b, size_t n, const char *path)
{
    unsigned char *line = malloc(4 * (size_t)hd->len);
    size_t p = 0;
    long i;
    int r = 0;
    if (!line) return header_error(path, "out of memory");
    for (i = 0; i < hd->lines && r == 0; i++) {
        size_t at = p;
        r = read_line(b, n, &p, line, hd->len);
        if (r == -2)
            fprintf(stderr, "%s: scanline %ld of %ld (byte %zu of the pixel data): its run-length header gives "
                    "a length other than the resolution line's %ld\n", path, i, hd->lines, at, hd->len);
        else if (r)
            fprintf(stderr, "%s: scanline %ld of %ld (byte %zu of the pixel data): %s\n", path, i, hd->lines, at,
                    p >= n || n - p < 4 ? "truncated" : "bad run-length data (an empty packet, a run past the "
                    "end of the scanline, or an old-style run with no pixel before it)");
        else put_line(im, hd, i, line);
    }
    free(line);
    if (r == 0 && p != n) {
        fprintf(stderr, "%s: %zu bytes after the last scanline: a second image, or a wrong resolution line?\n",
                path, n - p);
        r = 1;
    }
    return r != 0;
}

/* A whole file in memory (n bytes). */
static int decode_hdr(image *im, const unsigned char *b, size_t n, const char *path)
{
    rgbe_header hd;
    im->w = im->h = 0;
    im->px = NULL;
    if (parse_header(b, n, &hd, path) || check_size(&hd, n - hd.size, path)) return 1;
    if (img_alloc(im, (int)hd.w, (int)hd.h)) return header_error(path, "out of memory");
    if (decode_lines(im, &hd, b + hd.size, n - hd.size, path)) {
        img_free(im);
        return 1;
    }
    return 0;
}

/* The header of the file f (at most RGBE_HEADER_MAX bytes) into *hd and the file's length into
 * *size, checked against the scanlines the resolution line declares: 0, or 1 after saying why. */
static int read_header(FILE *f, const char *path, rgbe_header *hd, long *size)
{
    unsigned char *b;
    size_t head;
    if (fseek(f, 0, SEEK_END) != 0 || (*size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0)
        return header_error(path, "cannot find the file's size");
    head = (size_t)*size < RGBE_HEADER_MAX ? (size_t)*size : RGBE_HEADER_MAX;
    b = malloc(head ? head : 1);
    if (!b) return header_error(path, "out of memory");
    if (fread(b, 1, head, f) != head || parse_header(b, head, hd, path) || check_size(hd, (size_t)*size - hd->size, path)) {
        if (ferror(f)) fprintf(stderr, "%s: read error: %s\n", path, strerror(errno));
        free(b);
        return 1;
    }
    free(b);
    return 0;
}

/* The file's bytes, read in two steps: the header first, so that the size check runs before the
 * pixel data is read into memory. */
static int read_checked(FILE *f, const char *path, unsigned char **out, size_t *n)
{
    unsigned char *b;
    rgbe_header hd;
    long size;
    if (read_header(f, path, &hd, &size)) return 1;
    b = malloc((size_t)size);
    if (!b) return header_error(path, "out of memory");
    if (fseek(f, 0, SEEK_SET) != 0 || fread(b, 1, (size_t)size, f) != (size_t)size) {
        fprintf(stderr, "%s: read error: %s\n", path, strerror(errno));
        free(b);
        return 1;
    }
    *out = b;
    *n = (size_t)size;
    return 0;
}

int img_read_hdr_size(const char *path, int *w, int *h)
{
    rgbe_header hd;
    long size;
    int err;
    char name[SHOWN_CAP];
    FILE *f = input_file_open(path, 1);
    snprintf(name, sizeof name, "%s", shown(path));
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", name, input_file_why(errno));
        return 1;
    }
    err = read_header(f, name, &hd, &size);
    fclose(f);
    if (!err) *w = (int)hd.w, *h = (int)hd.h;
    return err;
}

int img_read_hdr(image *im, const char *path)
{
    unsigned char *b = NULL;
    size_t n = 0;
    int err;
    FILE *f;
    char name[SHOWN_CAP];   /* the name in messages: a student's file name, shown escaped */
    snprintf(name, sizeof name, "%s", shown(path));
    im->w = im->h = 0;
    im->px = NULL;
    f = input_file_open(path, 1);
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", name, input_file_why(errno));
        return 1;
    }
    err = read_checked(f, name, &b, &n);
    fclose(f);
    if (err) return 1;
    err = decode_hdr(im, b, n, name);
    free(b);
    return err;
}
