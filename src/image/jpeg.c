/* jpeg.c — JPEG files read (see decode.h), written from ITU-T T.81: Huffman-coded baseline and
 * extended sequential (SOF0, SOF1) and progressive (SOF2: spectral selection and successive
 * approximation) frames, 8-bit samples, 1 (grey) or 3 components (YCbCr, or RGB when an Adobe
 * APP14 segment says transform 0) with any sampling factors 1 to 4 (4:4:4, 4:2:2, 4:2:0 ...),
 * interleaved and non-interleaved scans, restart markers. Not read: arithmetic coding, lossless and
 * hierarchical frames, 12-bit samples, 4 components (CMYK), a height given by DNL.
 *
 * Every scan is decoded into the quantised coefficients of every block (2 bytes a coefficient: 2
 * bytes a pixel a component, less than the float image); at the end each block is dequantised,
 * inverse-transformed (a separable float IDCT: decoders differ by +-1 code here), and the colour is
 * converted, subsampled chroma interpolated between sample centres (as libjpeg's "fancy" upsampling). Before
 * anything is allocated the scan data must be able to hold the frame: every block takes at least
 * 1 bit (its DC) in a progressive file, 2 (DC and end of block) in a sequential one. */
#include "image/decode.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    unsigned char bits[17], val[256];
    int mincode[17], maxcode[18], valptr[17], defined;
} jhuff;

typedef struct {
    int id, h, v, tq, td, ta, dc_pred;
    long bw, bh;          /* blocks per row and column, padded to whole MCUs */
    long cw, ch;          /* blocks covering the component's own samples */
    int16_t *coef;        /* 64 a block, zig-zag order undone */
} jcomp;

typedef struct {
    const unsigned char *b;
    size_t n, pos;
    uint32_t bits;
    int count, pad;       /* bits held; of which zeros fed at a marker or the end (consumed: truncated) */
    uint16_t q[4][64];
    int q_defined;        /* bit t: table t was read (a file without its DQT decoded to flat grey) */
    jhuff dc[4], ac[4];
    jcomp c[3];
    int nc, w, h, hmax, vmax, progressive, restart, rgb, frame;
    long mcux, mcuy, eobrun;
    int ns, sc[3], ss, se, ah, al;   /* the current scan */
    const char *path;
    long max_pixels;                 /* the most pixels allowed (img_decode_cap) */
} jpeg;

static const unsigned char ZIGZAG[64] = {0, 1, 8, 16, 9, 2, 3, 10, 17, 24, 32, 25, 18, 11, 4, 5, 12, 19, 26, 33, 40, 48,
    41, 34, 27, 20, 13, 6, 7, 14, 21, 28, 35, 42, 49, 56, 57, 50, 43, 36, 29, 22, 15, 23, 30, 37, 44, 51, 58, 59, 52, 45,
    38, 31, 39, 46, 53, 60, 61, 54, 47, 55, 62, 63};

static int jfail(const jpeg *j, const char *what)
{
    fprintf(stderr, "%s: %s\n", j->path, what);
    return 1;
}

static unsigned be16(const unsigned char *b) { return (unsigned)b[0] << 8 | b[1]; }

/* ---- entropy-coded data: bytes with 0xFF 0x00 stuffing, ended by a marker ---- */

static void fill(jpeg *j)
{
    while (j->count <= 24) {
        unsigned v = 0;
        if (j->pos < j->n && !(j->b[j->pos] == 0xff && (j->pos + 1 >= j->n || j->b[j->pos + 1] != 0))) {
            v = j->b[j->pos++];
            if (v == 0xff) j->pos++;   /* the stuffed 0x00 */
        } else j->pad += 8;           /* a marker or the end: zeros, counted */
        j->bits |= v << (24 - j->count);
        j->count += 8;
    }
}

static unsigned get_bits(jpeg *j, int k)
{
    unsigned v;
    if (k == 0) return 0;
    if (j->count < k) fill(j);
    v = j->bits >> (32 - k);
    j->bits <<= k;
    j->count -= k;
    return v;
}

/* A value of s bits, its sign from the first bit (T.81 F.2.2.1, EXTEND). */
static int receive_extend(jpeg *j, int s)
{
    int v;
    if (s == 0) return 0;
    v = (int)get_bits(j, s);
    return v < 1 << (s - 1) ? v - (1 << s) + 1 : v;
}

/* One Huffman symbol (T.81 F.2.2.3, DECODE), or -1 for a code the table does not have. */
static int decode(jpeg *j, const jhuff *t)
{
    int code = (int)get_bits(j, 1), l = 1;
    while (code > t->maxcode[l]) {
        if (++l > 16) return -1;
        code = code << 1 | (int)get_bits(j, 1);
    }
    return t->val[t->valptr[l] + code - t->mincode[l]];
}

/* ---- segments ---- */

static int read_dht(jpeg *j, const unsigned char *s, size_t len)
{
    while (len > 0) {
        int tc = s[0] >> 4, th = s[0] & 15, l, total = 0, code = 0, k = 0;
        jhuff *t;
        if (len < 17 || tc > 1 || th > 3) return jfail(j, "bad DHT segment");
        t = tc ? &j->ac[th] : &j->dc[th];
        for (l = 1; l <= 16; l++) total += t->bits[l] = s[l];
        if (total > 256 || (size_t)total > len - 17) return jfail(j, "bad DHT segment: more codes than bytes");
        memcpy(t->val, s + 17, (size_t)total);
        for (l = 1; l <= 16; l++) {   /* T.81 C.2 and F.2.2.3: the codes of each length, in order */
            t->mincode[l] = code;
            t->valptr[l] = k;
            code += t->bits[l];
            k += t->bits[l];
            t->maxcode[l] = t->bits[l] ? code - 1 : -1;
            if (code > 1 << l) return jfail(j, "bad DHT segment: more codes than a length allows");
            code <<= 1;
        }
        t->maxcode[17] = 0x7fffffff;
        t->defined = 1;
        s += 17 + total;
        len -= 17 + (size_t)total;
    }
    return 0;
}

static int read_dqt(jpeg *j, const unsigned char *s, size_t len)
{
    while (len > 0) {
        int pq = s[0] >> 4, tq = s[0] & 15, k;
        size_t size = 1 + 64 * (size_t)(pq + 1);
        if (pq > 1 || tq > 3 || len < size) return jfail(j, "bad DQT segment");
        for (k = 0; k < 64; k++) j->q[tq][ZIGZAG[k]] = (uint16_t)(pq ? be16(s + 1 + 2 * k) : s[1 + k]);
        j->q_defined |= 1 << tq;
        s += size;
        len -= size;
    }
    return 0;
}

/* The frame's blocks and their size check; the coefficient arrays. */
static int frame_layout(jpeg *j)
{
    size_t blocks = 0, left = j->n - j->pos;
    int i;
    j->mcux = (j->w + 8L * j->hmax - 1) / (8L * j->hmax);
    j->mcuy = (j->h + 8L * j->vmax - 1) / (8L * j->vmax);
    for (i = 0; i < j->nc; i++) {
        jcomp *c = &j->c[i];
        c->bw = j->mcux * c->h;
        c->bh = j->mcuy * c->v;
        c->cw = ((long)j->w * c->h + 8L * j->hmax - 1) / (8L * j->hmax);
        c->ch = ((long)j->h * c->v + 8L * j->vmax - 1) / (8L * j->vmax);
        blocks += (size_t)c->cw * (size_t)c->ch;
    }
    if (left < blocks / (j->progressive ? 8 : 4)) {
        fprintf(stderr, "%s: truncated: %d x %d pixels take %zu blocks, which %zu bytes of data cannot hold\n",
                j->path, j->w, j->h, blocks, left);
        return 1;
    }
    for (i = 0; i < j->nc; i++) {
        j->c[i].coef = calloc((size_t)j->c[i].bw * (size_t)j->c[i].bh, 64 * sizeof(int16_t));
        if (!j->c[i].coef) return jfail(j, "out of memory");
    }
    return 0;
}

static int read_sof(jpeg *j, const unsigned char *s, size_t len, int marker)
{
    int i;
    if (j->frame) return jfail(j, "a second frame header (SOF)");
    if (len < 6 || s[0] != 8) return jfail(j, "a JPEG of other than 8-bit samples (12-bit and lossless are not read)");
    j->h = (int)be16(s + 1);
    j->w = (int)be16(s + 3);
    j->nc = s[5];
    j->progressive = marker == 0xc2;
    if (j->h == 0) return jfail(j, "a JPEG whose height is given later (DNL): not read");
    if (j->w == 0) return jfail(j, "bad JPEG size (width 0)");
    if ((long)j->w * j->h > j->max_pixels) {
        fprintf(stderr, "%s: JPEG of %d x %d pixels, over the %ld allowed here\n", j->path, j->w, j->h, j->max_pixels);
        return 1;
    }
    if ((j->nc != 1 && j->nc != 3) || len < 6 + 3 * (size_t)j->nc)
        return jfail(j, "a JPEG of other than 1 (grey) or 3 components (CMYK is not read)");
    j->hmax = j->vmax = 1;
    for (i = 0; i < j->nc; i++) {
        jcomp *c = &j->c[i];
        c->id = s[6 + 3 * i];
        c->h = s[7 + 3 * i] >> 4;
        c->v = s[7 + 3 * i] & 15;
        c->tq = s[8 + 3 * i];
        if (c->h < 1 || c->h > 4 || c->v < 1 || c->v > 4 || c->tq > 3) return jfail(j, "bad sampling factors or quantisation table");
        if (c->h > j->hmax) j->hmax = c->h;
        if (c->v > j->vmax) j->vmax = c->v;
    }
    j->frame = 1;
    return frame_layout(j);
}

static int read_sos(jpeg *j, const unsigned char *s, size_t len)
{
    int i, k;
    if (!j->frame) return jfail(j, "a scan before the frame header");
    if (len < 1) return jfail(j, "bad SOS segment");   /* its count of components is its first byte */
    j->ns = s[0];
    if (len < 4 + 2 * (size_t)j->ns || j->ns < 1 || j->ns > j->nc) return jfail(j, "bad SOS segment");
    for (i = 0; i < j->ns; i++) {
        for (k = 0; k < j->nc && j->c[k].id != s[1 + 2 * i]; k++) {}
        if (k == j->nc) return jfail(j, "a scan of a component the frame does not have");
        j->sc[i] = k;
        j->c[k].td = s[2 + 2 * i] >> 4;
        j->c[k].ta = s[2 + 2 * i] & 15;
        if (j->c[k].td > 3 || j->c[k].ta > 3) return jfail(j, "bad Huffman table number");
    }
    j->ss = s[1 + 2 * j->ns];
    j->se = s[2 + 2 * j->ns];
    j->ah = s[3 + 2 * j->ns] >> 4;
    j->al = s[3 + 2 * j->ns] & 15;
    if (!j->progressive && (j->ss != 0 || j->se != 63 || j->ah || j->al)) return jfail(j, "bad SOS parameters for a sequential JPEG");
    if (j->progressive && (j->ss > j->se || j->se > 63 || (j->ss == 0 && j->se != 0) || (j->ss > 0 && j->ns != 1)
                           || j->al > 13 || j->ah > 13))
        return jfail(j, "bad progressive scan parameters");
    return 0;
}

/* ---- blocks ---- */

static int block_sequential(jpeg *j, jcomp *c, int16_t *blk)
{
    int t = decode(j, &j->dc[c->td]), k = 1;
    if (t < 0 || t > 11) return -1;
    c->dc_pred += receive_extend(j, t);
    if (c->dc_pred > 2047 * 8 || c->dc_pred < -2048 * 8) return -1;
    blk[0] = (int16_t)c->dc_pred;
    while (k < 64) {
        int rs = decode(j, &j->ac[c->ta]), r = rs >> 4, s = rs & 15;
        if (rs < 0) return -1;
        if (s == 0) {
            if (r != 15) break;
            k += 16;
            continue;
        }
        k += r;
        if (k > 63) return -1;
        blk[ZIGZAG[k++]] = (int16_t)receive_extend(j, s);
    }
    return 0;
}

static int block_dc(jpeg *j, jcomp *c, int16_t *blk)
{
    int t;
    if (j->ah) {   /* refinement: one more bit of the DC */
        if (get_bits(j, 1)) blk[0] = (int16_t)(blk[0] | 1 << j->al);
        return 0;
    }
    t = decode(j, &j->dc[c->td]);
    if (t < 0 || t > 11) return -1;
    c->dc_pred += receive_extend(j, t);
    if (c->dc_pred > 2047 * 8 || c->dc_pred < -2048 * 8) return -1;
    blk[0] = (int16_t)(c->dc_pred * (1 << j->al));
    return 0;
}

static int block_ac_first(jpeg *j, jcomp *c, int16_t *blk)
{
    int k;
    if (j->eobrun > 0) { j->eobrun--; return 0; }
    for (k = j->ss; k <= j->se; k++) {
        int rs = decode(j, &j->ac[c->ta]), r = rs >> 4, s = rs & 15;
        if (rs < 0) return -1;
        if (s == 0) {
            if (r < 15) {   /* EOBr: this block and 2^r - 1 + (r bits) more end here */
                j->eobrun = (1L << r) - 1 + (long)get_bits(j, r);
                break;
            }
            k += 15;
            continue;
        }
        k += r;
        if (k > 63) return -1;
        blk[ZIGZAG[k]] = (int16_t)(receive_extend(j, s) * (1 << j->al));
    }
    return 0;
}

/* A correction bit for a coefficient already nonzero: its magnitude gains the bit p1. */
static void refine(jpeg *j, int16_t *coef, int p1)
{
    if (get_bits(j, 1) && (*coef & p1) == 0) *coef = (int16_t)(*coef + (*coef >= 0 ? p1 : -p1));
}

static int block_ac_refine(jpeg *j, jcomp *c, int16_t *blk)
{
    int p1 = 1 << j->al, k = j->ss;
    if (j->eobrun == 0)
        for (; k <= j->se; k++) {
            int rs = decode(j, &j->ac[c->ta]), r = rs >> 4, s = rs & 15, v = 0;
            if (rs < 0 || s > 1) return -1;
            if (s) v = get_bits(j, 1) ? p1 : -p1;
            else if (r < 15) {
                j->eobrun = (1L << r) + (long)get_bits(j, r);
                break;
            }
            /* r zero coefficients skipped (the nonzero ones on the way take correction bits), then v */
            for (; k <= j->se; k++) {
                int16_t *z = blk + ZIGZAG[k];
                if (*z) refine(j, z, p1);
                else if (--r < 0) break;
            }
            if (s) {
                if (k > j->se) return -1;
                blk[ZIGZAG[k]] = (int16_t)v;
            }
        }
    if (j->eobrun > 0) {
        for (; k <= j->se; k++)
            if (blk[ZIGZAG[k]]) refine(j, blk + ZIGZAG[k], p1);
        j->eobrun--;
    }
    return 0;
}

static int block(jpeg *j, jcomp *c, long bx, long by)
{
    int16_t *blk = c->coef + 64 * ((size_t)by * c->bw + (size_t)bx);
    if (!j->progressive) return block_sequential(j, c, blk);
    if (j->ss == 0) return block_dc(j, c, blk);
    return j->ah ? block_ac_refine(j, c, blk) : block_ac_first(j, c, blk);
}

/* ---- scans ---- */

/* The tables a scan needs are there. */
static int scan_tables(const jpeg *j)
{
    int i;
    for (i = 0; i < j->ns; i++) {
        const jcomp *c = &j->c[j->sc[i]];
        if ((j->ss == 0 && !j->ah && !j->dc[c->td].defined) || (j->se > 0 && !j->ac[c->ta].defined)) return 0;
    }
    return 1;
}

static void scan_reset(jpeg *j)
{
    int i;
    for (i = 0; i < j->nc; i++) j->c[i].dc_pred = 0;
    j->eobrun = 0;
    j->bits = 0;
    j->count = j->pad = 0;
}

/* After restart-interval MCUs: the RSTn marker, then predictions start again. */
static int restart_marker(jpeg *j)
{
    while (j->pos + 1 < j->n && j->b[j->pos] == 0xff && j->b[j->pos + 1] == 0xff) j->pos++;
    if (j->pos + 1 >= j->n || j->b[j->pos] != 0xff || (j->b[j->pos + 1] & 0xf8) != 0xd0) return -1;
    j->pos += 2;
    scan_reset(j);
    return 0;
}

static int mcu(jpeg *j, long mx, long my)
{
    int i, h, v;
    if (j->ns == 1) return block(j, &j->c[j->sc[0]], mx, my);
    for (i = 0; i < j->ns; i++) {
        jcomp *c = &j->c[j->sc[i]];
        for (v = 0; v < c->v; v++)
            for (h = 0; h < c->h; h++)
                if (block(j, c, mx * c->h + h, my * c->v + v)) return -1;
    }
    return 0;
}

/* The entropy-coded data of a scan, from j->pos to the next marker. */
static int scan(jpeg *j)
{
    const jcomp *c0 = &j->c[j->sc[0]];
    long w = j->ns == 1 ? c0->cw : j->mcux, h = j->ns == 1 ? c0->ch : j->mcuy, m;
    if (!scan_tables(j)) return jfail(j, "a scan uses a Huffman table that was not defined");
    scan_reset(j);
    for (m = 0; m < w * h; m++) {
        if (j->restart && m > 0 && m % j->restart == 0 && restart_marker(j)) return jfail(j, "a restart marker is missing");
        if (mcu(j, m % w, m / w)) return jfail(j, "bad entropy-coded data (a code not in its table, or a value out of range)");
        if (j->count < j->pad) return jfail(j, "truncated: a scan's data ends before its last block");
    }
    while (j->pos + 1 < j->n && !(j->b[j->pos] == 0xff && j->b[j->pos + 1] != 0 && (j->b[j->pos + 1] & 0xf8) != 0xd0)) j->pos++;
    return 0;
}

/* ---- pixels ---- */

/* out = IDCT of the dequantised block (T.81 A.3.3), level-shifted, rounded, clamped to 0..255. */
static void idct(const int16_t *blk, const uint16_t *q, unsigned char *out, size_t stride, float cs[8][8])
{
    float tmp[64];
    int x, y, u;
    for (y = 0; y < 8; y++)   /* rows of coefficients v = y, then columns */
        for (x = 0; x < 8; x++) {
            float t = 0.0f;
            for (u = 0; u < 8; u++) t += cs[x][u] * (float)(blk[8 * y + u] * q[8 * y + u]);
            tmp[8 * y + x] = t;
        }
    for (y = 0; y < 8; y++)
        for (x = 0; x < 8; x++) {
            float t = 128.0f;
            for (u = 0; u < 8; u++) t += cs[y][u] * tmp[8 * u + x];
            out[(size_t)y * stride + x] = (unsigned char)(t <= 0.0f ? 0 : t >= 255.0f ? 255 : (int)(t + 0.5f));
        }
}

static unsigned char *component_samples(const jpeg *j, const jcomp *c)
{
    size_t stride = 8 * (size_t)c->bw;
    unsigned char *plane = malloc(stride * 8 * (size_t)c->bh);
    float cs[8][8];   /* cs[x][u] = C(u)/2 cos((2x + 1) u pi / 16) */
    long bx, by;
    int x, u;
    if (!plane) return NULL;
    for (x = 0; x < 8; x++)
        for (u = 0; u < 8; u++) cs[x][u] = (float)((u ? 0.5 : 0.5 / sqrt(2.0)) * cos((2 * x + 1) * u * PI / 16));
    for (by = 0; by < c->bh; by++)
        for (bx = 0; bx < c->bw; bx++)
            idct(c->coef + 64 * ((size_t)by * c->bw + (size_t)bx), j->q[c->tq], plane + 8 * ((size_t)by * stride + (size_t)bx), stride, cs);
    return plane;
}

/* Component c's sample at image pixel (x, y). A subsampled component is interpolated between its
 * two (four) nearest samples, each sample sitting at the centre of the pixels it covers (libjpeg's
 * "fancy" upsampling: weights 3/4 and 1/4 for a factor 2), the edges repeated. */
static float sample_at(const unsigned char *plane, const jcomp *c, const jpeg *j, long x, long y)
{
    size_t stride = 8 * (size_t)c->bw;
    long sw = ((long)j->w * c->h + j->hmax - 1) / j->hmax, sh = ((long)j->h * c->v + j->vmax - 1) / j->vmax, x0, y0, x1, y1;
    float fx, fy, ax, ay, top, bottom;
    if (c->h == j->hmax && c->v == j->vmax) return plane[(size_t)y * stride + (size_t)x];
    fx = (x + 0.5f) * (float)c->h / (float)j->hmax - 0.5f;
    fy = (y + 0.5f) * (float)c->v / (float)j->vmax - 0.5f;
    x0 = (long)floorf(fx);
    y0 = (long)floorf(fy);
    ax = fx - (float)x0;
    ay = fy - (float)y0;
    x1 = x0 + 1 < sw ? x0 + 1 : sw - 1;
    y1 = y0 + 1 < sh ? y0 + 1 : sh - 1;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    top = (1 - ax) * plane[(size_t)y0 * stride + (size_t)x0] + ax * plane[(size_t)y0 * stride + (size_t)x1];
    bottom = (1 - ax) * plane[(size_t)y1 * stride + (size_t)x0] + ax * plane[(size_t)y1 * stride + (size_t)x1];
    return (1 - ay) * top + ay * bottom;
}

static float code(float v) { return (v <= 0.0f ? 0.0f : v >= 255.0f ? 255.0f : floorf(v + 0.5f)) / 255.0f; }

/* The samples of every component into the image: grey, RGB, or YCbCr (JFIF) converted. */
static int to_image(image *im, const jpeg *j)
{
    unsigned char *plane[3] = {NULL, NULL, NULL};
    int i, err = 0;
    long x, y;
    for (i = 0; i < j->nc; i++)
        if (!(j->q_defined >> j->c[i].tq & 1)) return jfail(j, "a component's quantisation table (DQT) is not defined");
    for (i = 0; i < j->nc; i++)
        if (!(plane[i] = component_samples(j, &j->c[i]))) err = jfail(j, "out of memory");
    if (!err && img_alloc(im, j->w, j->h)) err = jfail(j, "out of memory");
    for (y = 0; !err && y < j->h; y++)
        for (x = 0; x < j->w; x++) {
            float s[3], *px = im->px + 3 * ((size_t)y * j->w + x);
            for (i = 0; i < j->nc; i++) s[i] = sample_at(plane[i], &j->c[i], j, x, y);
            if (j->nc == 1) px[0] = px[1] = px[2] = s[0] / 255.0f;
            else if (j->rgb) px[0] = s[0] / 255.0f, px[1] = s[1] / 255.0f, px[2] = s[2] / 255.0f;
            else {
                px[0] = code(s[0] + 1.402f * (s[2] - 128.0f));
                px[1] = code(s[0] - 0.344136f * (s[1] - 128.0f) - 0.714136f * (s[2] - 128.0f));
                px[2] = code(s[0] + 1.772f * (s[1] - 128.0f));
            }
        }
    for (i = 0; i < 3; i++) free(plane[i]);
    return err;
}

/* ---- the file: markers and segments ---- */

static int segment(jpeg *j, int marker, const unsigned char *s, size_t len)
{
    if (marker == 0xc0 || marker == 0xc1 || marker == 0xc2) return read_sof(j, s, len, marker);
    if (marker == 0xc4) return read_dht(j, s, len);
    if (marker == 0xdb) return read_dqt(j, s, len);
    if (marker == 0xdd) {
        if (len < 2) return jfail(j, "bad DRI segment");
        j->restart = (int)be16(s);
        return 0;
    }
    if (marker == 0xee && len >= 12 && memcmp(s, "Adobe", 5) == 0) j->rgb = s[11] == 0;
    if ((marker >= 0xc3 && marker <= 0xcf) || marker == 0xde || marker == 0xdc)
        return jfail(j, "an arithmetic-coded, lossless or hierarchical JPEG: not read (baseline and progressive Huffman only)");
    return 0;
}

static int markers(jpeg *j)
{
    int scans = 0;
    for (;;) {
        int m;
        size_t len;
        while (j->pos < j->n && j->b[j->pos] != 0xff) j->pos++;   /* bytes between segments: skipped */
        while (j->pos + 1 < j->n && j->b[j->pos + 1] == 0xff) j->pos++;
        if (j->pos + 1 >= j->n) return jfail(j, "truncated: no end-of-image marker");
        m = j->b[j->pos + 1];
        j->pos += 2;
        if (m == 0xd9) break;
        if ((m & 0xf8) == 0xd0 || m == 0x01 || m == 0) continue;
        if (j->n - j->pos < 2 || (len = be16(j->b + j->pos)) < 2 || len > j->n - j->pos) return jfail(j, "truncated: a segment runs past the end");
        j->pos += len;
        if (segment(j, m, j->b + j->pos - len + 2, len - 2)) return 1;
        if (m == 0xda && (read_sos(j, j->b + j->pos - len + 2, len - 2) || scan(j))) return 1;
        scans += m == 0xda;
    }
    return scans ? 0 : jfail(j, "no scan: no pixel data");
}

int img_decode_jpeg(image *im, const unsigned char *b, size_t n, const char *path, img_decoded *info, long max_pixels)
{
    jpeg *j = calloc(1, sizeof *j);
    int err, i;
    im->w = im->h = 0;
    im->px = NULL;
    if (!j) return fprintf(stderr, "%s: out of memory\n", path), 1;
    j->b = b;
    j->n = n;
    j->pos = 2;
    j->path = path;
    j->max_pixels = img_decode_cap(max_pixels);
    err = n < 4 || b[0] != 0xff || b[1] != 0xd8 ? jfail(j, "not a JPEG file") : markers(j) || !j->frame;
    if (!err) err = to_image(im, j);
    if (!err) {
        info->format = "JPEG";
        info->encoding = IMG_ENC_INTEGER;
        info->bits = 8;
        info->maxval = 255;
        info->channels = j->nc;
        info->had_alpha = 0;
    }
    for (i = 0; i < 3; i++) free(j->c[i].coef);
    free(j);
    if (err) img_free(im);
    return err;
}
