/* test_image.c — PFM and PPM files: exact round trips, byte layout and orientation, foreign
 * byte orders and greyscale, hostile inputs, the sRGB curve, atomic writes, and (when installed)
 * agreement with OpenImageIO's oiiotool, an independent PFM reader. Works in a fresh /tmp folder. */
#include "image/image.h"
#include "image/radiance.h"
#include "check.h"
#include "scratch.h"
#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Names in scratch_dir containing ".tmp." (leftover temporaries). */
static int count_temporaries(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    int n = 0;
    if (!d) return -1;
    while ((e = readdir(d)))
        if (strstr(e->d_name, ".tmp.")) n++;
    closedir(d);
    return n;
}

static void put_f32_big(unsigned char *b, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    b[0] = (unsigned char)(u >> 24); b[1] = (unsigned char)(u >> 16);
    b[2] = (unsigned char)(u >> 8);  b[3] = (unsigned char)u;
}
static void put_f32_little(unsigned char *b, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    b[3] = (unsigned char)(u >> 24); b[2] = (unsigned char)(u >> 16);
    b[1] = (unsigned char)(u >> 8);  b[0] = (unsigned char)u;
}

/* Writes a header then n floats in the given byte order. */
static void build_pfm(const char *path, const char *header, const float *v, int n, int big)
{
    size_t hl = strlen(header);
    unsigned char *b = malloc(hl + 4 * (size_t)n);
    int i;
    memcpy(b, header, hl);
    for (i = 0; i < n; i++) (big ? put_f32_big : put_f32_little)(b + hl + 4 * i, v[i]);
    spit(path, b, hl + 4 * (size_t)n);
    free(b);
}

static void test_roundtrip(void)
{
    static const float special[] = { 0.0f, -0.0f, 1e-45f, 1.17549435e-38f, 3.4028235e38f, -3.4028235e38f,
                                     1e30f, -1e-30f, 1.0f, -1.0f, 0.5f, INFINITY, -INFINITY };
    image a, b;
    size_t i, n;
    int ok;
    img_alloc(&a, 37, 23);
    n = (size_t)a.w * a.h * 3;
    for (i = 0; i < n; i++) {
        if (i < sizeof special / sizeof special[0]) a.px[i] = special[i];
        else if (i % 3 == 0) { uint32_t u = rng(); memcpy(&a.px[i], &u, 4); }  /* any bit pattern, NaNs too */
        else a.px[i] = (float)(rng() % 2000001) / 1000.0f - 1000.0f;
    }
    ok = img_write(&a, in_dir("round.pfm"), 3.0f) == 0 && img_read_pfm(&b, in_dir("round.pfm")) == 0;
    check(ok && b.w == 37 && b.h == 23 && memcmp(a.px, b.px, n * sizeof(float)) == 0, "pfm_roundtrip_exact_bits",
          "%zu floats incl. 0, -0, denormals, FLT_MAX, inf and random bit patterns", n);
    if (ok) img_free(&b);
    img_free(&a);
}

static void test_layout(void)
{
    image a;
    unsigned char *bytes;
    const char *hdr = "PF\n2 3\n-1.0\n";
    size_t n, hl = strlen(hdr);
    int x, y, c, ok = 1;
    img_alloc(&a, 2, 3);
    for (y = 0; y < 3; y++)
        for (x = 0; x < 2; x++)
            for (c = 0; c < 3; c++) a.px[(y * 2 + x) * 3 + c] = (float)(100 * y + 10 * x + c);
    img_write_pfm(&a, in_dir("layout.pfm"));
    bytes = slurp(in_dir("layout.pfm"), &n);
    check(bytes && n == hl + 2 * 3 * 12 && memcmp(bytes, hdr, hl) == 0, "pfm_header_bytes",
          "\"PF\\n2 3\\n-1.0\\n\" then 72 bytes");
    /* The file's k-th row is our row h-1-k: the top row comes last. */
    for (y = 0; bytes && n == hl + 72 && y < 3; y++)
        for (x = 0; x < 2; x++)
            for (c = 0; c < 3; c++) {
                unsigned char want[4];
                put_f32_little(want, (float)(100 * (2 - y) + 10 * x + c));
                if (memcmp(bytes + hl + (y * 2 + x) * 12 + c * 4, want, 4) != 0) ok = 0;
            }
    check(ok && bytes && n == hl + 72, "pfm_bottom_row_first", "top row written last");
    check(bytes && n == hl + 72 && bytes[hl] == 0x00 && bytes[hl + 1] == 0x00 && bytes[hl + 2] == 0x48
              && bytes[hl + 3] == 0x43,
          "pfm_little_endian_bytes", "first float 200.0f (bottom left red) = 00 00 48 43");
    free(bytes);
    img_free(&a);
}

static void test_foreign(void)
{
    /* Big-endian RGB, 2 x 2, bottom row first, with a magnitude-2 scale we must ignore. */
    float v[12] = { 1, 2, 3, 4, 5, 6, /* bottom */ 7, 8, 9, 10, 11, 12 /* top */ };
    float g[6] = { 0.25f, -1.5f, 3e10f, /* bottom */ 7, 8, 9 /* top */ };
    image im;
    int ok;
    build_pfm(in_dir("big.pfm"), "PF\n2 2\n2.0\n", v, 12, 1);
    ok = img_read_pfm(&im, in_dir("big.pfm")) == 0;
    check(ok && im.w == 2 && im.h == 2 && im.px[0] == 7 && im.px[5] == 12 && im.px[6] == 1 && im.px[11] == 6,
          "pfm_read_big_endian", "positive scale, values and orientation");
    if (ok) img_free(&im);
    build_pfm(in_dir("grey.pfm"), "Pf\n3 2\n-1\n", g, 6, 0);
    ok = img_read_pfm(&im, in_dir("grey.pfm")) == 0;
    check(ok && im.w == 3 && im.h == 2 && im.px[0] == 7 && im.px[1] == 7 && im.px[2] == 7 && im.px[8] == 9
              && im.px[9] == 0.25f && im.px[10] == 0.25f && im.px[11] == 0.25f && im.px[14] == -1.5f
              && im.px[17] == 3e10f,
          "pfm_read_greyscale", "Pf replicated into R, G, B");
    if (ok) img_free(&im);
    build_pfm(in_dir("grey-big.pfm"), "Pf\n1 1\n1.0\n", g, 1, 1);
    ok = img_read_pfm(&im, in_dir("grey-big.pfm")) == 0;
    check(ok && im.px[0] == 0.25f && im.px[2] == 0.25f, "pfm_read_greyscale_big_endian", NULL);
    if (ok) img_free(&im);
    build_pfm(in_dir("spaced.pfm"), "PF \t\n2\n 2\t\n-1.0\n", v, 12, 0);
    ok = img_read_pfm(&im, in_dir("spaced.pfm")) == 0;
    check(ok && im.px[0] == 7 && im.px[11] == 6, "pfm_read_loose_whitespace",
          "spaces and tabs, width and height on two lines");
    if (ok) img_free(&im);
}

/* Reading path must fail, leave an empty image, and print a message containing want. */
static void expect_read_error(const char *name, const char *path, const char *want)
{
    image im = { 7, 7, (float *)&im };
    const char *msg;
    int r;
    capture_begin();
    r = img_read_pfm(&im, path);
    msg = capture_end();
    check(r != 0 && im.px == NULL && im.w == 0 && strstr(msg, want) && strstr(msg, path), name,
          "message: %.*s", (int)strcspn(msg, "\n"), msg);
}

static void test_bad_files(void)
{
    float v[12] = { 0 };
    unsigned char junk[300];
    unsigned char *good;
    size_t i, n;
    int k;
    expect_read_error("pfm_missing_file", in_dir("nope.pfm"), "cannot open: No such file");
    spit(in_dir("empty.pfm"), "", 0);
    expect_read_error("pfm_empty_file", in_dir("empty.pfm"), "not a PFM file");
    spit(in_dir("p6.pfm"), "P6\n1 1\n255\nabc", 14);
    expect_read_error("pfm_wrong_magic", in_dir("p6.pfm"), "not a PFM file");
    spit(in_dir("pfx.pfm"), "PFX\n1 1\n-1\nabcdefghijkl", 23);
    expect_read_error("pfm_magic_with_suffix", in_dir("pfx.pfm"), "not a PFM file");
    spit(in_dir("hdr.pfm"), "PF\n2 ", 5);
    expect_read_error("pfm_truncated_header", in_dir("hdr.pfm"), "truncated or malformed PFM header");
    build_pfm(in_dir("zero.pfm"), "PF\n0 2\n-1\n", v, 0, 0);
    expect_read_error("pfm_zero_width", in_dir("zero.pfm"), "bad dimensions 0 x 2");
    build_pfm(in_dir("neg.pfm"), "PF\n2 -2\n-1\n", v, 12, 0);
    expect_read_error("pfm_negative_height", in_dir("neg.pfm"), "bad dimensions 2 x -2");
    build_pfm(in_dir("huge.pfm"), "PF\n99999999999999999999 2\n-1\n", v, 12, 0);
    expect_read_error("pfm_width_overflows_long", in_dir("huge.pfm"), "bad dimensions");
    build_pfm(in_dir("area.pfm"), "PF\n1000000 1000000\n-1\n", v, 12, 0);
    expect_read_error("pfm_area_too_large", in_dir("area.pfm"), "bad dimensions");
    build_pfm(in_dir("text.pfm"), "PF\n2x 2\n-1\n", v, 12, 0);
    expect_read_error("pfm_non_numeric_width", in_dir("text.pfm"), "bad dimensions");
    build_pfm(in_dir("scale0.pfm"), "PF\n2 2\n0.0\n", v, 12, 0);
    expect_read_error("pfm_zero_scale", in_dir("scale0.pfm"), "bad scale '0.0'");
    build_pfm(in_dir("scalenan.pfm"), "PF\n2 2\nnan\n", v, 12, 0);
    expect_read_error("pfm_nan_scale", in_dir("scalenan.pfm"), "bad scale");
    build_pfm(in_dir("short.pfm"), "PF\n2 2\n-1.0\n", v, 5, 0);
    expect_read_error("pfm_truncated_pixels", in_dir("short.pfm"),
                      "truncated: expected 2 x 2 x 3 x 4 = 48 bytes of pixels (width x height x channels x 4), "
                      "found 20: 28 bytes missing (2.33 pixels)");
    build_pfm(in_dir("shortgrey.pfm"), "Pf\n4 4\n-1.0\n", v, 3, 0);
    expect_read_error("pfm_truncated_greyscale", in_dir("shortgrey.pfm"),
                      "4 x 4 x 1 x 4 = 64 bytes of pixels (width x height x channels x 4), found 12: 52 bytes missing (13 pixels)");
    build_pfm(in_dir("big1.pfm"), "PF\n1000 1000\n-1.0\n", v, 12, 0);
    expect_read_error("pfm_lying_header_no_big_alloc", in_dir("big1.pfm"),
                      "1000 x 1000 x 3 x 4 = 12000000 bytes of pixels (width x height x channels x 4), found 48");
    expect_read_error("pfm_directory", scratch_dir, "cannot open: a folder, not a file");

    /* Fuzz: random bytes, and a valid file with random bytes changed or cut short. Success is
     * allowed; a crash or a sanitizer report is not, and a failure must leave an empty image. */
    build_pfm(in_dir("good.pfm"), "PF\n3 2\n-1.0\n", v, 12, 0);
    good = slurp(in_dir("good.pfm"), &n);
    for (k = 0; k < 600; k++) {
        image im;
        size_t len;
        if (k < 200) {
            len = rng() % sizeof junk;
            for (i = 0; i < len; i++) junk[i] = (unsigned char)rng();
            if (k % 2) { junk[0] = 'P'; if (len > 1) junk[1] = k % 4 == 1 ? 'F' : 'f'; }
        } else {
            len = n < sizeof junk ? n : sizeof junk;
            memcpy(junk, good, len);
            for (i = 0; i < 1 + rng() % 3; i++) junk[rng() % 12] = (unsigned char)("0123456789 \n-.Pfe+x\0"[rng() % 21]);
            if (k % 3 == 0) len = rng() % (len + 1);
        }
        spit(in_dir("fuzz.pfm"), junk, len);
        capture_begin();
        if (img_read_pfm(&im, in_dir("fuzz.pfm")) == 0) img_free(&im);
        else if (im.px || im.w || im.h) break;
        capture_end();
    }
    if (k < 600) capture_end();
    check(k == 600, "pfm_fuzz_no_crash", "600 random and mutated files");
    free(good);
}

static void test_srgb_ppm(void)
{
    float vals[] = { 0.0f, 1.0f, 0.5f, 0.25f, NAN, -1.0f, 1e30f, INFINITY, 0.0031308f, 0.18f };
    image a;
    unsigned char *b;
    size_t n, hl = strlen("P6\n10 1\n255\n");
    int i, ok;
    float s1 = srgb_encode(0.0031308f), lo = 12.92f * 0.0031308f;
    check(fabsf(s1 - lo) < 1e-6f && fabsf(srgb_encode(0.5f) - 0.735356983f) < 1e-6f && srgb_encode(-2.0f) == 0.0f
              && srgb_encode(2.0f) == 1.0f && srgb_encode(NAN) == 0.0f && fabsf(srgb_encode(0.001f) - 0.01292f) < 1e-8f,
          "srgb_curve", "piecewise sRGB, continuous at 0.0031308, clamped, NaN -> 0");
    img_alloc(&a, 10, 1);
    for (i = 0; i < 10; i++) a.px[3 * i] = a.px[3 * i + 1] = a.px[3 * i + 2] = vals[i];
    a.px[3 * 9 + 1] = 0.0f;   /* distinct channels in the last pixel: checks channel order */
    ok = img_write(&a, in_dir("v.PPM"), 0.0f) == 0;
    b = slurp(in_dir("v.PPM"), &n);
    check(ok && b && n == hl + 30 && memcmp(b, "P6\n10 1\n255\n", hl) == 0, "ppm_header", "P6, 255, by .PPM extension");
    if (b && n == hl + 30) {
        unsigned char *p = b + hl;
        check(p[0] == 0 && p[3] == 255 && p[6] == 188 && p[9] == 137, "ppm_known_values",
              "0 -> %d, 1 -> %d, 0.5 -> %d, 0.25 -> %d", p[0], p[3], p[6], p[9]);
        check(p[12] == 0 && p[15] == 0 && p[18] == 255 && p[21] == 255, "ppm_nan_negative_huge",
              "NaN -> %d, -1 -> %d, 1e30 -> %d, inf -> %d", p[12], p[15], p[18], p[21]);
        check(p[24] == 10 && p[27] == 118 && p[28] == 0 && p[29] == 118, "ppm_rounding_and_channels",
              "0.0031308 -> %d, 0.18 -> %d (G forced to %d)", p[24], p[27], p[28]);
    }
    free(b);
    /* +1 stop doubles before the curve: 0.25 -> 0.5 -> 188, and 0.5 -> 1 -> 255. */
    ok = img_write(&a, in_dir("e.ppm"), 1.0f) == 0;
    b = slurp(in_dir("e.ppm"), &n);
    check(ok && b && n == hl + 30 && b[hl + 9] == 188 && b[hl + 6] == 255 && b[hl + 0] == 0,
          "ppm_exposure_plus_one", "0.25 at +1 stop -> %d", b && n == hl + 30 ? b[hl + 9] : -1);
    free(b);
    ok = img_write(&a, in_dir("m.ppm"), -1.0f) == 0;
    b = slurp(in_dir("m.ppm"), &n);
    check(ok && b && n == hl + 30 && b[hl + 3] == 188, "ppm_exposure_minus_one", "1 at -1 stop -> 0.5 -> 188");
    free(b);
    img_free(&a);
}

static void test_atomic(void)
{
    image a, small;
    const char *msg;
    struct stat st;
    struct rlimit old, lim;
    unsigned char *b;
    size_t n;
    int r, r2;
    img_alloc(&a, 64, 64);
    capture_begin();
    r = img_write(&a, in_dir("no/such/dir/x.pfm"), 0.0f);
    msg = capture_end();
    check(r != 0 && !exists(in_dir("no/such/dir/x.pfm")) && !exists(in_dir("no")) && strstr(msg, "no/such/dir/x.pfm")
              && strstr(msg, "No such file or directory"),
          "write_missing_directory_fails", "message: %.*s", (int)strcspn(msg, "\n"), msg);
    capture_begin();
    r = img_write(&a, in_dir("x.jpg"), 0.0f) == 0 || img_write(&a, in_dir("pfm"), 0.0f) == 0
        || img_write(&a, in_dir("x.pfm.bak"), 0.0f) == 0;
    msg = capture_end();
    check(!r && strstr(msg, "x.jpg: unknown image format (use .pfm, .ppm or .png)") && !exists(in_dir("x.jpg"))
              && !exists(in_dir("pfm")) && !exists(in_dir("x.pfm.bak")),
          "write_unknown_extension_refused", NULL);
    check(img_write(&a, in_dir("UPPER.PfM"), 0.0f) == 0 && exists(in_dir("UPPER.PfM")), "write_extension_any_case", NULL);

    /* Overwrite an existing image: the new one replaces it, with the umask's usual permissions. */
    spit(in_dir("old.pfm"), "old", 3);
    r = img_write(&a, in_dir("old.pfm"), 0.0f);
    check(r == 0 && stat(in_dir("old.pfm"), &st) == 0 && st.st_size == 14 + 64 * 64 * 12, "write_replaces_target", NULL);
    check(r == 0 && (st.st_mode & 0044) != 0, "write_not_private", "mode %o (mkstemp makes 0600)", (unsigned)(st.st_mode & 0777));

    /* A write that fails half way (file size limit, like a full disk) leaves the old file alone:
     * a 64 x 64 PFM fails in fwrite, a 20 x 20 PPM (smaller than stdio's buffer) only in fflush. */
    spit(in_dir("keep.pfm"), "keep me", 7);
    spit(in_dir("keep.ppm"), "keep me", 7);
    img_alloc(&small, 20, 20);
    getrlimit(RLIMIT_FSIZE, &old);
    lim = old;
    lim.rlim_cur = 1000;
    signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &lim);
    capture_begin();
    r = img_write(&a, in_dir("keep.pfm"), 0.0f);
    r2 = img_write(&small, in_dir("keep.ppm"), 0.0f);
    msg = capture_end();
    setrlimit(RLIMIT_FSIZE, &old);
    b = slurp(in_dir("keep.pfm"), &n);
    check(r != 0 && b && n == 7 && memcmp(b, "keep me", 7) == 0 && strstr(msg, "keep.pfm: cannot write: File too large"),
          "write_failure_keeps_old_file", "message: %.*s", (int)strcspn(msg, "\n"), msg);
    free(b);
    b = slurp(in_dir("keep.ppm"), &n);
    check(r2 != 0 && b && n == 7 && memcmp(b, "keep me", 7) == 0 && strstr(msg, "keep.ppm: cannot write: File too large"),
          "write_flush_failure_detected", "1213-byte PPM over a 1000-byte limit");
    free(b);
    img_free(&small);

    /* a folder with the output's name: refused before anything is written (sys/atomic_file.h), and
     * no temporary file is left. */
    mkdir(in_dir("adir.pfm"), 0755);
    capture_begin();
    r = img_write(&a, in_dir("adir.pfm"), 0.0f);
    msg = capture_end();
    check(r != 0 && strstr(msg, "adir.pfm: exists and is not a regular file"), "write_onto_directory_fails", "message: %.*s",
          (int)strcspn(msg, "\n"), msg);
    rmdir(in_dir("adir.pfm"));

    capture_begin();
    {
        image empty = { 0, 0, NULL };
        r = img_write(&empty, in_dir("empty-image.pfm"), 0.0f);
    }
    msg = capture_end();
    check(r != 0 && !exists(in_dir("empty-image.pfm")), "write_empty_image_refused", NULL);
    check(count_temporaries() == 0, "no_temporary_files_left", "%d found", count_temporaries());
    img_free(&a);
    check(img_alloc(&a, 0, 5) != 0 && a.px == NULL && img_alloc(&a, 1 << 21, 1) != 0
              && img_alloc(&a, 1 << 20, 1 << 20) != 0 && a.px == NULL,
          "alloc_refuses_bad_sizes", NULL);
}

/* OpenImageIO reads our file: same size, values and orientation (its y = 0 is the top row). */
static void test_oiiotool(void)
{
    image a;
    char cmd[512], line[256];
    FILE *p;
    int x, y, w = 4, h = 3, seen = 0, bad = 0;
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) {
        check(1, "oiiotool_reads_our_pfm", "skipped: no oiiotool");
        check(1, "oiiotool_reads_our_ppm", "skipped: no oiiotool");
        return;
    }
    img_alloc(&a, w, h);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            a.px[(y * w + x) * 3 + 0] = 100.0f * y + x + 0.125f;
            a.px[(y * w + x) * 3 + 1] = -0.5f * x;
            a.px[(y * w + x) * 3 + 2] = 1000.0f + y;
        }
    img_write_pfm(&a, in_dir("oiio.pfm"));
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s' 2>&1", in_dir("oiio.pfm"));
    p = popen(cmd, "r");
    while (p && fgets(line, sizeof line, p)) {
        float r, g, b;
        if (sscanf(line, " Pixel (%d, %d): %f %f %f", &x, &y, &r, &g, &b) != 5) continue;
        seen++;
        if (x < 0 || x >= w || y < 0 || y >= h || r != a.px[(y * w + x) * 3] || g != a.px[(y * w + x) * 3 + 1]
            || b != a.px[(y * w + x) * 3 + 2])
            bad++;
    }
    if (p) pclose(p);
    check(seen == w * h && bad == 0, "oiiotool_reads_our_pfm", "%d pixels, %d differ", seen, bad);

    /* The PPM: oiiotool's 8-bit values must be our bytes, in the same place (no flip in PPM). */
    for (x = 0; x < w * h * 3; x++) a.px[x] = (float)x / (float)(w * h * 3);
    img_write_ppm(&a, in_dir("oiio.ppm"), 0.0f);
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s' 2>&1", in_dir("oiio.ppm"));
    p = popen(cmd, "r");
    seen = bad = 0;
    while (p && fgets(line, sizeof line, p)) {
        int r, g, b, i;
        if (sscanf(line, " Pixel (%d, %d): %d %d %d", &x, &y, &r, &g, &b) != 5) continue;
        seen++;
        i = (y * w + x) * 3;
        if (x < 0 || x >= w || y < 0 || y >= h || r != (int)(srgb_encode(a.px[i]) * 255.0f + 0.5f)
            || g != (int)(srgb_encode(a.px[i + 1]) * 255.0f + 0.5f) || b != (int)(srgb_encode(a.px[i + 2]) * 255.0f + 0.5f))
            bad++;
    }
    if (p) pclose(p);
    check(seen == w * h && bad == 0, "oiiotool_reads_our_ppm", "%d pixels, %d differ", seen, bad);
    img_free(&a);
}

/* The one extension test of pathlab: img_extension and img_format_of. */
static void test_extension(void)
{
    check(!strcmp(img_extension("dir/out.pfm"), ".pfm") && !strcmp(img_extension("a.b/out"), "")
          && !strcmp(img_extension("out"), "") && !strcmp(img_extension("x.tar.png"), ".png") && !strcmp(img_extension("."), "."),
          "img_extension: after the last dot of the file name, dot included", NULL);
    check(img_format_of("a.pfm") == IMG_PFM && img_format_of("d/A.PFM") == IMG_PFM && img_format_of("b.Ppm") == IMG_PPM
          && img_format_of("c.png") == IMG_PNG && img_format_of("c.jpg") == IMG_UNKNOWN && img_format_of("png") == IMG_UNKNOWN
          && img_format_of("a.pfm/b") == IMG_UNKNOWN && img_format_of("a.pfmx") == IMG_UNKNOWN,
          "img_format_of: .pfm, .ppm, .png in any case; nothing else", NULL);
}

/* n values of a plausible radiance image: zeros and ordinary values with arbitrary mantissas. */
static void radiance_values(float *v, int n)
{
    int i;
    for (i = 0; i < n; i++) v[i] = i % 7 == 0 ? 0.0f : (float)(rng() % 100000) / 3000.0f;
}

/* The header's mistakes: text-mode line ends, blank and comment lines, no whitespace after the scale. */
static void test_header_mistakes(void)
{
    float v[36];
    radiance_values(v, 36);
    build_pfm(in_dir("crlf.pfm"), "PF\r\n4 3\r\n-1.0\r\n", v, 36, 0);
    expect_read_error("pfm_crlf_header", in_dir("crlf.pfm"),
                      "the header's lines end with CR LF (a file written in text mode on Windows?): PFM headers "
                      "end lines with LF only, and the data is shifted by a byte; open the file in binary mode (\"wb\")");
    build_pfm(in_dir("crlast.pfm"), "PF\n4 3\n-1.0\r\n", v, 36, 0);
    expect_read_error("pfm_cr_after_scale", in_dir("crlast.pfm"), "the header's lines end with CR LF");
    build_pfm(in_dir("crmid.pfm"), "PF\n4 3\r\n-1.0\n", v, 36, 0);
    expect_read_error("pfm_cr_after_height", in_dir("crmid.pfm"), "the header's lines end with CR LF");
    build_pfm(in_dir("blank.pfm"), "PF\n4 3\n\n-1.0\n", v, 36, 0);
    expect_read_error("pfm_blank_header_line", in_dir("blank.pfm"), "the header has a blank line");
    build_pfm(in_dir("blank2.pfm"), "PF\n \n4 3\n-1.0\n", v, 36, 0);
    expect_read_error("pfm_blank_line_with_a_space", in_dir("blank2.pfm"), "the header has a blank line");
    build_pfm(in_dir("comment.pfm"), "PF\n# written by my renderer\n4 3\n-1.0\n", v, 36, 0);
    expect_read_error("pfm_comment_in_header", in_dir("comment.pfm"), "the header has a comment ('#'): PFM headers have none");
    build_pfm(in_dir("leading.pfm"), "\nPF\n4 3\n-1.0\n", v, 36, 0);
    expect_read_error("pfm_magic_not_first", in_dir("leading.pfm"), "not a PFM file (it must begin with \"PF\" or \"Pf\")");
    v[0] = 0.0f;   /* the data starts with a 0 byte */
    build_pfm(in_dir("nolf.pfm"), "PF\n4 3\n-1.0", v, 36, 0);
    expect_read_error("pfm_no_whitespace_after_scale", in_dir("nolf.pfm"),
                      "no line feed after the scale '-1.0': the pixel data must follow the scale and exactly one "
                      "whitespace character (a line feed)");
}

/* The data's mistakes: bytes after the pixels, and a scale whose sign gives the wrong byte order. */
static void test_data_mistakes(void)
{
    float v[40], one[12] = { 1, 1, 1, 0.5f, 0.5f, 0.5f, 2, 2, 2, 0.25f, 0.25f, 0.25f };
    unsigned char junk[12 + 16 * 16 * 12];
    size_t i;
    radiance_values(v, 40);
    build_pfm(in_dir("trail.pfm"), "PF\n4 3\n-1.0\n", v, 39, 0);
    expect_read_error("pfm_trailing_bytes", in_dir("trail.pfm"),
                      "12 bytes after the pixel data: expected exactly 4 x 3 x 3 x 4 = 144 bytes (width x height x "
                      "channels x 4); a second image or a header written twice?");
    build_pfm(in_dir("trailgrey.pfm"), "Pf\n4 3\n-1\n", v, 36, 0);
    expect_read_error("pfm_trailing_bytes_greyscale", in_dir("trailgrey.pfm"),
                      "96 bytes after the pixel data: expected exactly 4 x 3 x 1 x 4 = 48 bytes");
    v[0] = 0.0f;
    build_pfm(in_dir("space.pfm"), "PF\n4 3\n-1.0 \n", v, 36, 0);
    expect_read_error("pfm_space_before_last_line_feed", in_dir("space.pfm"),
                      "1 byte after the pixel data: expected exactly 4 x 3 x 3 x 4 = 144 bytes");
    expect_read_error("pfm_space_before_last_line_feed_hint", in_dir("space.pfm"),
                      "a space before the header's last line feed? after the scale, PFM allows exactly one whitespace");
    radiance_values(v, 36);
    build_pfm(in_dir("le-said-be.pfm"), "PF\n4 3\n1.0\n", v, 36, 0);
    expect_read_error("pfm_byte_order_little_said_big", in_dir("le-said-be.pfm"),
                      "the header's scale +1.0 says big-endian, but read so the values are absurd (up to ");
    expect_read_error("pfm_byte_order_little_said_big_advice", in_dir("le-said-be.pfm"),
                      "; read little-endian they are ordinary (0 to 3");
    expect_read_error("pfm_byte_order_little_said_big_fix", in_dir("le-said-be.pfm"),
                      ": write the scale as -1.0 for little-endian data");
    build_pfm(in_dir("be-said-le.pfm"), "PF\n4 3\n-1\n", v, 36, 1);
    expect_read_error("pfm_byte_order_big_said_little", in_dir("be-said-le.pfm"),
                      "the header's scale -1 says little-endian, but read so the values are absurd");
    expect_read_error("pfm_byte_order_big_said_little_fix", in_dir("be-said-le.pfm"),
                      "read big-endian they are ordinary (0 to 3");
    build_pfm(in_dir("round-said-be.pfm"), "Pf\n4 3\n2.0\n", one, 12, 0);
    expect_read_error("pfm_byte_order_exact_values_denormal", in_dir("round-said-be.pfm"),
                      "12 of the 12 nonzero values are NaN, infinite, denormal or beyond 1e20); read little-endian "
                      "they are ordinary (0.25 to 2)");
    {   /* a firefly of 3e38 in a 3x3 image (3 values of 27) and a 1x1 image of 3e38 (big-endian, said
         * so) are radiance: "not float radiance", and for the second "write the scale as -1.0", which
         * would read -0.106 (a review, 2026-12-08) */
        float ff[27], big[3] = {3e38f, 3e38f, 3e38f};
        image im;
        int k, ok;
        for (k = 0; k < 27; k++) ff[k] = 1.0f;
        ff[12] = ff[13] = ff[14] = 3e38f;
        build_pfm(in_dir("firefly.pfm"), "PF\n3 3\n-1\n", ff, 27, 0);
        ok = img_read_pfm(&im, in_dir("firefly.pfm")) == 0;
        check(ok && im.px[12] == 3e38f && im.px[0] == 1.0f, "pfm_firefly_3x3_reads", NULL);
        if (ok) img_free(&im);
        {   /* a small big-endian image with a negative value said little-endian: read as denormals,
             * silently, once the advice to swap stopped at negatives; now the advice again */
            float sn[4] = {1.0f, -1.0f, 2.0f, 0.5f};
            build_pfm(in_dir("swapneg.pfm"), "Pf\n2 2\n-1.0\n", sn, 4, 1);
            expect_read_error("pfm_swapped_with_a_negative_value", in_dir("swapneg.pfm"), "write the scale as 1.0 for big-endian data");
        }
        {   /* a black 256x256 image holding 5 values, one of them 2e-39 (denormal), is radiance */
            static float sparse[3 * 256 * 256];
            sparse[100] = 0.2f, sparse[200] = 1.5f, sparse[300] = 2e-39f, sparse[400] = 0.7f, sparse[500] = 0.1f;
            build_pfm(in_dir("sparse.pfm"), "PF\n256 256\n-1\n", sparse, 3 * 256 * 256, 0);
            ok = img_read_pfm(&im, in_dir("sparse.pfm")) == 0;
            check(ok, "pfm_sparse_with_a_denormal_reads", NULL);
            if (ok) img_free(&im);
        }
        build_pfm(in_dir("big1.pfm"), "PF\n1 1\n1.0\n", big, 3, 1);
        ok = img_read_pfm(&im, in_dir("big1.pfm")) == 0;
        check(ok && im.px[0] == 3e38f, "pfm_1x1_big_endian_3e38_reads", NULL);
        if (ok) img_free(&im);
    }
    memcpy(junk, "PF\n16 16\n-1\n", 12);
    for (i = 12; i < sizeof junk; i++) junk[i] = (unsigned char)rng();
    spit(in_dir("random.pfm"), junk, sizeof junk);
    expect_read_error("pfm_random_data_not_radiance", in_dir("random.pfm"),
                      "the pixel data is not float radiance: read little-endian (as the header's scale -1 says), ");
}

/* img_read_pfm_info: the header's facts; and every PFM of ref/ reads, as clean radiance. */
static void test_info_and_refs(void)
{
    float g[6] = { 0.25f, 1.5f, 3e10f, 7, 8, 9 };
    img_pfm_info info = { 0, 0, 0.0, 0, 0 };
    image im;
    DIR *d;
    struct dirent *e;
    char path[300];
    int ok, n = 0, bad = 0;
    build_pfm(in_dir("info.pfm"), "Pf\n3 2\n2.5\n", g, 6, 1);
    ok = img_read_pfm_info(&im, in_dir("info.pfm"), &info) == 0;
    check(ok && info.channels == 1 && info.big_endian == 1 && info.scale == 2.5 && im.px[0] == 7,
          "pfm_info_greyscale_big_endian", "channels %d, big_endian %d, scale %g", info.channels, info.big_endian, info.scale);
    if (ok) img_free(&im);
    ok = img_read_pfm_info(&im, "ref/cornell.pfm", &info) == 0;
    check(ok && info.channels == 3 && info.big_endian == 0 && info.scale == -1.0 && im.w == 64,
          "pfm_info_colour_little_endian", "ref/cornell.pfm: channels %d, big_endian %d, scale %g",
          info.channels, info.big_endian, info.scale);
    if (ok) img_free(&im);
    d = opendir("ref");
    while (d && (e = readdir(d))) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".pfm") != 0) continue;
        snprintf(path, sizeof path, "ref/%s", e->d_name);
        n++;
        if (img_read_pfm_info(&im, path, &info) != 0 || info.channels != 3) { bad++; continue; }
        if (img_check_radiance(&im, path, 3) != 0) bad++;
        img_free(&im);
    }
    if (d) closedir(d);
    check(n >= 10 && bad == 0, "pfm_every_ref_reads", "%d files in ref/, %d refused or not clean radiance", n, bad);
}

/* img_check_radiance on an image of 0.5 with one mistake each; msg must contain want. */
static void expect_radiance(const char *name, const image *im, int max_listed, int want_rc, const char *want)
{
    const char *msg;
    int r;
    capture_begin();
    r = img_check_radiance(im, "x.pfm", max_listed);
    msg = capture_end();
    check((r != 0) == want_rc && (want ? strstr(msg, want) != NULL : msg[0] == '\0'), name,
          "returned %d; message: %.*s", r, (int)strcspn(msg, "\n"), msg);
}

static void test_radiance(void)
{
    image im;
    int i;
    img_alloc(&im, 4, 3);
    for (i = 0; i < 36; i++) im.px[i] = 0.5f;
    im.px[5] = -0.0f;
    expect_radiance("radiance_clean_silent", &im, 3, 0, NULL);
    im.px[3 * 1 + 1] = NAN;    /* x 1, y 0, green */
    im.px[3 * 4 + 0] = NAN;    /* x 0, y 1, red */
    im.px[3 * 5 + 2] = NAN;    /* x 1, y 1, blue */
    im.px[3 * 6 + 0] = NAN;    /* x 2, y 1, red */
    expect_radiance("radiance_nan_positions", &im, 3, 1,
                    "x.pfm: 4 pixel-channels are NaN, first at x 1, y 0 (green), x 0, y 1 (red), x 1, y 1 (blue), "
                    "...; y = 0 is the top row\n");
    expect_radiance("radiance_nan_all_listed", &im, 4, 1, "x 1, y 1 (blue), x 2, y 1 (red); y = 0 is the top row\n");
    im.px[3 * 11 + 2] = INFINITY;
    im.px[0] = -INFINITY;
    expect_radiance("radiance_plus_inf", &im, 3, 1, "x.pfm: 1 pixel-channel is +Inf, at x 3, y 2 (blue); y = 0 is the top row\n");
    expect_radiance("radiance_minus_inf", &im, 3, 1, "x.pfm: 1 pixel-channel is -Inf, at x 0, y 0 (red); y = 0 is the top row\n");
    expect_radiance("radiance_error_hint", &im, 3, 1, "x.pfm: radiance is a finite number >= 0 in every pixel-channel");
    for (i = 0; i < 36; i++) im.px[i] = 0.5f;
    im.px[7] = -0.25f;           /* x 2, y 0, green */
    expect_radiance("radiance_negative", &im, 3, 1, "x.pfm: 1 pixel-channel is negative (below -1e-06 x 0.5, the median |value| "
                    "rounded down to a power of 2; down to -0.25), at x 2, y 0 (green -0.25); y = 0 is the top row\n");
    im.px[7] = -6e-7f;           /* beyond 1e-6 x the median, 0.5 */
    expect_radiance("radiance_small_negative_beyond_tolerance", &im, 3, 1, "1 pixel-channel is negative");
    im.px[7] = -4e-7f;           /* within the tolerance: a warning, no error */
    expect_radiance("radiance_tiny_negative_warning", &im, 3, 0, "x.pfm: warning: 1 pixel-channel is slightly negative "
                    "(down to -4e-07, within 1e-06 x 0.5, the median |value| rounded down to a power of 2: float rounding?), "
                    "at x 2, y 0 (green -4e-07)");
    im.px[0] = 1e11f;            /* one huge value moved the mean (8e9 here), and -4e-7 with it... */
    im.px[7] = -0.25f;           /* ...so that -0.25 passed for float rounding: the median does not move */
    expect_radiance("radiance_negative_beside_a_huge_value", &im, 3, 1, "1 pixel-channel is negative (below -1e-06 x 0.5,");
    img_free(&im);
}

int main(void)
{
    scratch_begin("test_image");
    rng_seed(12345u);
    test_roundtrip();
    test_layout();
    test_foreign();
    test_bad_files();
    test_header_mistakes();
    test_data_mistakes();
    test_info_and_refs();
    test_radiance();
    test_srgb_ppm();
    test_atomic();
    test_oiiotool();
    test_extension();
    scratch_end();
    return check_summary();
}
