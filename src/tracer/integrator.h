/* integrator.h — the path tracer: the radiance along a camera ray, split by bounce.
 * L_k is the light that reached the eye after exactly k reflections: L0 = emitters seen directly,
 * L1 = direct light, L2 = one indirect bounce... At each surface vertex x_k the path adds
 *   - L_k by light sampling: a point s on an emitter with pdf1(s) and a shadow ray, and/or
 *   - L_k by direction sampling: the continuation ray from x_k hits an emitter,
 * weighted by MIS when both are used, so emission is never counted twice. */
#ifndef PATHLAB_INTEGRATOR_H
#define PATHLAB_INTEGRATOR_H
#include <stdint.h>
#include "math/rng.h"
#include "tracer/scene.h"

typedef enum { DIR_UNIFORM, DIR_COSINE, DIR_BRDF } dir_strategy;                /* --dir */
typedef enum { DIRECT_LIGHT, DIRECT_BRDF, DIRECT_MIS_BALANCE, DIRECT_MIS_POWER } direct_strategy; /* --direct */
/* Their names on the command line (--dir, --direct), in enum order, NULL-terminated. */
extern const char *const DIR_STRATEGY_NAMES[];
extern const char *const DIRECT_STRATEGY_NAMES[];

#define BOUNCES_INF 1000000   /* --bounces A:inf */

typedef struct {
    light_strategy light;
    dir_strategy dir;
    direct_strategy direct;
    int bmin, bmax;           /* render L_bmin + ... + L_bmax */
    int rr_depth;             /* Russian roulette after this many bounces; -1: off */
    int split;                /* 0: L[0] = the total; 1: also L[1 + k - bmin] = L_k */
} integrator_opts;

typedef struct {
    uint64_t camera_rays, continuation_rays, shadow_rays;
    uint64_t nonfinite;       /* samples that were NaN or infinite (and were dropped) */
} trace_stats;

/* Adds the radiance along r (a camera ray) to L[0], and with opts->split each L_k to L[1 + k - bmin]. */
void integrate(const scene *s, const integrator_opts *o, const ray *r, pcg32 *rng, vec3 *L, trace_stats *st);
#endif
