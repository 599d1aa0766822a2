/* scene.h — what the integrator needs of a scene: the mesh, its BVH, each triangle's front
 * normal and area, and the emitters. */
#ifndef PATHLAB_SCENE_H
#define PATHLAB_SCENE_H
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "tracer/light.h"
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
    double load_seconds, bvh_seconds;   /* parse time, BVH build time */
} scene;

/* Loads the OBJ at path with the options so (NULL: the defaults) and builds everything with up to
 * `threads` threads; 0 on success (errors are printed as file:line: message). The vn are normalized. */
int scene_load(scene *sc, const char *path, const scene_opts *so, int threads, int quiet);
void scene_free(scene *sc);
/* Hit point on triangle h->tri from its barycentrics. */
vec3 scene_hit_point(const scene *sc, const hit *h);
/* The largest |coordinate| of triangle tri's corners: the scale of its rounding errors (stored). */
float scene_triangle_scale(const scene *sc, int tri);
#endif
