/* test_mosaic.c — the mosaic's layout: its size from the panels and the labels' lines, small
 * panels magnified 4x with their gain, background between panels, a long label wrapped onto three
 * lines that makes its row's band taller, and wide panels labelled at twice the text size. */
#include "check.h"
#include "image/font.h"
#include "image/mosaic.h"

/* A w x h image whose pixel (x, y) has red x, green y and blue c. */
static int pattern(image *im, int w, int h, float c)
{
    int x, y;
    if (img_alloc(im, w, h)) return 1;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            im->px[3 * (y * w + x)] = (float)x;
            im->px[3 * (y * w + x) + 1] = (float)y;
            im->px[3 * (y * w + x) + 2] = c;
        }
    return 0;
}

static const float *pixel(const image *m, int x, int y) { return m->px + 3L * (y * m->w + x); }

/* White pixels of m in rows y0..y1-1, columns x0..x1-1. */
static int ink(const image *m, int x0, int x1, int y0, int y1)
{
    int x, y, n = 0;
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++) n += pixel(m, x, y)[0] == 1.0f && pixel(m, x, y)[2] == 1.0f;
    return n;
}

int main(void)
{
    image im[3], wide, m;
    mosaic_panel p[6];
    const float *a, *b;
    int i, band;
    for (i = 0; i < 3; i++)
        if (pattern(&im[i], 32, 32, (float)i + 0.25f)) return 1;   /* blue never 1, the ink's */
    for (i = 0; i < 6; i++) {
        p[i].im = &im[i % 3];
        p[i].label = i < 3 ? "render" : "error";
        p[i].gain = i < 3 ? 2.0f : 1.0f;
    }
    /* 32x32 panels are magnified 4x to 128; bands of one line: 2 + FONT_LINE = 13 pixels */
    if (mosaic_make(&m, p, 2, 3)) return 1;
    check(m.w == 4 + 3 * (128 + 4) && m.h == 4 + 2 * (13 + 128 + 4), "mosaic: 2 x 3 panels of 32x32 make 400x294", "%dx%d", m.w, m.h);
    a = pixel(&m, 4 + 132 + 4 * 5 + 3, 4 + 13 + 4 * 7 + 1);            /* panel 1 of row 0, pixel (5, 7) */
    b = pixel(&m, 4 + 2 * 132 + 4 * 9, 4 + 13 + 128 + 4 + 13 + 4 * 2);  /* panel 2 of row 1, pixel (9, 2) */
    check(a[0] == 10.0f && a[1] == 14.0f && a[2] == 2.5f && b[0] == 9.0f && b[1] == 2.0f && b[2] == 2.25f,
          "mosaic: each pixel a 4x4 square, times the panel's gain", "(%g %g %g) (%g %g %g)", a[0], a[1], a[2], b[0], b[1], b[2]);
    a = pixel(&m, 133, 100);
    check(a[0] < 0.02f && a[0] == a[1] && a[2] > a[0], "mosaic: background between the panels", "%g %g %g", a[0], a[1], a[2]);
    check(ink(&m, 4, 132, 4, 17) > 10 && ink(&m, 4, 132, 17, 145) == 0, "mosaic: the label is drawn in the band, not over the panel", NULL);
    img_free(&m);
    /* a label of three lines (21 characters each at 128 pixels) makes the band of its row 2 + 3 x 11 */
    p[4].label = "a long label that wraps over three lines of the band and is cut short there";
    if (mosaic_make(&m, p, 2, 3)) return 1;
    band = 2 + 3 * FONT_LINE;
    check(m.h == 4 + 13 + 128 + 4 + band + 128 + 4, "mosaic: a three-line label makes its row's band taller", "height %d", m.h);
    check(ink(&m, 136, 264, 149 + 2 + 2 * FONT_LINE, 149 + band) > 10 && ink(&m, 136, 264, 149 + band, 149 + band + 128) == 0,
          "mosaic: its third line is drawn, above its panel", NULL);
    img_free(&m);
    /* panels 400 wide or more: no magnification, text twice as large */
    if (pattern(&wide, 400, 10, 0.5f)) return 1;
    p[0].im = &wide;
    p[0].label = "wide";
    if (mosaic_make(&m, p, 1, 1)) return 1;
    check(m.w == 408 && m.h == 4 + 2 + 2 * FONT_LINE + 10 + 4, "mosaic: a 400x10 panel is not magnified, its label twice as large",
          "%dx%d", m.w, m.h);
    img_free(&m);
    img_free(&wide);
    for (i = 0; i < 3; i++) img_free(&im[i]);
    return check_summary();
}
