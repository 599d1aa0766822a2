/* sampler.h — the uniform numbers of one sample, addressed by (seed, pixel, sample index, dimension).
 * sampler_start picks the sample; then sampler_1d, sampler_2d and sampler_2d_53bit give its
 * coordinates at a dimension, and sampler_vertex with the named draws below (sampler_light,
 * sampler_lobe, ...) give each use at each path vertex its own dimension, so that the same use of
 * every path of a pixel reads the same dimension.
 *   independent  one PCG32 stream per sample (pcg32_for_sample), read in the order of the calls:
 *                the dimension argument is ignored.
 *   sobol        Owen-scrambled Sobol points (Burley 2020, "Practical Hash-based Owen Scrambling",
 *                JCGT 9(4)), padded: every dimension is its own shuffled, scrambled 1D or 2D Sobol
 *                set, with seeds hashed from (seed, pixel, group, dimension). Sample `index` belongs
 *                to group index mod SAMPLER_GROUPS, whose scrambling is independent of the other
 *                groups', and is point index div SAMPLER_GROUPS of it. Within one group the samples
 *                are NOT independent: their sample variance does not estimate the variance of the
 *                mean; the spread between the group means does (render/pixel_sums.h).
 *                Only the pixel jitter and the first SAMPLER_SOBOL_VERTICES path vertices are Sobol
 *                sets; the numbers of the deeper vertices are independent, hashed from (seed, pixel,
 *                group, index, dimension).
 *   sobol1       the same with a single group: one scrambled sequence per pixel, stratified over
 *                all of its samples (the lowest error), whose variance cannot be estimated. */
#ifndef PATHLAB_SAMPLER_H
#define PATHLAB_SAMPLER_H
#include <stdint.h>
#include "math/rng.h"

typedef enum { SAMPLER_INDEPENDENT, SAMPLER_SOBOL, SAMPLER_SOBOL1 } sampler_kind;   /* --sampler */
/* sobol: independent scramblings per pixel (K; the variance of the mean has K - 1 degrees of
 * freedom); sobol1: one scrambling per pixel (K = 1: the best-stratified points, but no variance
 * estimate). Each takes 2^32 points per group (past that they would repeat). */
#define SAMPLER_GROUPS 4   /* sobol's K; sampler_groups() gives each kind's */
static inline int sampler_groups(sampler_kind k) { return k == SAMPLER_SOBOL ? SAMPLER_GROUPS : k == SAMPLER_SOBOL1 ? 1 : 0; }
static inline int64_t sampler_max_index(sampler_kind k) { return k == SAMPLER_INDEPENDENT ? INT64_MAX : 4294967296LL * sampler_groups(k); }
extern const char *const SAMPLER_NAMES[];                            /* in enum order, NULL-terminated */

typedef struct {
    sampler_kind kind;
    pcg32 rng;              /* independent: the sample's stream */
    uint64_t pixel_seed;    /* sobol: hashed from (seed, pixel, group); each dimension's seeds derive from it */
    uint32_t index_reversed;   /* sobol: the point's index in its group (sample index div SAMPLER_GROUPS), bits reversed */
    uint64_t sample_seed;   /* sobol: hashed from pixel_seed and that index; the deeper vertices' numbers derive from it */
    uint32_t vertex_dim;    /* the first dimension of the current path vertex (sampler_vertex) */
} sampler;

/* Sample `index` of pixel `pixel` under seed `seed`: depends on nothing else. */
void sampler_start(sampler *s, sampler_kind kind, uint64_t seed, uint64_t pixel, uint64_t index);
/* An independent sampler reading the stream r from where it is (the tests' own streams). */
void sampler_from_stream(sampler *s, const pcg32 *r);

/* Uniform in [0, 1), 24 bits: never 1. */
float sampler_1d(sampler *s, uint32_t dim);
/* Uniform in [0, 1)^2, both coordinates of one 2D set (independent: two numbers in turn). */
void sampler_2d(sampler *s, uint32_t dim, float *u1, float *u2);
/* Both coordinates of a 2D set, the first a double with 53 random bits: a discrete choice among
 * millions of items, some of probability far below 2^-32 (a light tree's), whose remainder is
 * reused as a coordinate (light_sample_point_joint), so the pair stays one stratified 2D set. The
 * top 32 bits are the set's (sobol: its stratified coordinate), the 21 below them independent. */
double sampler_2d_53bit(sampler *s, uint32_t dim, float *u2);

/* The numbers of a path, by use. A sample's dimensions are the pixel jitter, then
 * SAMPLER_DIMS_PER_VERTEX per path vertex k >= 1, one per use: the integrator tells the sampler
 * which vertex it is at, then asks for each use's numbers by name. A use that needs no number at a
 * vertex (no lobe to choose, a sure survivor of the roulette) skips its dimension, and no other
 * use's dimension moves. An independent sampler ignores the dimensions: it reads its stream in the
 * order of the calls. (pbrt-v4's samplers instead count the dimensions as they are drawn.) */
enum {
    SAMPLER_DIM_PIXEL = 0,          /* 2D: the jitter inside the pixel */
    SAMPLER_DIM_LIGHT = 0,          /* 2D, the first coordinate 53 bits: which emitter, and the point s on it */
    SAMPLER_DIM_LOBE = 1,           /* 1D: which BRDF lobe */
    SAMPLER_DIM_DIRECTION = 2,      /* 2D: the direction wi */
    SAMPLER_DIM_ROULETTE = 3,       /* 1D: Russian roulette */
    SAMPLER_DIMS_PER_VERTEX = 4
};
/* sobol, sobol1: the vertices whose numbers are stratified, and the dimensions that takes */
#define SAMPLER_SOBOL_VERTICES 2
#define SAMPLER_SOBOL_DIMS (1u + SAMPLER_SOBOL_VERTICES * SAMPLER_DIMS_PER_VERTEX)
static inline void sampler_pixel(sampler *s, float *jx, float *jy) { sampler_2d(s, SAMPLER_DIM_PIXEL, jx, jy); }
/* From here on, the numbers are those of path vertex k >= 1. */
static inline void sampler_vertex(sampler *s, int k) { s->vertex_dim = 1u + (uint32_t)(k - 1) * SAMPLER_DIMS_PER_VERTEX; }
/* The light's choice (returned, 53 bits) and the point's second coordinate *u2: one 2D set. */
static inline double sampler_light(sampler *s, float *u2) { return sampler_2d_53bit(s, s->vertex_dim + SAMPLER_DIM_LIGHT, u2); }
static inline float sampler_lobe(sampler *s) { return sampler_1d(s, s->vertex_dim + SAMPLER_DIM_LOBE); }
static inline void sampler_direction(sampler *s, float *u1, float *u2) { sampler_2d(s, s->vertex_dim + SAMPLER_DIM_DIRECTION, u1, u2); }
static inline float sampler_roulette(sampler *s) { return sampler_1d(s, s->vertex_dim + SAMPLER_DIM_ROULETTE); }

/* The building blocks of sobol, for the tests: the first two Sobol dimensions (van der Corput and
 * the one of the polynomial x + 1) as 32-bit fractions, and Owen's nested uniform scrambling. */
uint32_t sobol_dim0(uint32_t index);
uint32_t sobol_dim1(uint32_t index);
uint32_t owen_scramble(uint32_t x, uint32_t seed);
#endif
