/* write_pfm.c: how your renderer can save an image that pathlab diff/grade read.
 * PFM colour: the text header "PF\n W H\n -1\n" (-1 = little-endian floats), then W*H*3 floats,
 * the BOTTOM row first. Here rgb[] holds the rows top to bottom, as most renderers store them. */
#include <stdio.h>
#include <stdlib.h>

static int write_pfm(const char *path, int w, int h, const float *rgb)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    fprintf(f, "PF\n%d %d\n-1\n", w, h);          /* assumes a little-endian machine (x86, ARM) */
    for (int y = h - 1; y >= 0; y--)                /* bottom row first */
        if (fwrite(rgb + (size_t)y * w * 3, sizeof(float), (size_t)w * 3, f) != (size_t)w * 3) {
            fclose(f);
            return -1;
        }
    return fclose(f);                               /* 0 on success */
}

int main(void)   /* a test image: the top half 0.75, the bottom half 0.25 */
{
    int w = 64, h = 64;
    float *rgb = malloc(sizeof(float) * 3 * w * h);
    if (!rgb) return 1;
    for (int i = 0; i < 3 * w * h; i++) rgb[i] = i / 3 / w < h / 2 ? 0.75f : 0.25f;
    int err = write_pfm("mine.pfm", w, h, rgb);
    free(rgb);
    return err ? 1 : 0;
}
