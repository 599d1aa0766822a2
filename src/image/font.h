/* font.h — a small bitmap font of our own for labels on images: printable ASCII (32..126), each
 * glyph 5 pixels wide and 7 tall above the baseline, plus 2 rows below it for the descenders of
 * g j p q y , _ — so a cell is 5x9, drawn with one blank column and two blank rows between cells. */
#ifndef PATHLAB_FONT_H
#define PATHLAB_FONT_H
#include "image/image.h"

#define FONT_W 5          /* glyph width */
#define FONT_H 9          /* glyph height: 7 above the baseline, 2 below */
#define FONT_ADVANCE 6    /* from one character to the next */
#define FONT_LINE 11      /* from one line to the next */

/* 1 if pixel (x, y) of the glyph of c is ink (0 <= x < FONT_W, 0 <= y < FONT_H, y = 0 the top);
 * characters outside 32..126 are drawn as '?'. */
int font_pixel(int c, int x, int y);
/* For the tests (test_font): 0 if every row of the glyph table is FONT_W characters of '.' and
 * '#', else the first bad character's code (a typo in the table would otherwise show as a blank
 * row). */
int font_table_check(void);
/* Width in pixels of a line of text at integer scale s (no trailing gap); for the tests. */
int font_text_width(const char *text, int s);
/* Draws one line of text into im with its top-left corner at (x, y), each font pixel an s x s
 * square of colour rgb; whatever falls outside the image is clipped. */
void font_draw(image *im, int x, int y, const char *text, int s, const float rgb[3]);
#endif
