/* combine.c — Chan, Golub and LeVeque's pairwise update of a mean and its sum of squares. */
#include "stats/combine.h"
#include <stdlib.h>

int combine_init(combine_acc *c, size_t count)
{
    c->count = count;
    c->n = 0.0;
    c->mean = calloc(count ? count : 1, sizeof(double));
    c->m2 = calloc(count ? count : 1, sizeof(double));
    if (c->mean && c->m2) return 0;
    combine_free(c);
    return 1;
}

void combine_free(combine_acc *c)
{
    free(c->mean);
    free(c->m2);
    c->mean = c->m2 = NULL;
}

void combine_add(combine_acc *c, const float *mean, const float *var, double n)
{
    double total = c->n + n;
    size_t i;
    if (n <= 0) return;
    for (i = 0; i < c->count; i++) {
        double mb = mean[i];
        double m2b = var ? (double)var[i] * n * (n - 1.0) : 0.0;   /* var of the mean = m2 / ((n - 1) n) */
        double delta = mb - c->mean[i];
        c->mean[i] += delta * (n / total);
        c->m2[i] += m2b + delta * delta * (c->n * n / total);
    }
    c->n = total;
}

void combine_result(const combine_acc *c, float *mean, float *var)
{
    size_t i;
    for (i = 0; i < c->count; i++) {
        mean[i] = (float)c->mean[i];
        if (var) var[i] = c->n > 1.0 ? (float)(c->m2[i] / ((c->n - 1.0) * c->n)) : 0.0f;
    }
}
