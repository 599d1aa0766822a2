/* test_decode.c — img_decode_file (image/decode.h): the format told by the first bytes, not the
 * name; PPM/PGM (P2, P3, P5, P6, 8 and 16 bits), TGA (types 1, 2, 3, 9, 10, 11, both origins, right
 * to left) written here byte by byte, with their values and img_decoded facts; hostile headers;
 * and, when installed, files written by OpenImageIO's oiiotool compared with its own decoding. */
#include "image/image.h"
#include "image/decode.h"
#include "check.h"
#include "scratch.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Decodes bytes written as `name`, stderr captured into msg. */
static int decode(const char *name, const void *bytes, size_t n, image *im, img_decoded *info, char *msg, size_t size)
{
    int rc;
    spit(in_dir(name), bytes, n);
    capture_begin();
    rc = img_decode_file(im, in_dir(name), info);
    snprintf(msg, size, "%s", chop_newlines(capture_end()));
    return rc;
}

/* im's values are want (w*h*3 floats) within tol. */
static int same(const image *im, const float *want, int w, int h, float tol)
{
    int i;
    if (im->w != w || im->h != h || !im->px) return 0;
    for (i = 0; i < w * h * 3; i++)
        if (fabsf(im->px[i] - want[i]) > tol) return 0;
    return 1;
}

static void test_ppm(void)
{
    static const unsigned char p6[] = "P6\n# a comment\n2 1\n255\n\x00\x80\xff\x10\x20\x30";
    static const unsigned char p6_16[] = "P6 1 1 1000\n\x03\xe8\x01\xf4\x00\x00";
    static const char p3[] = "P3\n2 1 # size\n15\n0 5 15\n 10 1\n2\n";
    static const unsigned char p5[] = "P5\n2 1\n255\n\x33\x66";
    static const char p2[] = "P2 1 2 7 7 0";
    const float w6[6] = {0, 128 / 255.f, 1, 16 / 255.f, 32 / 255.f, 48 / 255.f}, w16[3] = {1, 0.5f, 0};
    const float w3[6] = {0, 5 / 15.f, 1, 10 / 15.f, 1 / 15.f, 2 / 15.f}, w5[6] = {0.2f, 0.2f, 0.2f, 0.4f, 0.4f, 0.4f};
    const float w2[6] = {1, 1, 1, 0, 0, 0};
    image im;
    img_decoded in;
    char msg[2048];
    int r;
    r = decode("p6.png", p6, sizeof p6 - 1, &im, &in, msg, sizeof msg);   /* the name says PNG: the bytes rule */
    check(r == 0 && same(&im, w6, 2, 1, 0) && strcmp(in.format, "PPM") == 0 && in.encoding == IMG_ENC_INTEGER
          && in.bits == 8 && in.maxval == 255 && in.channels == 3 && !in.had_alpha, "decode_ppm_p6_by_magic", "%s", msg);
    if (!r) img_free(&im);
    r = decode("p6_16.ppm", p6_16, sizeof p6_16 - 1, &im, &in, msg, sizeof msg);
    check(r == 0 && same(&im, w16, 1, 1, 0) && in.bits == 10 && in.maxval == 1000, "decode_ppm_16_bit_maxval_1000", "%s", msg);
    if (!r) img_free(&im);
    r = decode("p3.ppm", p3, sizeof p3 - 1, &im, &in, msg, sizeof msg);
    check(r == 0 && same(&im, w3, 2, 1, 1e-7f), "decode_ppm_p3_comments", "%s", msg);
    if (!r) img_free(&im);
    r = decode("p5.pgm", p5, sizeof p5 - 1, &im, &in, msg, sizeof msg);
    check(r == 0 && same(&im, w5, 2, 1, 1e-7f) && in.channels == 1, "decode_pgm_p5_grey_replicated", "%s", msg);
    if (!r) img_free(&im);
    r = decode("p2.pgm", p2, sizeof p2 - 1, &im, &in, msg, sizeof msg);
    check(r == 0 && same(&im, w2, 1, 2, 0), "decode_pgm_p2", "%s", msg);
    if (!r) img_free(&im);
}

/* A hostile file is refused, with im empty and a message naming the file and saying want. */
static void refused(const char *name, const void *bytes, size_t n, const char *want)
{
    image im = {3, 3, NULL};
    img_decoded in;
    char msg[2048];
    int r = decode(name, bytes, n, &im, &in, msg, sizeof msg);
    check(r != 0 && im.px == NULL && im.w == 0 && strstr(msg, want) && strstr(msg, name), name, "%s", msg);
}

static void test_hostile(void)
{
    static unsigned char big[300];
    memset(big, 7, sizeof big);
    memcpy(big, "P6 16000 16000 255\n", 19);
    refused("ppm_declared_size.ppm", big, sizeof big, "truncated: 16000 x 16000 pixels");
    refused("ppm_p3_declared_size.ppm", "P3 3000 3000 255\n1 2 3", 23, "truncated");
    refused("ppm_above_maxval.ppm", "P6 1 1 100\n\x01\x65\x01", 14, "above the maxval 100");
    refused("ppm_p3_not_number.ppm", "P3 1 1 100\n1 x 3 4 5", 20, "not a number");
    refused("ppm_maxval_0.ppm", "P6 1 1 0\n\x01\x02\x03", 12, "bad PPM/PGM maxval");
    refused("ppm_maxval_big.ppm", "P6 1 1 65536\n\x01\x02\x03\x01\x02\x03", 19, "bad PPM/PGM maxval");
    refused("ppm_size_0.ppm", "P6 0 1 255\n", 11, "bad PPM/PGM size");
    refused("ppm_huge.ppm", "P6 99999999999999999999 1 255\n", 30, "bad PPM/PGM size");
    refused("ppm_trailing.ppm", "P6 1 1 255\n\x01\x02\x03\x04", 15, "1 bytes after the pixels");
    refused("unknown.png", "GIF89a\x01\x00\x01\x00", 10, "unknown image format");
    refused("empty.ppm", "", 0, "an empty file");
    refused("tga_declared_size.tga", "\0\0\x02\0\0\0\0\0\0\0\0\0\xff\xff\xff\xff\x18\x20\1\2\3", 21, "truncated: 65535 x 65535");
    refused("tga_rle_declared_size.tga", "\0\0\x0a\0\0\0\0\0\0\0\0\0\xff\xff\xff\xff\x18\x20\xff\1\2\3", 22, "need at least");
    refused("tga_rle_short.tga", "\0\0\x0a\0\0\0\0\0\0\0\0\0\x08\0\x01\0\x18\x20\x81\1\2\3\x02\1\2\3\4\5\6\0\0", 31, "ends after 4 of 8 pixels");
    refused("tga_index.tga", "\0\1\x01\0\0\1\0\x18\0\0\0\0\x01\0\x01\0\x08\x20\1\2\3\x05", 22, "outside the colour map");
}

/* TGA files: a 3 x 2 image of codes, written in a given type, depth and origin. */
static const unsigned char codes[2][3][3] = {{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}, {{10, 20, 30}, {10, 20, 30}, {10, 20, 30}}};

static size_t tga_pixel(unsigned char *o, int type, int depth, const unsigned char *rgb)
{
    if ((type & 7) == 3) { o[0] = rgb[0]; if (depth == 16) o[1] = 200; return (size_t)depth / 8; }
    o[0] = rgb[2]; o[1] = rgb[1]; o[2] = rgb[0]; if (depth == 32) o[3] = 77;
    return (size_t)depth / 8;
}

static size_t write_tga(unsigned char *o, int type, int depth, int descriptor)
{
    size_t p = 18, k;
    int i;
    memset(o, 0, 18);
    o[2] = (unsigned char)type; o[12] = 3; o[14] = 2; o[16] = (unsigned char)depth; o[17] = (unsigned char)descriptor;
    if ((type & 7) == 1) {   /* a map of 4 entries from index 2: the 3 colours of row 0 and row 1's */
        o[1] = 1; o[3] = 2; o[5] = 4; o[7] = 24;
        for (i = 0; i < 3; i++) p += tga_pixel(o + p, 2, 24, codes[0][i]);
        p += tga_pixel(o + p, 2, 24, codes[1][0]);
    }
    for (k = 0; k < 6; k++) {   /* file order: rows from the bottom unless bit 5, right to left if bit 4 */
        int fy = (int)(k / 3), fx = (int)(k % 3);
        int y = descriptor & 0x20 ? fy : 1 - fy, x = descriptor & 0x10 ? 2 - fx : fx;
        if (type >= 9 && y == 1 && fx > 0) continue;   /* row 1: one run packet of 3 */
        if (type >= 9) o[p++] = y == 1 ? 0x82 : 0x00;
        if ((type & 7) == 1) o[p++] = (unsigned char)(y == 1 ? 5 : 2 + x);
        else p += tga_pixel(o + p, type, depth, codes[y][x]);
    }
    return p;
}

static void test_tga(void)
{
    static const int types[][3] = {{2, 24, 0}, {2, 32, 0x28}, {2, 24, 0x20}, {2, 24, 0x10}, {10, 24, 0}, {10, 32, 0x30},
                                   {3, 8, 0}, {11, 8, 0x20}, {3, 16, 0}, {1, 8, 0}, {9, 8, 0x20}};
    unsigned char file[256];
    float want[18];
    image im;
    img_decoded in;
    char msg[2048], name[64];
    int t, i, r;
    for (t = 0; t < (int)(sizeof types / sizeof types[0]); t++) {
        int type = types[t][0], depth = types[t][1], grey = (type & 7) == 3;
        size_t n = write_tga(file, type, depth, types[t][2]);
        for (i = 0; i < 18; i++) want[i] = codes[i / 9][i / 3 % 3][grey ? 0 : i % 3] / 255.0f;
        snprintf(name, sizeof name, "t%d_%d_%x.tga", type, depth, types[t][2]);
        r = decode(name, file, n, &im, &in, msg, sizeof msg);
        check(r == 0 && same(&im, want, 3, 2, 0) && strcmp(in.format, "TGA") == 0 && in.channels == (grey ? 1 : 3)
              && in.had_alpha == (depth == 32 || depth == 16), name, "type %d, %d bits, descriptor 0x%02x %s", type, depth,
              types[t][2], msg);
        if (!r) img_free(&im);
    }
}

/* The float formats through img_decode_file: the PFM and HDR readers, named by their bytes. */
static void test_float(void)
{
    static const unsigned char hdr[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x40\x00\x81";
    const float want[3] = {2 * 128.5f / 256, 2 * 64.5f / 256, 2 * 0.5f / 256};
    image im, src;
    img_decoded in;
    char msg[2048];
    int r;
    r = decode("h.pfm", hdr, sizeof hdr - 1, &im, &in, msg, sizeof msg);
    check(r == 0 && same(&im, want, 1, 1, 0) && strcmp(in.format, "HDR") == 0 && in.encoding == IMG_ENC_LINEAR,
          "decode_hdr_by_magic", "%s", msg);
    if (!r) img_free(&im);
    img_alloc(&src, 2, 1);
    src.px[0] = 0.5f; src.px[4] = 3.0f;
    img_write_pfm(&src, in_dir("f.pfm"));
    rename(in_dir("f.pfm"), in_dir("f.hdr"));
    r = img_decode_file(&im, in_dir("f.hdr"), &in);
    check(r == 0 && same(&im, src.px, 2, 1, 0) && strcmp(in.format, "PFM") == 0 && in.bits == 32, "decode_pfm_by_magic", NULL);
    if (!r) img_free(&im);
    img_free(&src);
    mkfifo(in_dir("fifo.ppm"), 0600);
    r = img_decode_file(&im, in_dir("fifo.ppm"), NULL);
    check(r != 0 && im.px == NULL, "decode_refuses_fifo", NULL);
}

/* img_decode_file_within: each format's file of w x h pixels decodes with a cap of w h pixels and is
 * refused, nothing decoded, with a cap of one less, and of 0 (a scene's textures share one budget:
 * when it is spent, 0 once meant no cap at all). */
static void test_cap(void)
{
    static const char *const names[] = {"c.ppm", "c.tga", "c.png", "c.pfm", "c.hdr"};
    unsigned char b[512];
    image im, src;
    size_t n;
    int k, bad = 0;
    char msg[2048], why[600] = "";
    img_alloc(&src, 3, 2);
    spit(in_dir("c.ppm"), "P6\n3 2\n255\n000111222333444555", 29);
    n = write_tga(b, 2, 24, 0), spit(in_dir("c.tga"), b, n);
    img_write_png(&src, in_dir("c.png"), 0.0f);
    img_write_pfm(&src, in_dir("c.pfm"));
    n = (size_t)sprintf((char *)b, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 3\n");
    memset(b + n, 128, 24), spit(in_dir("c.hdr"), b, n + 24);
    for (k = 0; k < 5; k++) {
        int ok, refused;
        ok = img_decode_file_within(&im, in_dir(names[k]), NULL, 6) == 0 && im.w == 3 && im.h == 2;
        if (ok) img_free(&im);
        capture_begin();
        refused = img_decode_file_within(&im, in_dir(names[k]), NULL, 5) != 0 && !im.px;
        refused = refused && img_decode_file_within(&im, in_dir(names[k]), NULL, 0) != 0 && !im.px;   /* a budget spent */
        snprintf(msg, sizeof msg, "%s", chop_newlines(capture_end()));
        if (!ok || !refused || !strstr(msg, "over the 5 allowed here")) {
            bad++;
            snprintf(why + strlen(why), sizeof why - strlen(why), "%s: %.100s; ", names[k], msg);
        }
    }
    img_free(&src);
    check(bad == 0, "decode_within_a_cap: PPM, TGA, PNG, PFM, HDR of 3 x 2 read with a cap of 6 pixels, refused with 5 and with 0", "%s", why);
}

/* oiiotool --dumpdata's integer values of an 8-bit file (its y = 0 is the top row). */
static int oiio_codes(const char *path, int *out, int w, int h)
{
    char cmd[600], line[256];
    FILE *p;
    int x, y, r, g, b, n = 0;
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s' 2>&1", path);
    p = popen(cmd, "r");
    while (p && fgets(line, sizeof line, p))
        if (sscanf(line, " Pixel (%d, %d): %d %d %d", &x, &y, &r, &g, &b) == 5 && x >= 0 && x < w && y >= 0 && y < h) {
            out[3 * (y * w + x)] = r, out[3 * (y * w + x) + 1] = g, out[3 * (y * w + x) + 2] = b;
            n++;
        }
    if (p) pclose(p);
    return n;
}

/* oiiotool writes name (its options opts) from a PFM of a gradient with flat patches; we decode
 * it to oiiotool's own integers / 255 exactly. */
static void oiio_same(const char *name, const char *opts, int w, int h)
{
    static int codes8[256 * 256 * 3];
    float *want = malloc(sizeof(float) * 3 * (size_t)w * h);
    image src, im;
    img_decoded in;
    char cmd[1200];
    int i, r, n;
    img_alloc(&src, w, h);
    for (i = 0; i < w * h * 3; i++) src.px[i] = (i / 3) % w < w / 3 ? 0.5f : (float)((i * 37) % 101) / 100.0f;
    img_write_pfm(&src, in_dir("osrc.pfm"));
    snprintf(cmd, sizeof cmd, "oiiotool '%s' %s -o '%s' > /dev/null 2>&1", in_dir("osrc.pfm"), opts, in_dir(name));
    r = system(cmd);
    n = r == 0 ? oiio_codes(in_dir(name), codes8, w, h) : 0;
    for (i = 0; i < w * h * 3; i++) want[i] = codes8[i] / 255.0f;
    r = r == 0 && n == w * h ? img_decode_file(&im, in_dir(name), &in) : 1;
    check(r == 0 && same(&im, want, w, h, 0), name, "%d x %d, oiiotool %s: %d pixels dumped", w, h, opts, n);
    if (r == 0) img_free(&im);
    img_free(&src);
    free(want);
}

static void test_oiiotool(void)
{
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) {
        printf("SKIP decode_oiiotool: no oiiotool\n");
        return;
    }
    oiio_same("oiio_rle.tga", "-d uint8 --compression rle", 67, 19);
    oiio_same("oiio_raw.tga", "-d uint8", 31, 7);
    oiio_same("oiio.ppm", "-d uint8", 13, 5);
}

int main(void)
{
    scratch_begin("test_decode");
    test_ppm();
    test_hostile();
    test_tga();
    test_float();
    test_cap();
    test_oiiotool();
    scratch_end();
    return check_summary();
}
