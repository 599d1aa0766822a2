/* scene.h — what the integrator needs of a scene: the mesh, its BVH, each triangle's front
 * normal and area, the emitters, and the sky (--sky). Light sampling chooses between the sky and
 * the emitters by power: an emitter's is pi x area x luminance(Ke) (one-sided, Lambertian), the
 * sky's is the flux it sends into the scene's bounding sphere of radius R, pi R^2 x the integral of
 * its luminance over the sphere (= pi x 4 pi R^2 x its mean luminance: each point of the sphere
 * receives pi x the mean from the inner hemisphere); then an emitter by --light. In a small scene,
 * the pairs of a triangle and an emitter that nothing can come between (visibility.h). */
#ifndef PATHLAB_SCENE_H
#define PATHLAB_SCENE_H
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "geometry/visibility.h"
#include "tracer/light.h"
#include "tracer/sky.h"
#include "scene/mesh.h"
#include "scene/obj.h"
#include "tracer/brdf.h"

/* What the command line says of loading: --mtl and --texture-decode (obj), and --material, for the
 * warning about Kd + Ks > 1 (none with diffuse, which ignores Ks). */
typedef struct {
    mtl_opts obj;
    brdf_model model;
} scene_opts;

typedef struct {
    mesh m;
    bvh *accel;
    vec3 *Ng;        /* unit geometric normal per triangle, (b-a) x (c-a): the front side */
    float *area;
    float *scale;    /* triangle_scale per triangle (for offset_ray_origin): computed once, at load */
    light_set lights;
    pair_visibility wholly_seen;   /* (triangle, emitter) pairs no shadow ray between can be blocked */
    unsigned char *near_blocker;   /* per emitter: 1 if a triangle stands (or may) within a shadow
                                      ray's end offset of it, in front: its shadow rays end on it
                                      (NULL, in a scene made by hand: every emitter) */
    sky sky;         /* the light from infinitely far away; none (w = 0) without --sky */
    double sky_prob; /* the probability that light sampling chooses the sky (the rest: an emitter) */
    float emitter_prob;   /* 1 - sky_prob, rounded once */
    double load_seconds, bvh_seconds, pairs_seconds;   /* parse time, BVH build time, wholly_seen's */
} scene;

/* Loads the OBJ at path with the options so (NULL: the defaults) and builds everything with up to
 * `threads` threads; 0 on success (errors are printed as file:line: message). The vn are normalized. */
int scene_load(scene *sc, const char *path, const scene_opts *so, int threads, int quiet);
void scene_free(scene *sc);
/* Puts the sky of spec (sky.h) over the loaded scene and sets the choice between it and the
 * emitters; 0 on success, 1 after printing why. A black sky is no sky. */
int scene_add_sky(scene *sc, const sky_spec *spec);
/* 1 if anything gives light: an emitter, or a sky. */
static inline int scene_has_light(const scene *sc) { return sc->lights.n > 0 || sky_present(&sc->sky); }
/* Hit point on triangle h->tri from its barycentrics. */
vec3 scene_hit_point(const scene *sc, const hit *h);
/* The largest |coordinate| of triangle tri's corners: the scale of its rounding errors (stored). */
float scene_triangle_scale(const scene *sc, int tri);
#endif
