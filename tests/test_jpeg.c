/* test_jpeg.c — the JPEG decoder (image/decode.h) against OpenImageIO's (libjpeg) on files that
 * oiiotool writes: baseline 4:4:4, 4:2:2 and 4:2:0, greyscale, progressive (spectral selection and
 * successive approximation, 10 scans) 4:2:0 and 4:4:4, sizes that are not whole MCUs. IDCTs and
 * chroma upsampling differ between decoders (ours: float IDCT, chroma interpolated in float;
 * libjpeg's: integer IDCT and upsampling), so the codes are compared within a tolerance: the
 * mean |difference| and the largest, per file. Hostile files are refused. Skipped without oiiotool. */
#include "image/image.h"
#include "image/decode.h"
#include "check.h"
#include "scratch.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { W = 67, H = 45 };

/* oiiotool --dumpdata's 8-bit codes (grey replicated), in image order. */
static int oiio_codes(const char *path, int *out)
{
    char cmd[600], line[512];
    FILE *p;
    int n = 0;
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s' 2>&1", path);
    p = popen(cmd, "r");
    while (p && fgets(line, sizeof line, p)) {
        int x, y, v[3], k = 0, used;
        char *s = strstr(line, "):");
        if (!s || sscanf(line, " Pixel (%d, %d)", &x, &y) != 2 || x < 0 || x >= W || y < 0 || y >= H) continue;
        for (s += 2; k < 3 && sscanf(s, " %d%n", &v[k], &used) == 1; k++) s += used;
        out[3 * (y * W + x)] = v[0];
        out[3 * (y * W + x) + 1] = k == 3 ? v[1] : v[0];
        out[3 * (y * W + x) + 2] = k == 3 ? v[2] : v[0];
        n++;
    }
    if (p) pclose(p);
    return n;
}

/* A photograph-like image: smooth colour gradients, a disc with a sharp edge, some texture. */
static void make_source(void)
{
    image src;
    int x, y;
    img_alloc(&src, W, H);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            float *p = src.px + 3 * (y * W + x), disc = (x - 40) * (x - 40) + (y - 20) * (y - 20) < 150 ? 0.4f : 0.0f;
            p[0] = 0.1f + 0.6f * x / W + disc;
            p[1] = 0.2f + 0.5f * y / H + 0.1f * sinf(x * 0.7f) * sinf(y * 0.9f);
            p[2] = 0.8f - 0.5f * (x + y) / (W + H) - disc;
        }
    img_write_pfm(&src, in_dir("src.pfm"));
    img_free(&src);
}

static void refused(const char *name, const unsigned char *b, size_t n, const char *want);

/* Writes NAME with oiiotool's options, decodes it both ways; mean and max |difference| in codes. */
static void same_within(const char *name, const char *opts, double mean_tol, int max_tol)
{
    static int theirs[W * H * 3];
    char cmd[1200], msg[64] = "";
    image im;
    img_decoded in;
    double sum = 0.0;
    int i, worst = 0, r, n;
    snprintf(cmd, sizeof cmd, "oiiotool '%s' %s -o '%s' > /dev/null 2>&1", in_dir("src.pfm"), opts, in_dir(name));
    r = system(cmd);
    n = r == 0 ? oiio_codes(in_dir(name), theirs) : 0;
    r = r == 0 && n == W * H ? img_decode_file(&im, in_dir(name), &in) : 1;
    for (i = 0; r == 0 && i < W * H * 3; i++) {
        int d = abs((int)lroundf(im.px[i] * 255.0f) - theirs[i]);
        sum += d;
        if (d > worst) worst = d;
    }
    if (r == 0) snprintf(msg, sizeof msg, "%s", in.format);
    check(r == 0 && sum / (W * H * 3) <= mean_tol && worst <= max_tol && strcmp(msg, "JPEG") == 0, name,
          "oiiotool %s: mean |ours - libjpeg's| %.3f codes (at most %.2f), largest %d (at most %d)", opts,
          sum / (W * H * 3), mean_tol, worst, max_tol);
    if (r == 0) img_free(&im);
}

static void refused(const char *name, const unsigned char *b, size_t n, const char *want)
{
    image im = {2, 2, NULL};
    const char *msg;
    int r;
    spit(in_dir(name), b, n);
    capture_begin();
    r = img_decode_file(&im, in_dir(name), NULL);
    msg = chop_newlines(capture_end());
    check(r != 0 && im.px == NULL && strstr(msg, want), name, "%s", msg);
}

/* Hostile: a real file cut, its frame enlarged (the size check), its scan data damaged. */
static void test_hostile(void)
{
    FILE *f = fopen(in_dir("base.jpg"), "rb");
    unsigned char *b = malloc(1 << 16), *sof;
    size_t n = f ? fread(b, 1, 1 << 16, f) : 0, i;
    if (f) fclose(f);
    sof = NULL;
    for (i = 0; i + 8 < n; i++)
        if (b[i] == 0xff && b[i + 1] == 0xc0) { sof = b + i; break; }
    if (!sof) { check(0, "jpeg_hostile", "no base.jpg"); free(b); return; }
    {   /* its DQT segments made comments: decoded to flat grey (every quantiser 0) before */
        unsigned char *c = malloc(n);
        memcpy(c, b, n);
        for (i = 0; i + 1 < n; i++)
            if (c[i] == 0xff && c[i + 1] == 0xdb) c[i + 1] = 0xfe;
        refused("no_dqt.jpg", c, n, "quantisation table (DQT) is not defined");
        free(c);
    }
    refused("cut.jpg", b, n / 2, "truncated");
    sof[5] = sof[7] = 0x3e;   /* 16000 x 16000 */
    sof[6] = sof[8] = 0x80;
    refused("enlarged.jpg", b, n, "truncated: 16000 x 16000 pixels");
    sof[5] = sof[7] = 0;
    sof[6] = H;
    sof[8] = W;
    sof[4] = 12;
    refused("12bit.jpg", b, n, "other than 8-bit");
    sof[4] = 8;
    memset(b + n - 200, 0xff, 2);
    refused("marker_in_data.jpg", b, n, "");
    refused("no_eoi.jpg", (const unsigned char *)"\xff\xd8\xff\xe0\x00\x04" "ab", 8, "no end-of-image");
    free(b);
}

/* Written by hand: 16 x 16 grey, one block an MCU, a restart marker after each (DRI 1). Each
 * block's DC difference is +4 (category 3, bits 100): with the prediction reset at every restart
 * every block is 4 x 8 (its quantiser) / 8 = +4 over 128; without, they would climb 132, 136, ... */
static void test_restart(void)
{
    static const unsigned char head[] = {0xff, 0xd8, 0xff, 0xdb, 0, 0x43, 0},
        rest[] = {0xff, 0xc0, 0, 11, 8, 0, 16, 0, 16, 1, 1, 0x11, 0,
                  0xff, 0xc4, 0, 21, 0x00, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3,
                  0xff, 0xc4, 0, 20, 0x10, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                  0xff, 0xdd, 0, 4, 0, 1, 0xff, 0xda, 0, 8, 1, 1, 0, 0, 63, 0,
                  0x63, 0xff, 0xd0, 0x63, 0xff, 0xd1, 0x63, 0xff, 0xd2, 0x63, 0xff, 0xd9};
    unsigned char file[256];
    image im;
    int i, bad = 0, r;
    memcpy(file, head, sizeof head);
    memset(file + sizeof head, 8, 64);
    memcpy(file + sizeof head + 64, rest, sizeof rest);
    spit(in_dir("restart.jpg"), file, sizeof head + 64 + sizeof rest);
    r = img_decode_file(&im, in_dir("restart.jpg"), NULL);
    for (i = 0; r == 0 && i < 16 * 16 * 3; i++) bad += im.px[i] != 132.0f / 255.0f;
    check(r == 0 && bad == 0, "jpeg_restart_markers", "4 MCUs, DRI 1: %d values not 132", bad);
    if (r == 0) img_free(&im);
    file[sizeof head + 64 + sizeof rest - 7] = 0xd5;   /* RST1 -> RST5: the order is not checked; cut after it */
    refused("restart_cut.jpg", file, sizeof head + 64 + sizeof rest - 5, "restart marker is missing");
}

int main(void)
{
    scratch_begin("test_jpeg");
    test_restart();
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) {
        printf("SKIP jpeg_oiiotool: no oiiotool\n");
        scratch_end();
        return check_summary();
    }
    make_source();
    same_within("base.jpg", "--attrib jpeg:subsampling 4:4:4", 0.6, 3);
    same_within("q60.jpg", "--attrib jpeg:subsampling 4:4:4 --attrib Compression jpeg:60", 0.6, 3);
    same_within("s422.jpg", "--attrib jpeg:subsampling 4:2:2", 0.6, 4);
    same_within("s420.jpg", "--attrib jpeg:subsampling 4:2:0", 0.6, 4);
    same_within("grey.jpg", "--ch R", 0.6, 2);
    same_within("progressive444.jpg", "--attrib jpeg:progressive 1 --attrib jpeg:subsampling 4:4:4", 0.6, 3);
    same_within("progressive420.jpg", "--attrib jpeg:progressive 1 --attrib jpeg:subsampling 4:2:0", 0.6, 4);
    test_hostile();
    scratch_end();
    return check_summary();
}
