/* big_array.h — large arrays that are filled once and read a lot (the BVH's nodes and triangles).
 * On Linux they are backed by transparent huge pages where the system allows it: a fresh array of
 * tens of MB otherwise takes one page fault per 4 KiB on first touch, and in a virtual machine each
 * fault costs microseconds (profile of the dragon's build: 12 % of its time in page faults). */
#ifndef PATHLAB_BIG_ARRAY_H
#define PATHLAB_BIG_ARRAY_H
#include <stddef.h>

/* n elements of `size` bytes aligned to `align` (a power of two, a multiple of sizeof(void *));
 * NULL when out of memory. Free with free(). */
void *big_array(size_t n, size_t size, size_t align);
#endif
