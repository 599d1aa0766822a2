/* ray_bench.h — the work of `pathlab bench-rays`: the BVH built (the best time of a few builds) and
 * three fixed ray sets traced and timed: primary rays of a res x res camera, one diffuse bounce
 * and one shadow ray from each primary hit. It generates exactly the rays of the Embree anchor
 * (shared/tools/embree-rays/README.md: same camera, same lowbias32 hashes, same 1e-4 D offset, same
 * shadow tmax, rows shared out among the threads), so that hit counts must agree and speeds
 * compare like with like. */
#ifndef PATHLAB_RAY_BENCH_H
#define PATHLAB_RAY_BENCH_H
#include "geometry/bvh.h"

#define RAY_BENCH_BUILDS 3      /* the build time is the best of this many */

enum { RAY_BENCH_PRIMARY, RAY_BENCH_DIFFUSE, RAY_BENCH_SHADOW };

typedef struct {
    double build_ms;            /* the fastest build */
    double bvh_bytes;           /* the tree's nodes and triangle blocks (all it keeps of the mesh) */
    long rays[3], hits[3];      /* per kind; a shadow ray's hit: it is occluded */
    double secs[3];
} ray_bench_result;

/* How to run it: res x res primary rays on `threads` threads; the BVH built by bvh_build_quality
 * with `quality`; cpu_time: times are the process's CPU seconds (all threads' together) instead of
 * wall seconds, which a loaded machine inflates by the time slices it gives to other processes. */
typedef struct { int res, threads, quality, cpu_time; } ray_bench_options;

/* The triangles P[tri[3i+k]] (nverts vertices, ntris triangles). 0, or 1 when out of memory. */
int ray_bench_run(const vec3 *P, int nverts, const int *tri, int ntris, const ray_bench_options *opt,
                  ray_bench_result *out);
#endif
