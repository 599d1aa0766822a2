/* rng.h — PCG32 (O'Neill 2014, "PCG: a family of simple fast space-efficient statistically good
 * algorithms for random number generation"): 64-bit LCG state, 32-bit output by xorshift and a
 * random rotation. Each pixel owns one stream, selected by (seed, pixel index), so an image does
 * not depend on how pixels are shared among threads. Also SplitMix64's finaliser, which turns
 * such (seed, index) pairs into unrelated seeds. */
#ifndef PATHLAB_RNG_H
#define PATHLAB_RNG_H
#include <stdint.h>

typedef struct { uint64_t state, inc; } pcg32;

#define PCG32_MULT 6364136223846793005ULL

static inline uint32_t pcg32_next(pcg32 *r)
{
    uint64_t old = r->state;
    uint32_t xorshifted = (uint32_t)(((old >> 18) ^ old) >> 27);
    uint32_t rot = (uint32_t)(old >> 59);
    r->state = old * PCG32_MULT + r->inc;
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
}

/* Stream `sequence` (any 64-bit value; the increment must be odd) started at `seed`. */
static inline void pcg32_init(pcg32 *r, uint64_t seed, uint64_t sequence)
{
    r->state = 0;
    r->inc = (sequence << 1) | 1u;
    pcg32_next(r);
    r->state += seed;
    pcg32_next(r);
}

/* SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijection of 64-bit words that scatters
 * neighbouring inputs, so that seeds made of (seed, pixel) or (seed, case) give unrelated streams. */
static inline uint64_t splitmix64_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* The stream of sample i of pixel p: its numbers depend on (seed, p, i) only, never on the samples
 * drawn before, so any range of samples can be rendered alone (--samples A:B) and pieces merged
 * equal the whole render. The j-th number drawn is the sample's dimension j. */
static inline void pcg32_for_sample(pcg32 *r, uint64_t seed, uint64_t pixel, uint64_t i)
{
    pcg32_init(r, splitmix64_mix(splitmix64_mix(splitmix64_mix(seed) ^ pixel) ^ i), pixel);
}

/* SplitMix64's increment, 2^64 / golden ratio: seed + k GAMMA for k = 0, 1, 2... are far apart. */
#define SPLITMIX64_GAMMA 0x9E3779B97F4A7C15ULL

/* The k-th output of the SplitMix64 sequence started at seed: unrelated seeds for items k of a run. */
static inline uint64_t splitmix64_at(uint64_t seed, uint64_t k) { return splitmix64_mix(seed + SPLITMIX64_GAMMA * k); }

/* Uniform double in [0, 1) with 32 random bits: for discrete choices among millions of items,
 * where 24 bits would quantise each item's probability. */
static inline double pcg32_double(pcg32 *r) { return (double)pcg32_next(r) * (1.0 / 4294967296.0); }

/* Uniform double in [0, 1) with all 53 bits random, from two outputs: for a choice whose
 * probabilities may be far below 2^-32 (a light tree's), which 32 bits would never draw. */
static inline double pcg32_double53(pcg32 *r)
{
    uint32_t hi = pcg32_next(r), lo = pcg32_next(r) >> 11;
    return ((double)hi + (double)lo * (1.0 / 2097152.0)) * (1.0 / 4294967296.0);
}

/* Uniform float in [0, 1): the top 24 bits, so that 1 is never returned. */
static inline float pcg32_float(pcg32 *r) { return (float)(pcg32_next(r) >> 8) * (1.0f / 16777216.0f); }
#endif
