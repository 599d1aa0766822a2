/* bench/texture_lookup.c — the cost of one texture lookup (scene/texture.h), nearest and bilinear, in
 * ns: a 1024 x 1024 texture of random texels, 2^20 texcoords looked up 16 times over, against the
 * same loop summing the texcoords alone (subtracted). Random texcoords in [-2, 3) (repeats included:
 * every lookup a cache miss, the worst case), and coherent ones (a raster walk over the texture, as
 * neighbouring pixels see it). One thread. `make bench` runs it (bench/texture.sh). */
#include "scene/texture.h"
#include "sys/clock.h"
#include <stdio.h>
#include <stdlib.h>

#define N (1 << 20)
#define ROUNDS 16

static double run(const texture *t, const float *uv, int filter, float *sink)
{
    double t0 = clock_seconds();
    float s = 0.0f;
    int r, i;
    for (r = 0; r < ROUNDS; r++)
        for (i = 0; i < N; i++) {
            if (filter < 0) s += uv[2 * i] + uv[2 * i + 1];
            else s += texture_lookup(t, uv[2 * i], uv[2 * i + 1], (texture_filter)filter).y;
        }
    *sink += s;
    return (clock_seconds() - t0) * 1e9 / ((double)N * ROUNDS);
}

int main(void)
{
    texture t;
    float *uv = malloc(2 * sizeof(float) * N), sink = 0.0f;
    unsigned long long x = 88172645463325252ULL;
    double base, ns[2];
    int i, f, k;
    t.w = t.h = 1024;
    t.rgb = malloc(3 * sizeof(float) * 1024 * 1024);
    t.path = NULL;
    if (!uv || !t.rgb) return 1;
    for (i = 0; i < 3 * 1024 * 1024; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        t.rgb[i] = (float)(x >> 40) / 16777216.0f;
    }
    for (i = 0; i < 2 * N; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        uv[i] = -2.0f + 5.0f * (float)(x >> 40) / 16777216.0f;
    }
    for (k = 0; k < 2; k++) {
        if (k == 1)   /* a raster walk: 1024 rows of 1024 steps, 1.3 texels apart */
            for (i = 0; i < N; i++) uv[2 * i] = 1.3f * (float)(i % 1024) / 1024.0f, uv[2 * i + 1] = (float)(i / 1024) / 1024.0f;
        base = run(&t, uv, -1, &sink);
        for (f = 0; f < 2; f++) ns[f] = run(&t, uv, f, &sink) - base;
        for (f = 0; f < 2; f++)
            printf("texture lookup, %s, 1024x1024, %s texcoords: %.1f ns\n", TEXTURE_FILTER_NAMES[f], k ? "coherent" : "random", ns[f]);
    }
    printf("(checksum %g)\n", (double)sink);
    free(uv);
    free(t.rgb);
    return 0;
}
