/* test_png.c — the PNG decoder and its inflate (image/decode.h, image/inflate.h) on files written
 * by an independent encoder, Python's zlib (tests/png_cases.py): the 5 colour types at each bit
 * depth PNG allows, plain and Adam7, every filter, stored, fixed and dynamic deflate blocks, each
 * decoded to the integers written / maxval exactly; hostile files refused with their reason; and,
 * when installed, oiiotool's own decoding of those files and of PNGs oiiotool writes (8 and 16
 * bits, RGB, RGBA, grey) equal to ours. */
#include "image/image.h"
#include "image/decode.h"
#include "check.h"
#include "scratch.h"
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

/* Decodes path with stderr captured into msg. */
static int decode(const char *path, image *im, img_decoded *info, char *msg, size_t size)
{
    int rc;
    capture_begin();
    rc = img_decode_file(im, path, info);
    snprintf(msg, size, "%s", chop_newlines(capture_end()));
    return rc;
}

/* The expected integers of NAME.txt against the decoded image: the number of differing values,
 * or -1 when the file or the size is wrong. */
static int compare_txt(const char *txt, const image *im)
{
    FILE *f = fopen(txt, "r");
    int w, h, maxval, i, v, bad = 0;
    if (!f || fscanf(f, "%d %d %d", &w, &h, &maxval) != 3 || w != im->w || h != im->h) {
        if (f) fclose(f);
        return -1;
    }
    for (i = 0; i < w * h * 3; i++) {
        if (fscanf(f, "%d", &v) != 1) { bad = -1; break; }
        if (im->px[i] != (float)v / (float)maxval) bad++;
    }
    fclose(f);
    return bad;
}

static void test_cases(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    char msg[600], name[300], failed[1024] = "";
    int n = 0, bad = 0, types = 0;
    while (d && (e = readdir(d))) {
        image im;
        img_decoded in;
        size_t len = strlen(e->d_name);
        int r, diff;
        if (e->d_name[0] != 'c' || len < 5 || strcmp(e->d_name + len - 4, ".png") != 0) continue;
        snprintf(name, sizeof name, "%s", in_dir(e->d_name));
        r = decode(name, &im, &in, msg, sizeof msg);
        strcpy(name + strlen(name) - 4, ".txt");
        diff = r == 0 ? compare_txt(name, &im) : -1;
        if (r == 0 && (strcmp(in.format, "PNG") != 0 || in.encoding != IMG_ENC_INTEGER)) diff = -1;
        if (diff != 0) {
            bad++;
            if (strlen(failed) < 900) snprintf(failed + strlen(failed), sizeof failed - strlen(failed), " %s (%d %s)", e->d_name, diff, msg);
        }
        if (r == 0) img_free(&im);
        types |= 1 << (e->d_name[1] - '0');
        n++;
    }
    if (d) closedir(d);
    check(n == 90 && bad == 0 && types == (1 | 4 | 8 | 16 | 64), "png_every_type_depth_filter_interlace",
          "%d files (5 colour types, 15 type and depth pairs, plain and Adam7, 3 sizes, zlib levels 0, 1, 9), %d wrong:%s", n, bad, failed);
}

static void refused(const char *what, const char *want)
{
    image im = {3, 3, NULL};
    img_decoded in;
    char msg[2048], file[64];
    int r;
    snprintf(file, sizeof file, "hostile_%s.png", what);
    r = decode(in_dir(file), &im, &in, msg, sizeof msg);
    check(r != 0 && im.px == NULL && im.w == 0 && strstr(msg, want) && strstr(msg, file), file, "%s", msg);
}

static void test_hostile(void)
{
    refused("bad_crc", "its CRC does not match");
    refused("bomb", "truncated: 16000 x 16000 pixels");
    refused("huge", "PNG of 30000 x 30000 pixels");
    refused("filter_5", "unknown filter type 5");
    refused("short_data", "less data than expected");
    refused("long_data", "more data than expected");
    refused("adler", "Adler-32");
    refused("truncated_idat", "truncated");
    refused("no_plte", "without a PLTE chunk");
    refused("index_past_plte", "palette index past the end");
    refused("depth_3", "IHDR");
    refused("rgb_4bit", "IHDR");
    refused("critical", "unknown critical chunk 'ABCD'");
    refused("cut", "truncated");
    refused("reserved_block", "reserved type 3");
    refused("far_distance", "before the start of the data");
}

/* oiiotool --dumpdata's integers (grey replicated; alpha dropped) of path, in image order, and
 * the code of 1.0 in its data type (it reads a 1-, 2- or 4-bit PNG as 8 bits). */
static int oiio_ints(const char *path, int *out, int w, int h, float *maxval)
{
    char cmd[600], line[512];
    FILE *p;
    int n = 0;
    snprintf(cmd, sizeof cmd, "oiiotool --iconfig oiio:UnassociatedAlpha 1 --dumpdata '%s' 2>&1", path);
    p = popen(cmd, "r");
    while (p && fgets(line, sizeof line, p)) {
        int x, y, v[4], k = 0, used;
        char *s = strstr(line, "):");
        if (strstr(line, " uint8 ")) *maxval = 255.0f;
        if (strstr(line, " uint16 ")) *maxval = 65535.0f;
        if (!s || sscanf(line, " Pixel (%d, %d)", &x, &y) != 2 || x < 0 || x >= w || y < 0 || y >= h) continue;
        for (s += 2; k < 4 && sscanf(s, " %d%n", &v[k], &used) == 1; k++) s += used;
        if (k < 1) continue;
        out[3 * (y * w + x)] = v[0];
        out[3 * (y * w + x) + 1] = k >= 3 ? v[1] : v[0];
        out[3 * (y * w + x) + 2] = k >= 3 ? v[2] : v[0];
        n++;
    }
    if (p) pclose(p);
    return n;
}

/* Our decoding of path equals oiiotool's integers / maxval. */
static int same_as_oiio(const char *path, int w, int h, char *why, size_t size)
{
    static int ints[64 * 64 * 3];
    image im;
    img_decoded in;
    char msg[2048];
    float maxval = 0.0f;
    int i, bad = 0, n = oiio_ints(path, ints, w, h, &maxval);
    if (n != w * h || decode(path, &im, &in, msg, sizeof msg)) {
        snprintf(why, size, "%s: %d pixels from oiiotool; %s", path, n, msg);
        return 0;
    }
    for (i = 0; i < w * h * 3; i++)
        if (im.px[i] != (float)ints[i] / maxval) bad++;
    img_free(&im);
    if (bad) snprintf(why, size, "%s: %d values differ", path, bad);
    return bad == 0;
}

static void test_oiiotool(void)
{
    static const char *const python_files[] = {"c3_d4_i1_13x11.png", "c3_d8_i0_33x3.png", "c4_d8_i1_13x11.png", "c4_d16_i0_33x3.png",
                                               "c0_d1_i1_13x11.png", "c0_d16_i1_13x11.png", "c2_d16_i1_13x11.png", "c6_d8_i1_13x11.png"};
    static const char *const writes[] = {"-d uint8", "-d uint16", "-d uint8 --ch R,G,B,A=0.5", "-d uint16 --ch R,G,B,A=0.25",
                                         "-d uint8 --ch R", "-d uint16 --ch R"};
    char why[2400] = "", cmd[1200], name[64];
    image src;
    int i, ok = 1;
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) {
        printf("SKIP png_oiiotool: no oiiotool\n");
        return;
    }
    for (i = 0; ok && i < (int)(sizeof python_files / sizeof python_files[0]); i++) {
        int w = 0, h = 0;
        sscanf(strrchr(python_files[i], '_') + 1, "%dx%d", &w, &h);
        ok = same_as_oiio(in_dir(python_files[i]), w, h, why, sizeof why);
    }
    check(ok, "png_palette_grey_alpha_16bit_interlaced_as_oiiotool", "%s", why);
    img_alloc(&src, 61, 23);
    for (i = 0; i < 61 * 23 * 3; i++) src.px[i] = (i / 3) % 61 < 20 ? 0.5f : (float)((i * 53) % 997) / 996.0f;
    img_write_pfm(&src, in_dir("osrc.pfm"));
    img_free(&src);
    for (i = 0, ok = 1; ok && i < (int)(sizeof writes / sizeof writes[0]); i++) {
        snprintf(name, sizeof name, "oiio%d.png", i);
        snprintf(cmd, sizeof cmd, "oiiotool '%s' %s -o '%s' > /dev/null 2>&1", in_dir("osrc.pfm"), writes[i], in_dir(name));
        ok = system(cmd) == 0 && same_as_oiio(in_dir(name), 61, 23, why, sizeof why);
        if (!ok && !why[0]) snprintf(why, sizeof why, "oiiotool %s failed", writes[i]);
    }
    check(ok, "png_written_by_oiiotool", "8 and 16 bits, RGB, RGBA, grey: %s", ok ? "equal" : why);
}

int main(void)
{
    char cmd[600];
    scratch_begin("test_png");
    snprintf(cmd, sizeof cmd, "python3 tests/png_cases.py '%s'", scratch_dir);
    if (system("command -v python3 >/dev/null 2>&1") != 0) printf("SKIP png_cases: no python3\n");
    else if (!check(system(cmd) == 0, "png_cases_written", "python3 tests/png_cases.py")) {
        scratch_end();
        return check_summary();
    } else {
        test_cases();
        test_hostile();
        test_oiiotool();
    }
    scratch_end();
    return check_summary();
}
