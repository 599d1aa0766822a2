/* parallel.c — parallel_for: a shared counter under a mutex hands out chunks; C99 has no atomics. */
#include "sys/parallel.h"
#include <pthread.h>
#include <unistd.h>

typedef struct {
    parallel_body *body;
    void *ctx;
    int n, grain, next;
    pthread_mutex_t lock;
} loop;

typedef struct { loop *l; int thread; } worker_arg;

/* Takes chunks until none is left. */
static void run_chunks(loop *l, int thread)
{
    for (;;) {
        int begin, end;
        pthread_mutex_lock(&l->lock);
        begin = l->next;
        end = l->n - begin < l->grain ? l->n : begin + l->grain;
        l->next = end;
        pthread_mutex_unlock(&l->lock);
        if (begin >= end) return;
        l->body(l->ctx, thread, begin, end);
    }
}

static void *worker_main(void *p)
{
    worker_arg *a = p;
    run_chunks(a->l, a->thread);
    return 0;
}

void parallel_for(int n, int grain, int threads, parallel_body *body, void *ctx)
{
    pthread_t th[PARALLEL_MAX_THREADS];
    worker_arg arg[PARALLEL_MAX_THREADS];
    int started[PARALLEL_MAX_THREADS];
    loop l;
    int t;
    if (n <= 0) return;
    threads = parallel_threads(threads);
    l.body = body, l.ctx = ctx, l.n = n, l.grain = grain < 1 ? 1 : grain, l.next = 0;
    pthread_mutex_init(&l.lock, 0);
    for (t = 1; t < threads; t++) {
        arg[t].l = &l, arg[t].thread = t;
        started[t] = pthread_create(&th[t], 0, worker_main, &arg[t]) == 0;
    }
    run_chunks(&l, 0);
    for (t = 1; t < threads; t++)
        if (started[t]) pthread_join(th[t], 0);
    pthread_mutex_destroy(&l.lock);
}

int parallel_threads(int requested)
{
    return requested < 1 ? 1 : requested > PARALLEL_MAX_THREADS ? PARALLEL_MAX_THREADS : requested;
}

int parallel_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);   /* -1 if unknown: parallel_threads makes it 1 */
    return parallel_threads(n > PARALLEL_MAX_THREADS ? PARALLEL_MAX_THREADS : (int)n);
}

int parallel_even_grain(int n, int threads)
{
    int g;
    if (threads < 1) threads = 1;
    g = (int)(((long long)n + threads - 1) / threads);
    return g < 1 ? 1 : g;
}
