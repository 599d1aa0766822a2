/* mosaic.c — labelled images on a grid (see mosaic.h). */
#include "image/mosaic.h"
#include <assert.h>
#include <string.h>
#include "image/font.h"

#define GAP 4                 /* pixels between panels and around them */
#define MAX_LINES 3           /* of a label */
#define MAX_COLS 127          /* characters of a label's line */

static const float BG[3] = {0.012f, 0.012f, 0.014f};     /* dark grey once sRGB-encoded (~0.11) */
static const float INK[3] = {1.0f, 1.0f, 1.0f};

typedef struct {
    int k;        /* magnification: each image pixel is k x k */
    int ts;       /* text scale: each font pixel is ts x ts */
    int pw, ph;   /* panel size */
    int cols;     /* characters of a label line */
} layout;

/* Breaks text into at most MAX_LINES lines of at most cols characters, at spaces when it can;
 * the last line ends with ".." if the text did not fit. Returns the number of lines. */
static int wrap(const char *text, int cols, char lines[MAX_LINES][MAX_COLS + 1])
{
    int n = 0, len;
    if (cols < 3) cols = 3;
    if (cols > MAX_COLS) cols = MAX_COLS;
    while (*text == ' ') text++;
    while (*text && n < MAX_LINES) {
        len = (int)strlen(text);
        if (len > cols) {
            int k = cols;
            while (k > 0 && text[k] != ' ') k--;
            len = k > cols / 3 ? k : cols;   /* break at the last space, or cut a long word */
        }
        memcpy(lines[n], text, (size_t)len);
        lines[n][len] = '\0';
        text += len;
        while (*text == ' ') text++;
        n++;
    }
    if (*text && n > 0) {   /* did not fit: mark the cut */
        size_t m = strlen(lines[n - 1]);
        if (m + 2 > (size_t)cols) m = (size_t)cols - 2;
        strcpy(lines[n - 1] + m, "..");
    }
    return n;
}

/* The height of the label band over row r: 2 pixels, then as many lines as its longest label. */
static int band_height(const layout *L, const mosaic_panel *row, int cols)
{
    char lines[MAX_LINES][MAX_COLS + 1];
    int i, n, most = 0;
    for (i = 0; i < cols; i++)
        if ((n = wrap(row[i].label, L->cols, lines)) > most) most = n;
    return 2 + most * FONT_LINE * L->ts;
}

static void draw_label(image *m, const layout *L, int x, int y, const char *text)
{
    char lines[MAX_LINES][MAX_COLS + 1];
    int i, n = wrap(text, L->cols, lines);
    for (i = 0; i < n; i++) font_draw(m, x, y + 2 + i * FONT_LINE * L->ts, lines[i], L->ts, INK);
}

/* Copies im into m at (x, y), each pixel a k x k square, multiplied by gain. */
static void blit(image *m, const image *im, int x, int y, int k, float gain)
{
    int i, j, c;
    for (j = 0; j < im->h * k; j++)
        for (i = 0; i < im->w * k; i++)
            for (c = 0; c < 3; c++)
                m->px[3 * ((long)(y + j) * m->w + x + i) + c] = gain * im->px[3 * ((long)(j / k) * im->w + i / k) + c];
}

/* Small images are magnified up to 4x toward 128 pixels; labels of wide panels are drawn 2x. */
static void make_layout(layout *L, const image *first)
{
    for (L->k = 1; first->w * L->k < 128 && L->k < 4; L->k++) continue;
    L->pw = first->w * L->k;
    L->ph = first->h * L->k;
    L->ts = L->pw >= 400 ? 2 : 1;
    L->cols = (L->pw + L->ts) / (FONT_ADVANCE * L->ts);
}

int mosaic_make(image *m, const mosaic_panel *panels, int rows, int cols)
{
    layout L;
    int i, r, x, y, band, h = GAP;
    make_layout(&L, panels[0].im);
    for (r = 0; r < rows; r++) h += band_height(&L, panels + r * cols, cols) + L.ph + GAP;
    if (img_alloc(m, GAP + cols * (L.pw + GAP), h)) return 1;
    for (i = 0; i < m->w * m->h; i++) memcpy(m->px + 3L * i, BG, sizeof BG);
    for (r = 0, y = GAP; r < rows; r++, y += band + L.ph + GAP) {
        band = band_height(&L, panels + r * cols, cols);
        for (i = 0; i < cols; i++) {
            const mosaic_panel *p = &panels[r * cols + i];
            assert(p->im->w == panels[0].im->w && p->im->h == panels[0].im->h);
            x = GAP + i * (L.pw + GAP);
            draw_label(m, &L, x, y, p->label);
            blit(m, p->im, x, y + band, L.k, p->gain);
        }
    }
    return 0;
}
