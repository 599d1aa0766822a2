/* test_html_page.c — image/html_page.c without a browser: html_escape; a page holds the CSP, the
 * escaped title, the settings, one data block per image and variance, the embedded script and no
 * http(s) URL; images of different sizes are refused naming both, and leave no file.
 *   test_html_page DIR   also writes, for tests/test_viewer.sh, DIR/marks.html: a page of one 2048x1024
 *   image (values from 1e-3 to 1e3) with the marks, the link, HTML before and after the viewer. */
#include "check.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "image/html_page.h"

/* A w x h image with smoothly varying, wide-ranging values (not constant: sorting and drawing real work). */
static int pattern(image *im, int w, int h)
{
    long i;
    if (img_alloc(im, w, h)) return 1;
    for (i = 0; i < 3L * w * h; i++) {
        long p = i / 3, x = p % w, y = p / w;
        im->px[i] = (float)pow(10.0, 3.0 * sin(0.01 * (double)x + (double)(i % 3)) * cos(0.013 * (double)y));
    }
    return 0;
}

/* The whole file as a string, to free; NULL if unreadable. */
static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *text;
    if (!f || fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) { if (f) fclose(f); return NULL; }
    text = malloc((size_t)n + 1);
    if (text && fread(text, 1, (size_t)n, f) != (size_t)n) { free(text); text = NULL; }
    if (text) text[n] = 0;
    fclose(f);
    return text;
}

static int count(const char *text, const char *what)
{
    int n = 0;
    for (; (text = strstr(text, what)); text++) n++;
    return n;
}

/* The page of two images with a variance, a reference, marks, a link (full), or of the first image
 * alone with the marks and the link; then the checks on its text. */
static void page_checks(const char *path, image *a, image *b, int full)
{
    html_image im[2] = {{"alice.pfm", NULL, NULL, "alice.html"}, {"bob.pfm", NULL, NULL, NULL}}, ref = {"ref.pfm", NULL, NULL, NULL};
    html_mark marks[3] = {{4, 4, 16, 8, "too bright: +4.2 sigma"}, {30, 20, 10, 10, "too dark <b>"},
                          {2040, 1016, 8, 8, "too bright in the bottom-right corner: +9.9 sigma, +3.1% in red"}};
    static const char svg[] = "<svg xmlns='http://www.w3.org/2000/svg' width='4' height='3'><rect width='4' height='3' fill='red'/></svg>";
    char *uri = html_data_uri("image/svg+xml", svg, strlen(svg)), before[400], *text;
    html_page p = {"grade: alice & bob </script>", NULL, 2, NULL, NULL, 0, NULL, 2, before, "<p id=\"notes\">notes</p>", 0};
    snprintf(before, sizeof before, "<p id=\"verdict\">verdict <img id=\"data-image\" alt=\"\" src=\"%s\"></p>", uri ? uri : "");
    free(uri);
    im[0].img = a; im[0].var = b; im[1].img = b; ref.img = a;
    p.images = im; p.ref = full ? &ref : NULL; p.marks = marks;
    if (!full) p.nimages = 1, p.nmarks = 3;   /* the browser's 2048x1024 page: a mark in its corner too */
    if (!full) p.max_bytes = 1000;           /* ... and compact: RGBE in base 85, the variance left out */
    check(html_page_write(path, &p) == 0, "html_page: a page of two images, a reference, marks written", NULL);
    text = read_all(path);
    if (!check(text != NULL, "html_page: the page can be read back", NULL)) return;
    check(strstr(text, "Content-Security-Policy\" content=\"default-src 'none';") != NULL, "html_page: the CSP forbids every request", NULL);
    check(strstr(text, "<title>grade: alice &amp; bob &lt;/script&gt;</title>") != NULL, "html_page: the title escaped", NULL);
    check(count(text, "</script>") == (full ? 6 : 3), full ? "html_page: settings, 3 images, 1 variance, the script: 6 script blocks"
          : "html_page: settings, 1 image, the script: 3 script blocks", "%d", count(text, "</script>"));
    check(!strstr(text, "http://") && !strstr(text, "https://"), "html_page: no http(s) URL in the page", NULL);
    check(strstr(text, "\"label\":\"too dark \\u003cb\\u003e\"") != NULL, "html_page: a mark's label escaped in the JSON", NULL);
    check(strstr(text, "window.pathlabViewer") != NULL, "html_page: the viewer's script embedded", NULL);
    check(count(text, full ? "\"enc\":\"half\"" : "\"enc\":\"rgbe85\"") == (full ? 3 : 1) && (full || !strstr(text, "id=\"pathlab-sd-")),
          full ? "html_page: half floats within max_bytes" : "html_page: compact beyond max_bytes: RGBE in base 85, no variance", NULL);
    free(text);
}

int main(int argc, char **argv)
{
    image a, b, c, big;
    char *e = html_escape("a<b & \"c\" 'd'>"), dir[] = "/tmp/pathlab_html_XXXXXX", path[4200];
    html_image one[2] = {{"a.pfm", NULL, NULL, NULL}, {"c.pfm", NULL, NULL, NULL}};
    html_page p = {"t", NULL, 2, NULL, NULL, 0, NULL, 0, NULL, NULL, 0};
    check(e && !strcmp(e, "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;"), "html_escape: & < > \" ' escaped", "%s", e ? e : "NULL");
    free(e);
    e = html_data_uri("image/png", "abcab", 5);
    check(e && !strcmp(e, "data:image/png;base64,YWJjYWI="), "html_data_uri: base64 with its padding", "%s", e ? e : "NULL");
    free(e);
    if (pattern(&a, 64, 48) || pattern(&b, 64, 48) || pattern(&c, 48, 64) || !mkdtemp(dir)) return 1;
    snprintf(path, sizeof path, "%s/marks.html", dir);
    page_checks(path, &a, &b, 1);
    remove(path);
    one[0].img = &a; one[1].img = &c; p.images = one;
    snprintf(path, sizeof path, "%s/sizes.html", dir);
    fflush(stdout);
    check(html_page_write(path, &p) != 0 && access(path, F_OK) != 0, "html_page: images of two sizes refused, no file left", NULL);
    rmdir(dir);
    if (argc > 1) {   /* the browser's page: one 2048x1024 image with the marks and the link */
        snprintf(path, sizeof path, "%s/marks.html", argv[1]);
        if (pattern(&big, 2048, 1024)) return 1;
        page_checks(path, &big, &big, 0);
        img_free(&big);
    }
    img_free(&a); img_free(&b); img_free(&c);
    return check_summary();
}
