/* clock.h — wall-clock seconds from a monotonic clock, for timings (render, build, benchmarks). */
#ifndef PATHLAB_CLOCK_H
#define PATHLAB_CLOCK_H
#include <time.h>

/* Seconds since an arbitrary origin; only differences mean something. */
static inline double clock_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
#endif
