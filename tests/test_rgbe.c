/* test_rgbe.c — the Radiance RGBE reader (image/rgbe.h): files written here by a truncating
 * encoder as gKit's (stb's) writer does it, m = floor(v * 256 / 2^e), flat, new-style and old-style
 * run-length encoded, in the 8 orientations of the resolution line; decoded values checked to the
 * half step; hostile headers; and, when installed, files written by OpenImageIO's oiiotool. */
#include "image/image.h"
#include "image/rgbe.h"
#include "check.h"
#include "scratch.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

static double uniform(void) { return (rng() >> 8) / 16777216.0; }

/* The truncating encoder of stb_image_write (which gKit uses): e from frexp of the largest channel,
 * m = (unsigned char)(v * 256 / 2^e), all zero below 1e-32. */
static void encode(const float *v, unsigned char *q)
{
    float mx = v[0] > v[1] ? v[0] : v[1];
    int e, c;
    if (v[2] > mx) mx = v[2];
    if (mx < 1e-32f) { q[0] = q[1] = q[2] = q[3] = 0; return; }
    frexp(mx, &e);
    for (c = 0; c < 3; c++) q[c] = (unsigned char)(v[c] * 256.0 / ldexp(1.0, e));
    q[3] = (unsigned char)(e + 128);
}

/* The step of a pixel's exponent byte: one unit of mantissa, 2^(e - 136). */
static double step_of(int ebyte) { return ldexp(1.0, ebyte - 136); }

/* A file's pixels in image order (row 0 at the top): 4 bytes each. */
typedef struct { int w, h; unsigned char *q; } rgbe_img;

/* Radiance coordinates: x to the right, y UP (0 at the bottom). A pair "sA n": its k-th step is
 * at k from the low end for '+', from the high end for '-'. */
static int along(char sign, int extent, int k) { return sign == '+' ? k : extent - 1 - k; }

/* The image pixel at scanline i, index j for a resolution line "s1A1 . s2A2 .". */
static const unsigned char *pixel_at(const rgbe_img *im, const char *res, int i, int j)
{
    int x, y_up;
    if (res[1] == 'Y') { y_up = along(res[0], im->h, i); x = along(res[3], im->w, j); }
    else { x = along(res[0], im->w, i); y_up = along(res[3], im->h, j); }
    return im->q + 4 * ((size_t)(im->h - 1 - y_up) * im->w + x);
}

/* One channel's bytes as new-style packets: runs of 3 or more as runs, the rest as literals. */
static void rle_channel(FILE *f, const unsigned char *v, int n)
{
    int i = 0;
    while (i < n) {
        int run = 1, lit;
        while (i + run < n && run < 127 && v[i + run] == v[i]) run++;
        if (run >= 3) {
            fputc(128 + run, f);
            fputc(v[i], f);
            i += run;
            continue;
        }
        for (lit = 1; i + lit < n && lit < 128; lit++)
            if (i + lit + 2 < n && v[i + lit] == v[i + lit + 1] && v[i + lit] == v[i + lit + 2]) break;
        fputc(lit, f);
        fwrite(v + i, 1, (size_t)lit, f);
        i += lit;
    }
}

enum { FLAT, RLE };

/* res: "-Y +X" style signs and axes (sizes filled in); header: extra header lines. */
static void write_hdr(const char *path, const rgbe_img *im, const char *res, int mode, const char *header)
{
    int lines = res[1] == 'Y' ? im->h : im->w, len = res[1] == 'Y' ? im->w : im->h, i, j, c;
    unsigned char *line = malloc(4 * (size_t)len), *chan = malloc((size_t)len);
    FILE *f = fopen(path, "wb");
    fprintf(f, "#?RADIANCE\n# written by test_rgbe\n%sFORMAT=32-bit_rle_rgbe\n\n%c%c %d %c%c %d\n", header,
            res[0], res[1], lines, res[3], res[4], len);
    for (i = 0; i < lines; i++) {
        for (j = 0; j < len; j++) memcpy(line + 4 * j, pixel_at(im, res, i, j), 4);
        if (mode == RLE && len >= 8 && len <= 32767) {
            fputc(2, f); fputc(2, f); fputc(len >> 8, f); fputc(len & 255, f);
            for (c = 0; c < 4; c++) {
                for (j = 0; j < len; j++) chan[j] = line[4 * j + c];
                rle_channel(f, chan, len);
            }
        } else fwrite(line, 4, (size_t)len, f);
    }
    fclose(f);
    free(line);
    free(chan);
}

/* A test image: values spread over 2^-12 .. 2^6, with flat patches (runs) and black pixels. */
static void make_image(rgbe_img *im, float *v, int w, int h)
{
    int i, c;
    im->w = w;
    im->h = h;
    im->q = malloc(4 * (size_t)w * h);
    for (i = 0; i < w * h; i++) {
        int patch = (i % w) / 5 % 2 == 0;
        for (c = 0; c < 3; c++)
            v[3 * i + c] = patch ? 0.25f * (float)(c + 1)
                                 : (float)(exp(-12.0 * log(2.0) * uniform() + 6.0 * log(2.0) * uniform()) * uniform());
        if (i % 17 == 3) v[3 * i] = v[3 * i + 1] = v[3 * i + 2] = 0.0f;
        encode(v + 3 * i, im->q + 4 * i);
    }
}

/* The decoded image is exactly (m + 0.5) steps of each stored pixel, at the same place. */
static int exact(const image *d, const rgbe_img *im, double scale)
{
    int i, c, bad = 0;
    if (d->w != im->w || d->h != im->h) return -1;
    for (i = 0; i < im->w * im->h; i++)
        for (c = 0; c < 3; c++) {
            const unsigned char *q = im->q + 4 * i;
            double want = q[3] ? (q[c] + 0.5) * step_of(q[3]) * scale : 0.0;
            if (fabs(d->px[3 * i + c] - want) > 1e-6 * want) bad++;
        }
    return bad;
}

static void test_half_step(void)
{
    enum { W = 101, H = 61 };
    static float v[W * H * 3];
    rgbe_img im;
    image d;
    double sum = 0.0, trunc_sum = 0.0, worst = 0.0;
    int i, c, n = 0, r;
    make_image(&im, v, W, H);
    write_hdr(in_dir("half.hdr"), &im, "-Y +X", FLAT, "");
    r = img_read_hdr(&d, in_dir("half.hdr"));
    check(r == 0 && exact(&d, &im, 1.0) == 0, "hdr_values_are_m_plus_half_step", "%d x %d, flat", d.w, d.h);
    for (i = 0; r == 0 && i < W * H; i++)
        for (c = 0; c < 3; c++) {
            const unsigned char *q = im.q + 4 * i;
            double s, e;
            if (!q[3] || (i % W) / 5 % 2 == 0 || v[3 * i + c] < 0.25 * step_of(q[3]) * 256)
                continue;   /* the patches' dyadic values and small channels (few bits) */
            s = step_of(q[3]);
            e = (d.px[3 * i + c] - v[3 * i + c]) / s;
            sum += e;
            trunc_sum += (q[c] * s - v[3 * i + c]) / s;
            if (fabs(e) > worst) worst = fabs(e);
            n++;
        }
    /* the error of each value is uniform in [-0.5, 0.5] steps: its mean over n values has a standard
     * deviation of 0.29 / sqrt(n), 0.006 here; the truncating decode is 0.5 steps low */
    check(r == 0 && n > 2000 && worst <= 0.5 && fabs(sum / n) < 0.03 && fabs(trunc_sum / n + 0.5) < 0.03,
          "hdr_decode_unbiased", "%d channels: mean error %+.4f steps (truncated decode %+.4f), worst %.3f",
          n, sum / n, trunc_sum / n, worst);
    if (r == 0) img_free(&d);
    free(im.q);
}

static void test_rle_and_orientations(void)
{
    static const char *const res[8] = {"-Y +X", "-Y -X", "+Y +X", "+Y -X", "+X +Y", "+X -Y", "-X +Y", "-X -Y"};
    static const int widths[] = {8, 9, 127, 128, 129, 300, 7, 1};
    static float v[300 * 13 * 3];
    rgbe_img im;
    image d;
    int k, mode, bad = 0, bad_rle = 0, r;
    char name[64];
    for (k = 0; k < 8; k++) {
        make_image(&im, v, widths[k], 13);
        write_hdr(in_dir("rle.hdr"), &im, "-Y +X", RLE, "");
        r = img_read_hdr(&d, in_dir("rle.hdr"));
        if (r || exact(&d, &im, 1.0)) bad_rle++, printf("  width %d: read %d\n", widths[k], r);
        if (!r) img_free(&d);
        free(im.q);
    }
    check(bad_rle == 0, "hdr_rle_scanlines", "widths 8, 9, 127, 128, 129, 300 run-length encoded, 7 and 1 flat");
    make_image(&im, v, 11, 9);
    for (k = 0; k < 8; k++)
        for (mode = FLAT; mode <= RLE; mode++) {
            snprintf(name, sizeof name, "orient%d.hdr", k);
            write_hdr(in_dir(name), &im, res[k], mode, "");
            r = img_read_hdr(&d, in_dir(name));
            if (r || exact(&d, &im, 1.0)) bad++, printf("  orientation '%s' %s: read %d\n", res[k], mode ? "rle" : "flat", r);
            if (!r) img_free(&d);
        }
    check(bad == 0, "hdr_8_orientations", "11 x 9, flat and run-length encoded, top row first whatever the order");
    free(im.q);
}

/* Old-style RLE: 1,1,1,n repeats the pixel before n << s times, s += 8 for each such pixel in a row. */
static void test_old_rle(void)
{
    static const unsigned char a[4] = {200, 100, 50, 130}, rep255[4] = {1, 1, 1, 255}, rep1[4] = {1, 1, 1, 1};
    unsigned char b[4] = {10, 20, 30, 128};
    FILE *f = fopen(in_dir("old.hdr"), "wb");
    image d;
    int i, r, bad = 0;
    fprintf(f, "#?RGBE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 600\n");
    for (i = 0; i < 2; i++) {
        int j;
        fwrite(a, 1, 4, f);        /* pixel 0 */
        fwrite(rep255, 1, 4, f);   /* 1..255 */
        fwrite(rep1, 1, 4, f);     /* 256..511: 1 << 8 */
        for (j = 512; j < 600; j++) { b[0] = (unsigned char)j; fwrite(b, 1, 4, f); }
    }
    fclose(f);
    r = img_read_hdr(&d, in_dir("old.hdr"));
    for (i = 0; r == 0 && i < 1200; i++) {
        int x = i % 600;
        double want = x < 512 ? (200 + 0.5) * step_of(130) : ((x & 255) + 0.5) * step_of(128);
        if (d.px[3 * i] != (float)want) bad++;
    }
    check(r == 0 && bad == 0, "hdr_old_style_rle", "runs of 255 and 1 << 8 pixels, %d wrong", bad);
    if (r == 0) img_free(&d);
}

static void test_exposure(void)
{
    static float v[16 * 4 * 3];
    rgbe_img im;
    image d;
    int r;
    make_image(&im, v, 16, 4);
    write_hdr(in_dir("exp.hdr"), &im, "-Y +X", RLE, "EXPOSURE=2\nEXPOSURE=   2.0000\n");
    r = img_read_hdr(&d, in_dir("exp.hdr"));
    check(r == 0 && exact(&d, &im, 0.25) == 0, "hdr_exposure_divides", "two EXPOSURE=2 lines: values / 4");
    if (r == 0) img_free(&d);
    write_hdr(in_dir("exp.hdr"), &im, "-Y +X", RLE, "EXPOSURE=1.0000000000000\n");
    r = img_read_hdr(&d, in_dir("exp.hdr"));
    check(r == 0 && exact(&d, &im, 1.0) == 0, "hdr_exposure_one_as_stb_writes_it", NULL);
    if (r == 0) img_free(&d);
    free(im.q);
}

/* img_read_hdr of bytes written as hostile.hdr; returns what it printed on stderr. */
static const char *read_hostile(const unsigned char *bytes, size_t n, int *rc, image *d)
{
    spit(in_dir("hostile.hdr"), bytes, n);
    capture_begin();
    *rc = img_read_hdr(d, in_dir("hostile.hdr"));
    return chop_newlines(capture_end());
}

/* A header then raw bytes (the pixel data: n of them, all 128 unless given). */
static int refused(const char *name, const char *head, const unsigned char *data, size_t n, const char *want)
{
    static unsigned char buf[70000];
    size_t h = strlen(head);
    image d = {7, 7, NULL};
    const char *msg;
    int rc = 0;
    memcpy(buf, head, h);
    if (data) memcpy(buf + h, data, n);
    else memset(buf + h, 128, n);
    msg = read_hostile(buf, h + n, &rc, &d);
    return check(rc != 0 && d.px == NULL && d.w == 0 && strstr(msg, want) && strstr(msg, "hostile.hdr: "),
                 name, "%.300s", msg);
}

#define HD "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"
static void test_hostile(void)
{
    static unsigned char big[66000];
    static const unsigned char empty_packet[] = {2, 2, 0, 8, 0, 1, 1, 1, 1, 1, 1, 1, 1};
    static const unsigned char overrun[] = {2, 2, 0, 8, 200, 5, 136, 1, 136, 1, 136, 1};
    static const unsigned char wrong_len[] = {2, 2, 0, 9, 136, 1, 136, 1, 136, 1, 136, 1};
    static const unsigned char trailing[] = {2, 2, 0, 8, 136, 1, 136, 1, 136, 1, 136, 1, 0};
    static const unsigned char old_first[] = {1, 1, 1, 4, 9, 9, 9, 9};
    size_t i;
    refused("hdr_refuses_no_magic", "#?RADIANC\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n", NULL, 4, "not a Radiance HDR file");
    refused("hdr_refuses_pfm", "PF\n1 1\n-1\n", NULL, 12, "not a Radiance HDR file");
    refused("hdr_refuses_no_format", "#?RADIANCE\n\n-Y 1 +X 1\n", NULL, 4, "no FORMAT line");
    refused("hdr_refuses_xyze", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n", NULL, 4, "CIE XYZ");
    refused("hdr_refuses_other_format", "#?RADIANCE\nFORMAT=16-bit\n\n-Y 1 +X 1\n", NULL, 4, "unknown pixel format");
    refused("hdr_refuses_crlf", "#?RADIANCE\r\nFORMAT=32-bit_rle_rgbe\r\n\r\n-Y 1 +X 1\r\n", NULL, 4, "CR LF");
    refused("hdr_refuses_crlf_after_magic", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\r\n\r\n-Y 1 +X 1\r\n", NULL, 4, "CR LF");
    refused("hdr_refuses_bad_exposure", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=-1\n\n-Y 1 +X 1\n", NULL, 4, "bad EXPOSURE");
    refused("hdr_refuses_nan_exposure", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=nan\n\n-Y 1 +X 1\n", NULL, 4, "bad EXPOSURE");
    refused("hdr_refuses_bad_colorcorr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nCOLORCORR=1 1\n\n-Y 1 +X 1\n", NULL, 4, "bad COLORCORR");
    refused("hdr_refuses_zero_size", HD "-Y 0 +X 4\n", NULL, 4, "bad resolution line");
    refused("hdr_refuses_same_axes", HD "-Y 2 +Y 2\n", NULL, 16, "bad resolution line");
    refused("hdr_refuses_huge_side", HD "-Y 1 +X 99999999999999999999\n", NULL, 4, "bad resolution line");
    refused("hdr_refuses_too_many_pixels", HD "-Y 1048576 +X 1048576\n", NULL, 4, "bad resolution line");
    refused("hdr_refuses_junk_resolution", HD "-Y 2 +X 2 x\n", NULL, 16, "bad resolution line");
    refused("hdr_refuses_no_resolution", HD, NULL, 0, "no resolution line");
    refused("hdr_refuses_declared_size_unfilled", HD "-Y 16384 +X 16384\n", NULL, 100, "truncated: the resolution line declares 16384 x 16384");
    refused("hdr_refuses_truncated_flat", HD "-Y 2 +X 3\n", NULL, 23, "truncated");
    refused("hdr_refuses_trailing_bytes", HD "-Y 1 +X 8\n", trailing, sizeof trailing, "1 bytes after the last scanline");
    refused("hdr_refuses_flat_too_long", HD "-Y 2 +X 3\n", NULL, 25, "more than 3 x 2 pixels can take");
    refused("hdr_refuses_far_too_long", HD "-Y 1 +X 1\n", NULL, 400, "more than 1 x 1 pixels can take");
    refused("hdr_refuses_empty_packet", HD "-Y 1 +X 8\n", empty_packet, sizeof empty_packet, "bad run-length data");
    refused("hdr_refuses_run_overrun", HD "-Y 1 +X 8\n", overrun, sizeof overrun, "bad run-length data");
    refused("hdr_refuses_rle_length", HD "-Y 1 +X 8\n", wrong_len, sizeof wrong_len, "other than the resolution line's 8");
    refused("hdr_refuses_old_run_first", HD "-Y 1 +X 2\n", old_first, sizeof old_first, "no pixel before it");
    for (i = 0; i < sizeof big - 1; i++) big[i] = i % 50 == 49 ? '\n' : 'a';
    big[sizeof big - 1] = 0;
    memcpy(big, "#?RADIANCE\n", 11);
    refused("hdr_refuses_endless_header", (const char *)big, NULL, 0, "no blank line");
}

static void test_not_regular(void)
{
    image d;
    time_t t0 = time(NULL);
    int r1, r2;
    mkfifo(in_dir("fifo.hdr"), 0600);
    r1 = img_read_hdr(&d, in_dir("fifo.hdr"));
    r2 = img_read_hdr(&d, scratch_dir);
    check(r1 != 0 && r2 != 0 && time(NULL) - t0 < 5, "hdr_refuses_fifo_and_folder", "no hang");
}

/* pathlab convert FILE.hdr FILE.pfm gives the same values as the reader. */
static void test_convert(void)
{
    const char *prog = getenv("PATHLAB");
    static float v[12 * 5 * 3];
    char cmd[1200];
    rgbe_img im;
    image d = {0, 0, NULL}, p = {0, 0, NULL};
    int r;
    make_image(&im, v, 12, 5);
    write_hdr(in_dir("conv.hdr"), &im, "+Y -X", RLE, "");
    snprintf(cmd, sizeof cmd, "'%s' convert '%s' '%s' > /dev/null", prog ? prog : "./pathlab", in_dir("conv.hdr"),
             in_dir("conv.pfm"));
    r = system(cmd);
    check(r == 0 && img_read_pfm(&p, in_dir("conv.pfm")) == 0 && img_read_hdr(&d, in_dir("conv.hdr")) == 0
          && memcmp(d.px, p.px, sizeof(float) * 3 * 60) == 0, "convert_hdr_to_pfm", "exit %d", r);
    img_free(&d);
    img_free(&p);
    free(im.q);
}

/* Values in [0.01, 100] (oiiotool --dumpdata prints 9 decimals: 1e-9 is far below their step). */
static void make_bright(float *v, int n)
{
    int i;
    for (i = 0; i < n; i++) v[i] = (float)(0.01 * exp(log(1e4) * uniform()));
}

/* oiiotool --dumpdata's values of a file, in image order (its y = 0 is the top row); the count read. */
static int oiio_values(const char *path, float *out, int w, int h)
{
    char cmd[600], line[256];
    FILE *p;
    int x, y, n = 0;
    float r, g, b;
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s' 2>&1", path);
    p = popen(cmd, "r");
    while (p && fgets(line, sizeof line, p))
        if (sscanf(line, " Pixel (%d, %d): %f %f %f", &x, &y, &r, &g, &b) == 5 && x >= 0 && x < w && y >= 0 && y < h) {
            out[3 * (y * w + x)] = r, out[3 * (y * w + x) + 1] = g, out[3 * (y * w + x) + 2] = b;
            n++;
        }
    if (p) pclose(p);
    return n;
}

/* oiiotool writes a .hdr of our PFM (truncating, as Walter's rgbe.c does): we read it within half a
 * step of the PFM, and half a step above oiiotool's own decoding (m steps). A pixel's step follows
 * from its largest channel, (m + 0.5) steps with m in [128, 255]: 2^(floor(log2(max)) - 7). */
static void test_oiiotool(void)
{
    enum { W = 64, H = 32 };
    static float v[W * H * 3], theirs[W * H * 3];
    image src, ours;
    char cmd[1200];
    int i, c, r, n, bad = 0, off = 0;
    double sum = 0.0;
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) {
        printf("SKIP hdr_oiiotool_files: no oiiotool\n");
        return;
    }
    make_bright(v, W * H * 3);
    img_alloc(&src, W, H);
    memcpy(src.px, v, sizeof v);
    img_write_pfm(&src, in_dir("src.pfm"));
    snprintf(cmd, sizeof cmd, "oiiotool '%s' -o '%s'", in_dir("src.pfm"), in_dir("oiio.hdr"));
    r = system(cmd);
    n = r == 0 ? oiio_values(in_dir("oiio.hdr"), theirs, W, H) : 0;
    if (r != 0 || n != W * H || img_read_hdr(&ours, in_dir("oiio.hdr"))) {
        check(0, "hdr_oiiotool_files", "oiiotool (%d) or a read failed (%d pixels dumped)", r, n);
        img_free(&src);
        return;
    }
    for (i = 0; i < W * H; i++) {
        const float *o = ours.px + 3 * i;
        double mx = fmax(o[0], fmax(o[1], o[2])), s = ldexp(1.0, (int)floor(log2(mx)) - 7);
        for (c = 0; c < 3; c++) {
            double d = o[c], t = theirs[3 * i + c], x = v[3 * i + c];
            if (fabs(t - (d - 0.5 * s)) > 2e-9 + 1e-7 * d || fabs(d - x) > 0.5 * s * (1 + 1e-6)) bad++;
            if (x > 64 * s) sum += (d - x) / s, off++;
        }
    }
    check(bad == 0 && off > 2000 && fabs(sum / off) < 0.03, "hdr_oiiotool_files",
          "%d x %d written by oiiotool: %d values not half a step above oiiotool's decoding or not within half "
          "a step of the source; mean error %+.4f steps over %d", W, H, bad, off ? sum / off : 0.0, off);
    img_free(&src);
    img_free(&ours);
}

int main(void)
{
    scratch_begin("test_rgbe");
    rng_seed(2463534242u);
    test_half_step();
    test_rle_and_orientations();
    test_old_rle();
    test_exposure();
    test_hostile();
    test_not_regular();
    test_convert();
    test_oiiotool();
    scratch_end();
    return check_summary();
}
