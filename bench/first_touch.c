/* first_touch.c — what fresh memory costs on this machine: the time to write one byte per 4 KiB
 * page of a block of MB megabytes, in 3 allocations a process, with or without MADV_HUGEPAGE (as
 * src/sys/big_array.c asks), and a pause between one block's free and the next allocation. The
 * build of a big mesh writes about 1.2 GB of fresh memory at 16M triangles (bench/log.md, "The
 * blocks written over the primrefs; fresh pages, huge or not").
 *
 *     cc -O2 -std=c99 -Wall -o first_touch bench/first_touch.c
 *     ./first_touch MB HUGE PAUSE     e.g. ./first_touch 1024 1 3
 */
#define _DEFAULT_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Seconds to write one byte in each 4 KiB page of p[0, n). */
static double touch(volatile char *p, size_t n, char value)
{
    double t0 = seconds();
    size_t i;
    for (i = 0; i < n; i += 4096) p[i] = value;
    return seconds() - t0;
}

int main(int argc, char **argv)
{
    size_t n;
    int huge, pause_s, round;
    if (argc != 4) {
        fprintf(stderr, "usage: %s MB HUGE(0|1) PAUSE_SECONDS\n", argv[0]);
        return 2;
    }
    n = (size_t)atol(argv[1]) << 20;
    huge = atoi(argv[2]);
    pause_s = atoi(argv[3]);
    for (round = 0; round < 3; round++) {
        void *p = NULL;
        double first, again;
        if (posix_memalign(&p, (size_t)2 << 20, n) != 0) { fprintf(stderr, "out of memory\n"); return 1; }
#if defined(MADV_HUGEPAGE)
        if (huge) (void)madvise(p, n, MADV_HUGEPAGE);
#endif
        first = touch(p, n, 1);
        again = touch(p, n, 2);
        printf("%zu MB, huge pages %s: first touch %.3f s (%.2f GB/s), again %.4f s\n", n >> 20,
               huge ? "asked" : "not asked", first, (double)n / first * 1e-9, again);
        free(p);
        if (pause_s > 0) sleep((unsigned)pause_s);
    }
    return 0;
}
