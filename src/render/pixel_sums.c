/* pixel_sums.c — per-pixel sums and the variance of the mean, for independent and grouped samples. */
#include "render/pixel_sums.h"

#define NSUM_INDEPENDENT 6   /* sums of the samples and of their squares, RGB */

int pixel_sums_size(sampler_kind kind) { return kind == SAMPLER_INDEPENDENT ? NSUM_INDEPENDENT : 3 * sampler_groups(kind); }

void pixel_sums_add(double *a, sampler_kind kind, int64_t index, vec3 c)
{
    if (kind != SAMPLER_INDEPENDENT) {
        double *g = a + 3 * (index % sampler_groups(kind));
        g[0] += c.x; g[1] += c.y; g[2] += c.z;
        return;
    }
    a[0] += c.x; a[1] += c.y; a[2] += c.z;
    a[3] += (double)c.x * c.x; a[4] += (double)c.y * c.y; a[5] += (double)c.z * c.z;
}

/* Indices i in [0, x) with i mod K = g. */
static int64_t count_below(int64_t x, int g, int K) { return (x + K - 1 - g) / K; }

/* The samples of group g (of K) among the indices first .. first + n - 1. */
static int64_t pixel_sums_group_count(int64_t first, int64_t n, int g, int K) { return count_below(first + n, g, K) - count_below(first, g, K); }

int pixel_sums_dof(sampler_kind kind, int n)
{
    int K = sampler_groups(kind);
    if (kind == SAMPLER_INDEPENDENT) return 0;
    if (K < 2) return -1;   /* sobol1: one scrambling, no variance */
    return (n < K ? n : K) - 1;
}

/* The groups' means m_g (n_g samples, n in all) scatter about the mean m. With n a multiple of K the
 * groups are K independent, identically distributed estimates, and sum_g (m_g - m)^2 / (K (K - 1)) is
 * an unbiased estimate of the variance of m = mean of the m_g. Otherwise the first groups hold one
 * sample more: m is then the sample-weighted mean, and the estimate is the one-way analysis of
 * variance's, sum_g n_g (m_g - m)^2 / ((K' - 1) n) over the K' groups with samples, unbiased if each
 * m_g had variance c / n_g. Sobol's group variance falls faster than 1 / n_g, so this leans a little
 * towards the smaller groups: a bias of order 1 / n_g, nil when n is a multiple of K. */
static void store_groups(const double *a, int K, int64_t first, int n, float mean[3], float var[3])
{
    int g, ch, groups = 0;
    int64_t ng[SAMPLER_GROUPS];
    for (g = 0; g < K; g++) groups += (ng[g] = pixel_sums_group_count(first, n, g, K)) > 0;
    for (ch = 0; ch < 3; ch++) {
        double sum = 0.0, m, ss = 0.0;
        for (g = 0; g < K; g++) sum += a[3 * g + ch];
        m = n > 0 ? sum / n : 0.0;
        for (g = 0; g < K; g++)
            if (ng[g] > 0) {
                double e = a[3 * g + ch] / (double)ng[g] - m;
                ss += (double)ng[g] * e * e;
            }
        mean[ch] = (float)m;
        var[ch] = (float)(groups > 1 ? ss / ((groups - 1) * (double)n) : 0.0);
    }
}

void pixel_sums_store(const double *a, sampler_kind kind, int64_t first, int n, float mean[3], float var[3])
{
    int ch;
    if (kind != SAMPLER_INDEPENDENT) {   /* sobol1 (one group): variance 0, and no variance file */
        store_groups(a, sampler_groups(kind), first, n, mean, var);
        return;
    }
    for (ch = 0; ch < 3; ch++) {
        double m = n > 0 ? a[ch] / n : 0.0;
        double s2 = n > 1 ? (a[3 + ch] - n * m * m) / (n - 1) : 0.0;   /* sample variance */
        mean[ch] = (float)m;
        var[ch] = (float)(s2 > 0.0 ? s2 / n : 0.0);                      /* of the mean */
    }
}
