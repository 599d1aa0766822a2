/* combine.h — estimates of the same pixels from disjoint sets of samples, combined into the
 * estimate from all of them: means weighted by their sample counts, and the variances of the means
 * combined exactly (Chan, Golub, LeVeque 1979: the spread inside each set plus the spread between
 * their means), as if one render had drawn every sample. In double; only the float inputs round. */
#ifndef PATHLAB_COMBINE_H
#define PATHLAB_COMBINE_H
#include <stddef.h>

typedef struct {
    size_t count;      /* values (3 per pixel) */
    double n;          /* samples so far */
    double *mean, *m2; /* per value: the mean, and the sum of squared deviations from it */
} combine_acc;

/* 0, or 1 if memory ran out. */
int combine_init(combine_acc *c, size_t count);
void combine_free(combine_acc *c);
/* Adds the estimate of n samples: their means and the variances of those means (var NULL: means only). */
void combine_add(combine_acc *c, const float *mean, const float *var, double n);
/* The combined means, and the variances of the means (var may be NULL). */
void combine_result(const combine_acc *c, float *mean, float *var);
#endif
