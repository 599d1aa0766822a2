/* parallel.h — the one way pathlab uses threads: a loop over [0, n) whose iterations are handed
 * out in chunks of `grain` to `threads` threads as they come free. The caller is thread 0 and
 * waits for the others; a thread that cannot be started leaves its share to the rest, so the loop
 * always completes. Results must not depend on which thread ran an iteration (pathlab's images
 * use one random stream per pixel for that reason). */
#ifndef PATHLAB_PARALLEL_H
#define PATHLAB_PARALLEL_H

#define PARALLEL_MAX_THREADS 256

/* body(ctx, thread, begin, end) runs iterations [begin, end); `thread` in [0, threads) indexes
 * per-thread state (counters, buffers) that then needs no lock. */
typedef void parallel_body(void *ctx, int thread, int begin, int end);

/* threads is clamped by parallel_threads; grain < 1 is taken as 1. */
void parallel_for(int n, int grain, int threads, parallel_body *body, void *ctx);

/* The number of threads parallel_for runs for a request: clamped to [1, PARALLEL_MAX_THREADS], so
 * that callers can size their per-thread state. */
int parallel_threads(int requested);

/* The number of processors online, at least 1: the default number of threads. */
int parallel_default_threads(void);

/* The chunk size that gives each of `threads` threads one equal share of n (at least 1). */
int parallel_even_grain(int n, int threads);
#endif
