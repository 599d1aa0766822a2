/* sampler.c — independent samples (a PCG32 stream per sample) and padded, shuffled, Owen-scrambled
 * Sobol samples (Burley 2020). For sobol, dimension d of sample i of a pixel is
 *   j = owen_scramble(i, shuffle_d)                     a permutation of the indices that maps every
 *                                                       aligned block of 2^m indices onto another one,
 *   u = owen_scramble(sobol_dim0(j), scramble_d)        (and sobol_dim1(j) for the second coordinate),
 * with shuffle_d and scramble_d hashed from (seed, pixel, g, d), where the sample belongs to group
 * g = index mod SAMPLER_GROUPS and i = index div SAMPLER_GROUPS is its index in the group: the K
 * groups are K independent scramblings of one Sobol sequence, so the spread between their means
 * estimates the variance of the pixel's mean (pixel_sums.c). Each 2D set is thus the first two Sobol
 * dimensions, a (0, 2)-sequence in base 2: the first 2^m samples of a pixel put one point in every
 * elementary interval of area 2^-m, whatever m; the shuffle decorrelates the sets from one another
 * (padding), so only the first two Sobol dimensions are needed, never a table of direction numbers.
 * Past the pixel and the first SAMPLER_SOBOL_VERTICES path vertices (dimension SAMPLER_SOBOL_DIMS on),
 * the numbers are independent, hashed from (seed, pixel, g, i, d): a Sobol point costs a chain of
 * eleven multiplications, a hashed one two, and on the Cornell boxes the stratification of the
 * deeper vertices lowered no error measurably while its cost was 8% of a render (bench/log.md). */
#include "sampler/sampler.h"
#include <stddef.h>

const char *const SAMPLER_NAMES[] = {"independent", "sobol", "sobol1", 0};

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    x = ((x & 0x0F0F0F0Fu) << 4) | ((x >> 4) & 0x0F0F0F0Fu);
    x = ((x & 0x00FF00FFu) << 8) | ((x >> 8) & 0x00FF00FFu);
    return (x << 16) | (x >> 16);
}

/* Van der Corput: the bits of the index mirrored about the binary point. */
uint32_t sobol_dim0(uint32_t index) { return reverse_bits(index); }

/* The second Sobol dimension, primitive polynomial x + 1: direction numbers v_1 = 1/2 and
 * v_k = v_{k-1} xor v_{k-1}/2 (the rows of Pascal's triangle mod 2); u = xor of v_k over the bits k
 * of i. Row k has a 1 in column p iff C(k, p) is odd, i.e. iff the bits of p are among those of k
 * (Lucas): bit p of u (p = 0 the 1/2 place) is the xor of the index bits k that contain p. On a
 * fraction written with its 1/2 place as bit 0 (reversed, as sobol_point works), that is bit p of
 * the result = the xor of the index's bits k over the supersets k of p, the superset transform, done
 * one bit b of p at a time: 5 shifts instead of a loop over 32 index bits (tests/test_sampler.c
 * checks it against that loop). */
static uint32_t superset_transform(uint32_t y)
{
    y ^= (y >> 1) & 0x55555555u;
    y ^= (y >> 2) & 0x33333333u;
    y ^= (y >> 4) & 0x0F0F0F0Fu;
    y ^= (y >> 8) & 0x00FF00FFu;
    y ^= (y >> 16) & 0x0000FFFFu;
    return y;
}

uint32_t sobol_dim1(uint32_t index) { return reverse_bits(superset_transform(index)); }

/* Owen's nested uniform scrambling of a 32-bit fraction x, by hashing (Burley 2020, section 3): each
 * bit is flipped or not by a hash of the bits above it and the seed. A hash in which every bit
 * depends only on the bits below it (Laine and Karras 2011, with Burley's constants) does that to
 * the bits in reverse order. */
static uint32_t laine_karras(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

uint32_t owen_scramble(uint32_t x, uint32_t seed) { return reverse_bits(laine_karras(reverse_bits(x), seed)); }

void sampler_start(sampler *s, sampler_kind kind, uint64_t seed, uint64_t pixel, uint64_t index)
{
    s->kind = kind;
    if (kind == SAMPLER_INDEPENDENT) {
        pcg32_for_sample(&s->rng, seed, pixel, index);
        return;
    }
    /* group g = index mod SAMPLER_GROUPS: its own scrambling (seeds from (seed, pixel, g)), Sobol index i div K */
    {
        uint64_t K = (uint64_t)sampler_groups(kind);
        s->pixel_seed = splitmix64_at(splitmix64_mix(splitmix64_mix(seed) ^ pixel), index % K);
        /* render refuses indices past sampler_max_index; sobol_point needs the index only reversed */
        s->index_reversed = reverse_bits((uint32_t)(index / K));
        s->sample_seed = splitmix64_mix(s->pixel_seed ^ (index / K));
    }
}

void sampler_from_stream(sampler *s, const pcg32 *r)
{
    s->kind = SAMPLER_INDEPENDENT;
    s->rng = *r;
}

/* Sobol coordinates of dimension dim: the shuffled index, then coordinate 0 (and 1 if u2). It works
 * on reversed fractions (the 1/2 place as bit 0), where sobol_dim0(j) is j itself, sobol_dim1(j) is
 * superset_transform(j) and Owen's scrambling is laine_karras alone: the same numbers as
 * owen_scramble(sobol_dim0(j)) and owen_scramble(sobol_dim1(j)) with j = owen_scramble(index), but
 * with three bit reversals instead of eight (and the index reversed once, in sampler_start). */
static void sobol_point(const sampler *s, uint32_t dim, uint32_t *u1, uint32_t *u2)
{
    uint64_t h = splitmix64_at(s->pixel_seed, dim);
    uint32_t j = reverse_bits(laine_karras(s->index_reversed, (uint32_t)h));
    *u1 = reverse_bits(laine_karras(j, (uint32_t)(h >> 32)));
    if (u2) *u2 = reverse_bits(laine_karras(superset_transform(j), (uint32_t)splitmix64_mix(h)));
}

/* Independent numbers of dimension dim: one hash gives both coordinates. */
static void hashed_point(const sampler *s, uint32_t dim, uint32_t *u1, uint32_t *u2)
{
    uint64_t h = splitmix64_at(s->sample_seed, dim);
    *u1 = (uint32_t)h;
    if (u2) *u2 = (uint32_t)(h >> 32);
}

/* The numbers of a Sobol sampler at dimension dim: stratified up to the last Sobol vertex, hashed past it. */
static void point(const sampler *s, uint32_t dim, uint32_t *u1, uint32_t *u2)
{
    if (dim < SAMPLER_SOBOL_DIMS) sobol_point(s, dim, u1, u2);
    else hashed_point(s, dim, u1, u2);
}

static float to_float(uint32_t x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

float sampler_1d(sampler *s, uint32_t dim)
{
    uint32_t u;
    if (s->kind == SAMPLER_INDEPENDENT) return pcg32_float(&s->rng);
    point(s, dim, &u, NULL);
    return to_float(u);
}

void sampler_2d(sampler *s, uint32_t dim, float *u1, float *u2)
{
    uint32_t a, b;
    if (s->kind == SAMPLER_INDEPENDENT) {
        *u1 = pcg32_float(&s->rng);
        *u2 = pcg32_float(&s->rng);
        return;
    }
    point(s, dim, &a, &b);
    *u1 = to_float(a);
    *u2 = to_float(b);
}

/* The bits of the first coordinate below 2^-32, 21 of them: a hash of (sample, dimension). For a
 * Sobol set that is what Owen's scrambling would put there, since it flips each bit by a random
 * function of the bits above it and the points' own bits end at 2^-32. */
static uint32_t low_bits(const sampler *s, uint32_t dim)
{
    return (uint32_t)(splitmix64_at(s->sample_seed, (uint64_t)dim + 4294967296u) >> 43);
}

double sampler_2d_53bit(sampler *s, uint32_t dim, float *u2)
{
    uint32_t a, b;
    double u;
    if (s->kind == SAMPLER_INDEPENDENT) {
        u = pcg32_double53(&s->rng);
        *u2 = pcg32_float(&s->rng);
        return u;
    }
    point(s, dim, &a, &b);
    *u2 = to_float(b);
    return ((double)a + (double)low_bits(s, dim) * (1.0 / 2097152.0)) * (1.0 / 4294967296.0);
}
