/* test_sampler.c — the samplers of sampler/sampler.h:
 *   1. independent reads the stream pcg32_for_sample in the order of the calls;
 *   2. the first two Sobol dimensions, and each scrambled, shuffled 2D set of --sampler sobol, are
 *      (0, m, 2)-nets for every m <= 10: one point in every elementary interval of area 2^-m, for
 *      every shape 2^-a x 2^-(m-a); a 1D dimension puts one point in each of 2^m strata; each of
 *      the SAMPLER_GROUPS groups of a pixel (indices g, g + K, g + 2K...) is such a net on its own;
 *   3. the same sample is the same numbers (addressable), and different pixels and dimensions
 *      give different points;
 *   4. averages over pixels of a few coordinates are 1/2 within 5 standard errors (a gross bias),
 *      those of the deeper vertices' hashed numbers too, and these are uncorrelated with one
 *      another and with the last Sobol dimension;
 *   5. the light's choice (sampler_2d_53bit) is uniform below 2^-32 too: where it falls within its
 *      2^-32 cell, over 65536 samples in 64 bins, passes a chi-square test at alpha = 1e-4, for
 *      every sampler, at a Sobol and at a hashed dimension. With 32 bits it is always 0, and an
 *      emitter whose share is under 2^-32 (a light tree's, far from p) is never chosen. */
#include "check.h"
#include "sampler/sampler.h"
#include "stats/chi2.h"
#include <math.h>
#include <string.h>

/* 1 if the 2^m points (x[i], y[i]) (32-bit fractions) are a (0, m, 2)-net in base 2. */
static int is_net(const uint32_t *x, const uint32_t *y, int m)
{
    static unsigned char seen[1 << 10];
    int a, i, n = 1 << m;
    for (a = 0; a <= m; a++) {
        memset(seen, 0, (size_t)n);
        for (i = 0; i < n; i++) {
            uint32_t cx = a ? x[i] >> (32 - a) : 0, cy = m - a ? y[i] >> (32 - (m - a)) : 0;
            uint32_t cell = (cx << (m - a)) | cy;
            if (seen[cell]++) return 0;
        }
    }
    return 1;
}

/* 1 if sampler_1d at dimension dim puts one of the first 2^m samples of the pixel in each of 2^m strata. */
static int one_per_stratum(uint32_t pixel, uint32_t dim, int m, int g)
{
    static unsigned char seen[1 << 10];
    int i;
    memset(seen, 0, sizeof seen);
    for (i = 0; i < 1 << m; i++) {
        sampler s;
        sampler_start(&s, SAMPLER_SOBOL, 7, pixel, (uint64_t)i * SAMPLER_GROUPS + (uint64_t)g);
        if (seen[(int)(sampler_1d(&s, dim) * (float)(1 << m))]++) return 0;
    }
    return 1;
}

static void check_independent(void)
{
    sampler s;
    pcg32 r;
    float u1, u2, v2;
    int k, same = 1;
    sampler_start(&s, SAMPLER_INDEPENDENT, 42, 1234, 77);
    pcg32_for_sample(&r, 42, 1234, 77);
    for (k = 0; k < 20; k++) {
        double d = sampler_2d_53bit(&s, 99, &v2);
        same = same && d == pcg32_double53(&r) && v2 == pcg32_float(&r);
        sampler_2d(&s, 3, &u1, &u2);
        same = same && u1 == pcg32_float(&r) && u2 == pcg32_float(&r);
        same = same && sampler_1d(&s, 0) == pcg32_float(&r);
    }
    check(same, "independent: the stream pcg32_for_sample, read in the order of the calls", NULL);
}

/* The definition of the second Sobol dimension: the xor of the direction numbers of the index's bits. */
static uint32_t sobol_dim1_by_definition(uint32_t index)
{
    uint32_t u = 0, v = 0x80000000u;
    for (; index; index >>= 1, v ^= v >> 1)
        if (index & 1u) u ^= v;
    return u;
}

static void check_sobol_dim1(void)
{
    pcg32 r;
    uint32_t i, bad = 0;
    pcg32_init(&r, 5, 1);
    for (i = 0; i < 100000; i++) {
        uint32_t x = i < 50000 ? i : pcg32_next(&r);
        bad += sobol_dim1(x) != sobol_dim1_by_definition(x);
    }
    bad += sobol_dim1(0xFFFFFFFFu) != sobol_dim1_by_definition(0xFFFFFFFFu);
    check(bad == 0, "sobol_dim1 (subset transform) equals the xor of direction numbers: 0..49999 and 50000 random indices", "%u differ", bad);
}

static void check_sobol_nets(void)
{
    static uint32_t x[1 << 10], y[1 << 10];
    int m, i, plain = 1, scrambled = 1, strata = 1;
    for (m = 0; m <= 10; m++) {
        for (i = 0; i < 1 << m; i++) x[i] = sobol_dim0((uint32_t)i), y[i] = sobol_dim1((uint32_t)i);
        plain = plain && is_net(x, y, m);
    }
    check(plain, "sobol_dim0, sobol_dim1: the first 2^m points are a (0, m, 2)-net, m = 0..10", NULL);
    for (m = 0; m <= 10; m++) {
        uint32_t pixel, dim;
        int g;
        for (pixel = 0; pixel < 20; pixel++)
            for (dim = 0; dim < SAMPLER_SOBOL_DIMS; dim++)
                for (g = 0; g < SAMPLER_GROUPS; g++) {
                    for (i = 0; i < 1 << m; i++) {
                        sampler s;
                        float u1, u2;
                        sampler_start(&s, SAMPLER_SOBOL, 7, pixel, (uint64_t)i * SAMPLER_GROUPS + (uint64_t)g);
                        sampler_2d(&s, dim, &u1, &u2);
                        x[i] = (uint32_t)(u1 * 16777216.0f) << 8, y[i] = (uint32_t)(u2 * 16777216.0f) << 8;
                    }
                    scrambled = scrambled && is_net(x, y, m);
                    strata = strata && one_per_stratum(pixel, dim, m, g);
                }
    }
    check(scrambled, "sobol: each group's 2D set, 20 pixels x the 9 Sobol dimensions x 4 groups, is a (0, m, 2)-net for m = 0..10", NULL);
    check(strata, "sobol: sampler_1d puts one of a group's first 2^m samples in each of 2^m strata", NULL);
}

static void check_sobol_addressable(void)
{
    sampler a, b;
    float u1, u2, v1, v2;
    sampler_start(&a, SAMPLER_SOBOL, 3, 500, 9);
    sampler_start(&b, SAMPLER_SOBOL, 3, 500, 9);
    sampler_2d(&a, 4, &u1, &u2);
    (void)sampler_1d(&b, 2);   /* what was drawn before changes nothing */
    sampler_2d(&b, 4, &v1, &v2);
    check(u1 == v1 && u2 == v2, "sobol: a sample's numbers depend on (seed, pixel, index, dimension) only", NULL);
    sampler_start(&b, SAMPLER_SOBOL, 3, 501, 9);
    sampler_2d(&b, 4, &v1, &v2);
    sampler_2d(&a, 5, &u2, &u1);
    check(v1 != u1 || v2 != u2, "sobol: another pixel or dimension, another point", NULL);
    sampler_start(&a, SAMPLER_SOBOL, 3, 500, 8);
    sampler_start(&b, SAMPLER_SOBOL, 3, 500, 9);   /* the same point index 2 of groups 0 and 1 */
    sampler_2d(&a, 4, &u1, &u2);
    sampler_2d(&b, 4, &v1, &v2);
    check(v1 != u1 || v2 != u2, "sobol: the groups of a pixel are scrambled differently", NULL);
}

/* The mean of coordinate dim over n pixels x 16 samples, as a z-score against 1/2. */
static double mean_z(uint32_t dim, int n)
{
    double sum = 0, sum2 = 0, mean, var;
    int p, i;
    for (p = 0; p < n; p++) {
        double pix = 0;
        for (i = 0; i < 16; i++) {
            sampler s;
            float u2;
            sampler_start(&s, SAMPLER_SOBOL, 11, (uint64_t)p, (uint64_t)i);
            pix += dim % 2 ? sampler_1d(&s, dim) : sampler_2d_53bit(&s, dim, &u2);
        }
        pix /= 16;
        sum += pix, sum2 += pix * pix;
    }
    mean = sum / n;
    var = (sum2 - n * mean * mean) / (n - 1) / n;
    return var > 0 ? (mean - 0.5) / sqrt(var) : (mean == 0.5 ? 0 : 1e9);
}

/* The correlation of coordinate c1 of dimension d1 of sample i with coordinate c2 of dimension d2
 * of sample i + di of the same pixel (2D sets) over n pixels x 16 samples, as a z-score: r sqrt(N)
 * is about normal for independent numbers. */
static double correlation_z(uint32_t d1, int c1, uint32_t d2, int c2, uint64_t di, int n)
{
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, N = 16.0 * n, cov, r;
    int p, i;
    for (p = 0; p < n; p++)
        for (i = 0; i < 16; i++) {
            sampler s;
            float a[2], b[2];
            sampler_start(&s, SAMPLER_SOBOL, 13, (uint64_t)p, (uint64_t)i);
            sampler_2d(&s, d1, &a[0], &a[1]);
            sampler_start(&s, SAMPLER_SOBOL, 13, (uint64_t)p, (uint64_t)i + di);
            sampler_2d(&s, d2, &b[0], &b[1]);
            sx += a[c1], sy += b[c2], sxx += (double)a[c1] * a[c1], syy += (double)b[c2] * b[c2], sxy += (double)a[c1] * b[c2];
        }
    cov = sxy / N - sx / N * (sy / N);
    r = cov / sqrt((sxx / N - sx / N * (sx / N)) * (syy / N - sy / N * (sy / N)));
    return r * sqrt(N);
}

/* The fraction of a 2^-32 cell where the first coordinate of sampler_2d_53bit falls, binned: chi2 p-value. */
static double fine_bits_p(sampler_kind kind, uint32_t dim)
{
    enum { BINS = 64, N = 65536 };
    double observed[BINS] = {0}, expected[BINS];
    int i;
    for (i = 0; i < BINS; i++) expected[i] = (double)N / BINS;
    for (i = 0; i < N; i++) {
        sampler s;
        float u2;
        double u, cell;
        sampler_start(&s, kind, 21, (uint64_t)(i % 1024), (uint64_t)(i / 1024));
        u = sampler_2d_53bit(&s, dim, &u2) * 4294967296.0;
        cell = u - floor(u);
        observed[(int)(cell * BINS)] += 1;
    }
    return chi2_test(observed, expected, BINS).p;
}

static void check_fine_bits(void)
{
    const sampler_kind kinds[] = {SAMPLER_INDEPENDENT, SAMPLER_SOBOL, SAMPLER_SOBOL1};
    const uint32_t dims[] = {1 + SAMPLER_DIM_LIGHT, SAMPLER_SOBOL_DIMS + 1 + SAMPLER_DIM_LIGHT};
    double worst = 1;
    int k, d;
    for (k = 0; k < 3; k++)
        for (d = 0; d < 2; d++) {
            double p = fine_bits_p(kinds[k], dims[d]);
            if (p < worst) worst = p;
        }
    check(worst > 1e-4, "the light's choice is uniform below 2^-32 (3 samplers x 2 dimensions, 65536 samples, 64 bins, chi2 alpha 1e-4)",
          "smallest p %.3g", worst);
}

int main(void)
{
    uint32_t dim;
    double worst = 0;
    check_independent();
    check_fine_bits();
    check_sobol_dim1();
    check_sobol_nets();
    check_sobol_addressable();
    for (dim = 0; dim < 16; dim++) {
        double z = fabs(mean_z(dim, 20000));
        if (z > worst) worst = z;
    }
    check(worst < 5, "sobol: the mean of dimensions 0..15 (Sobol, then hashed) over 20000 pixels is 1/2", "largest |z| %.2f", worst);
    {
        /* the two halves of one hash, two hashed dimensions, the last Sobol one and a hashed one,
         * one hashed dimension in the next sample and in the next point of the same group */
        const uint32_t d = SAMPLER_SOBOL_DIMS;
        double z[6];
        z[0] = correlation_z(d + 1, 0, d + 1, 1, 0, 20000);
        z[1] = correlation_z(d, 0, d + 1, 0, 0, 20000);
        z[2] = correlation_z(d + 4, 1, d + 8, 1, 0, 20000);
        z[3] = correlation_z(d - 2, 0, d + 2, 0, 0, 20000);
        z[4] = correlation_z(d + 2, 0, d + 2, 0, 1, 20000);
        z[5] = correlation_z(d + 2, 1, d + 2, 1, SAMPLER_GROUPS, 20000);
        for (worst = 0, dim = 0; dim < 6; dim++)
            if (fabs(z[dim]) > worst) worst = fabs(z[dim]);
        check(worst < 5, "sobol: hashed numbers are uncorrelated (6 pairs, 320000 samples each, |z| < 5)", "largest |z| %.2f", worst);
    }
    return check_summary();
}
