/* integrator.h — the path tracer: the radiance along a camera ray, and each bounce's share of it.
 * L_k is the light that reached the eye after exactly k reflections: L0 = emitters seen directly,
 * L1 = direct light, L2 = one indirect bounce... At each surface vertex p the path adds
 *   - L_k by light sampling: a point s on an emitter with pdf1(s) and a shadow ray, and/or
 *   - L_k by direction sampling: the continuation ray from p hits an emitter at the next vertex q,
 * weighted by MIS when both are used, so emission is never counted twice. */
#ifndef PATHLAB_INTEGRATOR_H
#define PATHLAB_INTEGRATOR_H
#include <stdint.h>
#include "geometry/ray.h"
#include "sampler/sampler.h"
#include "tracer/scene.h"
#include "tracer/surface.h"

typedef enum { DIR_UNIFORM, DIR_COSINE, DIR_BRDF } dir_strategy;                /* --dir */
typedef enum { DIRECT_LIGHT, DIRECT_BRDF, DIRECT_MIS_BALANCE, DIRECT_MIS_POWER } direct_strategy; /* --direct */
/* Their names on the command line (--dir, --direct), in enum order, NULL-terminated. */
extern const char *const DIR_STRATEGY_NAMES[];
extern const char *const DIRECT_STRATEGY_NAMES[];

/* The hard bounce cap of every path, whatever --bounces says: Kd >= 1 (or Kd + Ks > 1) and
 * --rr off would otherwise never end a path. It is also the largest finite last bounce. */
#define BOUNCES_CAP 1000
/* bmax of a path with no last bounce (--bounces A:inf): only the roulette or BOUNCES_CAP ends it. */
#define BOUNCES_NO_END 1000000

typedef struct {
    light_strategy light;
    dir_strategy dir;
    direct_strategy direct;
    int bmin, bmax;           /* L_bmin + ... + L_bmax, 0 <= bmin <= bmax <= BOUNCES_CAP, or bmax = BOUNCES_NO_END */
    int rr_depth;             /* Russian roulette after this many bounces; -1: off */
    float rr_below;           /* T > 0: the roulette thins paths whose throughput max(beta) is below T
                               * (--rr-below, or the sampler's default: render_rr_below) */
    brdf_model material;      /* --material */
    normals_mode normals;     /* --normals */
    texture_filter filter;    /* --texture-filter */
} integrator_opts;

typedef struct {
    uint64_t camera_rays, continuation_rays, shadow_rays;
    uint64_t shadow_rays_spared;   /* not traced: nothing could block them (visibility.h) */
    uint64_t paths_cut;       /* paths that reached BOUNCES_CAP bounces, cut there (--bounces A:inf) */
} trace_stats;

/* Returns the radiance L_bmin + ... + L_bmax along the camera ray, summed in path order, drawing its
 * numbers from smp vertex by vertex, each use by name (sampler.h: sampler_vertex, sampler_light...).
 * If Lk is not NULL it has o->bmax + 1 entries and receives Lk[k] = L_k for k = 0..bmax (0 outside
 * bmin..bmax). Counts the rays it traces in *st. */
vec3 integrate(const scene *sc, const integrator_opts *o, const ray *camera, sampler *smp, vec3 *Lk, trace_stats *st);
#endif
