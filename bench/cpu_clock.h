/* bench/cpu_clock.h — forced into embree_rays.c when bench/scale.sh builds build/embree-rays-cpu
 * (SCALE_CLOCK=cpu): its timer then reads the process's CPU time instead of the wall clock, as
 * `pathlab bench-rays --cpu-time` does, so that the two compare on a machine loaded by other
 * processes (CPU seconds do not count the time slices given to others; wall seconds do). */
#define _POSIX_C_SOURCE 200809L
#include <time.h>
#undef CLOCK_MONOTONIC
#define CLOCK_MONOTONIC CLOCK_PROCESS_CPUTIME_ID
