/* test_sobol_definition.c — the Sobol samplers' numbers equal the definition of tracer/sampler.c's
 * header, computed here the slow way from the public building blocks:
 *   j = owen_scramble(i, shuffle_d),  u1 = owen_scramble(sobol_dim0(j), scramble_d),
 *   u2 = owen_scramble(sobol_dim1(j), scramble2_d),
 * with the seeds hashed from (seed, pixel, group, dimension) as sampler_start and sobol_point do,
 * and the two Sobol dimensions by their definition (loops over the index bits, not sampler.c's);
 * past SAMPLER_SOBOL_DIMS, the 64 bits of a hash of (the sample's seed, dimension); and the 21
 * bits that sampler_2d_53bit puts below u1's 32, a second hash of (the sample's seed, dimension).
 * sobol_point computes the same numbers with fewer bit reversals (on reversed fractions): any
 * change to its shortcuts that changes a number, and thus every Sobol image, fails here. Exact
 * comparisons, no statistics: sobol and sobol1, 2000 (seed, pixel, index, dimension) each, 3 calls. */
#include "check.h"
#include "sampler/sampler.h"

/* Van der Corput: index bit k is the fraction's 2^-(k+1) place. */
static uint32_t dim0_by_definition(uint32_t index)
{
    uint32_t u = 0, v = 0x80000000u;
    for (; index; index >>= 1, v >>= 1)
        if (index & 1u) u ^= v;
    return u;
}

/* Polynomial x + 1: direction numbers v_1 = 1/2, v_k = v_{k-1} xor v_{k-1}/2. */
static uint32_t dim1_by_definition(uint32_t index)
{
    uint32_t u = 0, v = 0x80000000u;
    for (; index; index >>= 1, v ^= v >> 1)
        if (index & 1u) u ^= v;
    return u;
}

/* Sample `index` of the sampler `kind`, dimension dim, as a 32-bit pair by the definition, and the
 * 21 bits below u1 in *low. */
static void by_definition(sampler_kind kind, uint64_t seed, uint64_t pixel, uint64_t index, uint32_t dim, uint32_t *u1, uint32_t *u2, uint32_t *low)
{
    uint64_t K = (uint64_t)sampler_groups(kind);
    uint64_t pixel_seed = splitmix64_at(splitmix64_mix(splitmix64_mix(seed) ^ pixel), index % K);
    uint64_t h = splitmix64_at(pixel_seed, dim);
    uint32_t j = owen_scramble((uint32_t)(index / K), (uint32_t)h);
    *low = (uint32_t)(splitmix64_at(splitmix64_mix(pixel_seed ^ (index / K)), (uint64_t)dim + 4294967296u) >> 43);
    if (dim >= SAMPLER_SOBOL_DIMS) {   /* a deeper vertex: independent numbers */
        h = splitmix64_at(splitmix64_mix(pixel_seed ^ (index / K)), dim);
        *u1 = (uint32_t)h, *u2 = (uint32_t)(h >> 32);
        return;
    }
    *u1 = owen_scramble(dim0_by_definition(j), (uint32_t)(h >> 32));
    *u2 = owen_scramble(dim1_by_definition(j), (uint32_t)splitmix64_mix(h));
}

static float top24(uint32_t x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

/* sampler_1d, sampler_2d and sampler_2d_53bit against the definition. */
static void check_kind(sampler_kind kind)
{
    pcg32 r;
    int n, bad = 0;
    char name[160];
    pcg32_init(&r, 2026, (uint64_t)kind);
    for (n = 0; n < 2000; n++) {
        uint64_t seed = pcg32_next(&r), pixel = pcg32_next(&r) % 1000000u;
        uint64_t index = n < 1000 ? (uint64_t)n : pcg32_next(&r);   /* the first indices, then any */
        uint32_t dim = pcg32_next(&r) % (n % 2 ? 200u : SAMPLER_SOBOL_DIMS), a, b, low;   /* half of them Sobol */
        sampler s;
        float f1, f2, g2;
        double d;
        by_definition(kind, seed, pixel, index, dim, &a, &b, &low);
        sampler_start(&s, kind, seed, pixel, index);
        sampler_2d(&s, dim, &f1, &f2);
        bad += f1 != top24(a) || f2 != top24(b);
        bad += sampler_1d(&s, dim) != top24(a);
        d = sampler_2d_53bit(&s, dim, &g2);
        bad += d != ((double)a + (double)low / 2097152.0) / 4294967296.0 || g2 != top24(b);
    }
    snprintf(name, sizeof name, "%s: 2000 draws of each call equal the definition (owen_scramble of Sobol dimensions 0, 1 at the shuffled index; a hash past the Sobol vertices)",
             SAMPLER_NAMES[kind]);
    check(bad == 0, name, "%d differ", bad);
}

int main(void)
{
    check_kind(SAMPLER_SOBOL);
    check_kind(SAMPLER_SOBOL1);
    return check_summary();
}
