/* big_array.c — posix_memalign, then madvise(MADV_HUGEPAGE) over the whole 2 MiB pages inside the
 * block. madvise is not POSIX: it needs _DEFAULT_SOURCE, and where MADV_HUGEPAGE does not exist
 * (not Linux) the advice is left out. The advice changes no value, only how pages are mapped, and a
 * refusal (THP disabled, an old kernel) is harmless, so its result is ignored. */
#define _DEFAULT_SOURCE
#include "sys/big_array.h"
#include <stdint.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#define HUGE_PAGE ((size_t)2 << 20)

void *big_array(size_t n, size_t size, size_t align)
{
    void *p = NULL;
    size_t bytes = (n ? n : 1) * size;
    if (n > (size_t)-1 / size || posix_memalign(&p, align, bytes) != 0) return NULL;
#if defined(MADV_HUGEPAGE)
    if (bytes >= 2 * HUGE_PAGE) {
        uintptr_t lo = ((uintptr_t)p + HUGE_PAGE - 1) & ~(uintptr_t)(HUGE_PAGE - 1);
        uintptr_t hi = ((uintptr_t)p + bytes) & ~(uintptr_t)(HUGE_PAGE - 1);
        if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    }
#endif
    return p;
}
