/* test_font.c — the label font: every printable ASCII character has a glyph of its own, the table
 * is well formed, and drawing puts ink where the text is and nowhere else. */
#include <string.h>
#include "check.h"
#include "image/font.h"

static void glyph_bits(int c, char *out)
{
    int x, y;
    for (y = 0; y < FONT_H; y++)
        for (x = 0; x < FONT_W; x++) out[y * FONT_W + x] = (char)font_pixel(c, x, y);
}

int main(void)
{
    char g[95][FONT_W * FONT_H];
    int c, d, x, y, blank = -1, dup_a = -1, dup_b = -1, ink, outside = 0, below = 0;
    const float white[3] = {1.0f, 1.0f, 1.0f};
    image im;
    d = font_table_check();
    check(d == 0, "font: every glyph row is 5 characters of '.' and '#'", d ? "first bad glyph: code %d" : NULL, d);
    for (c = 32; c <= 126; c++) {
        glyph_bits(c, g[c - 32]);
        for (ink = 0, d = 0; d < FONT_W * FONT_H; d++) ink += g[c - 32][d];
        if ((c == ' ') != (ink == 0) && blank < 0) blank = c;
    }
    check(blank < 0, "font: space is blank and each of the 94 other printable characters has ink", blank >= 0 ? "first wrong: code %d" : NULL, blank);
    for (c = 0; c < 95; c++)
        for (d = c + 1; d < 95; d++)
            if (!memcmp(g[c], g[d], sizeof g[c]) && dup_a < 0) { dup_a = c + 32; dup_b = d + 32; }
    check(dup_a < 0, "font: the 95 printable glyphs are pairwise different", dup_a >= 0 ? "'%c' and '%c' are the same" : NULL, dup_a, dup_b);
    for (y = 7; y < FONT_H; y++)
        for (x = 0; x < FONT_W; x++) below += font_pixel('g', x, y) + font_pixel('y', x, y) - font_pixel('a', x, y);
    check(below > 0, "font: g and y descend below the baseline, a does not", "%d", below);
    check(font_pixel(1, 2, 6) == font_pixel('?', 2, 6) && font_pixel(200, 1, 0) == font_pixel('?', 1, 0),
          "font: characters outside 32..126 are drawn as '?'", NULL);
    check(font_text_width("abc", 2) == (3 * FONT_ADVANCE - 1) * 2 && font_text_width("", 1) == 0,
          "font: text width", "%d", font_text_width("abc", 2));
    /* "Hi" at scale 2 at (3, 4) in a 40x30 image: ink inside its box only, the same count as the glyphs */
    if (img_alloc(&im, 40, 30)) return 1;
    font_draw(&im, 3, 4, "Hi", 2, white);
    for (ink = 0, y = 0; y < im.h; y++)
        for (x = 0; x < im.w; x++) {
            int on = im.px[3 * (y * im.w + x)] > 0.5f;
            int inside = x >= 3 && x < 3 + font_text_width("Hi", 2) && y >= 4 && y < 4 + FONT_H * 2;
            ink += on;
            outside += on && !inside;
        }
    for (d = 0, y = 0; y < FONT_H; y++)
        for (x = 0; x < FONT_W; x++) d += 4 * (font_pixel('H', x, y) + font_pixel('i', x, y));
    check(ink == d && outside == 0, "font: drawing 'Hi' at scale 2 inks its glyphs' pixels, 4 each, inside its box",
          "%d inked, %d expected, %d outside", ink, d, outside);
    font_draw(&im, -7, 25, "clipped", 3, white);   /* partly outside: must not write out of bounds */
    img_free(&im);
    return check_summary();
}
