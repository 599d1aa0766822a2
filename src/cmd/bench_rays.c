/* bench_rays.c — the BVH benchmark's command: `pathlab bench-rays MESH.obj [-r RES] [-t THREADS] [--cpu-time]
 * [--bvh-quality default|split]`.
 * The rays and their timing are geometry/ray_bench.h's; this file reads the flags and the mesh and
 * prints lines of the anchor's form, for compare.sh. */
#include "cmd/bench_rays.h"
#include "sys/shown.h"
#include "geometry/ray_bench.h"
#include "scene/obj.h"
#include "sys/clock.h"
#include "sys/parallel.h"
#include "util/cli.h"
#include <stdio.h>
#include <sys/resource.h>

#define BENCH_MAX_RES 16384

/* The process's peak resident memory so far, in MB (0 where getrusage cannot say). */
static double peak_rss_mb(void)
{
    struct rusage u;
    return getrusage(RUSAGE_SELF, &u) ? 0.0 : (double)u.ru_maxrss / 1024.0;
}

/* The mesh, build and memory lines, then the three ray kinds' lines. */
static void print_result(const char *path, const mesh *m, double load_ms, const ray_bench_options *opt,
                         const ray_bench_result *r, double loaded_mb)
{
    static const char *fmt[3] = {"primary: %ld rays, %ld hits, %.2f Mrays/s\n",
                                 "diffuse: %ld rays, %ld hits, %.2f Mrays/s\n",
                                 "shadow:  %ld rays, %ld occluded, %.2f Mrays/s\n"};
    int kind;
    printf("mesh %s: %d triangles, %d vertices, load %.0f ms\n", shown(path), m->ntris, m->nverts, load_ms);
    printf("pathlab build (binned SAH%s, %d threads): %.1f ms%s (best of %d)\n",
           opt->quality == BVH_BUILD_SPLIT ? ", split triangles" : "", opt->threads, r->build_ms,
           opt->cpu_time ? " of CPU time" : "", RAY_BENCH_BUILDS);
    printf("memory: BVH and triangles %.2f bytes/triangle; peak RSS %.0f MB (%.0f MB once the mesh was read)\n",
           r->bvh_bytes / (m->ntris > 0 ? m->ntris : 1), peak_rss_mb(), loaded_mb);
    for (kind = RAY_BENCH_PRIMARY; kind <= RAY_BENCH_SHADOW; kind++)
        printf(fmt[kind], r->rays[kind], r->hits[kind], (double)r->rays[kind] / r->secs[kind] * 1e-6);
}

static int usage(void)
{
    fprintf(stderr, "usage: pathlab bench-rays MESH.obj [-r RES] [-t THREADS] [--cpu-time] [--bvh-quality default|split]\n");
    return 2;
}

int bench_rays_main(int argc, char **argv)
{
    static const char *const qualities[] = {"default", "split", NULL};   /* BVH_BUILD_DEFAULT, _SPLIT */
    ray_bench_options opt = {1024, 1, BVH_BUILD_DEFAULT, 0};
    int nwords, rc;
    const cli_flag flags[] = {
        {"-r", CLI_INT, &opt.res, 1, BENCH_MAX_RES, NULL, NULL, NULL},
        {"-t", CLI_INT, &opt.threads, 1, PARALLEL_MAX_THREADS, NULL, NULL, NULL},
        {"--cpu-time", CLI_SWITCH, &opt.cpu_time, 0, 0, NULL, NULL, NULL},
        {"--bvh-quality", CLI_CHOICE, &opt.quality, 0, 0, qualities, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}
    };
    const cli_flag *tables[2];
    const char *path;
    ray_bench_result r;
    mesh m;
    double t0, load_ms, loaded_mb;
    tables[0] = flags; tables[1] = NULL;
    if (cli_parse("bench-rays", argc, argv, tables, NULL, &path, 1, &nwords) || nwords != 1) return usage();
    t0 = clock_seconds();
    if (obj_load(path, &m, 1) != 0) return 1;
    load_ms = (clock_seconds() - t0) * 1e3;
    loaded_mb = peak_rss_mb();
    rc = ray_bench_run(m.P, m.nverts, m.tri, m.ntris, &opt, &r);
    if (rc) fprintf(stderr, "bench-rays: out of memory\n");
    else print_result(path, &m, load_ms, &opt, &r, loaded_mb);
    mesh_free(&m);
    return rc;
}
