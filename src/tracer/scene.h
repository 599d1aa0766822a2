/* scene.h — what the integrator needs of a scene: the mesh, its BVH, each triangle's front
 * normal and area, and the emitters. */
#ifndef PATHLAB_SCENE_H
#define PATHLAB_SCENE_H
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "tracer/light.h"
#include "scene/mesh.h"

typedef struct {
    mesh m;
    bvh *accel;
    vec3 *Ng;        /* unit geometric normal per triangle, (b-a) x (c-a): the front side */
    float *area;
    float *scale;    /* triangle_scale per triangle (for offset_ray_origin): computed once, at load */
    light_set lights;
    double load_seconds, bvh_seconds;   /* parse time, BVH build time */
} scene;

/* Loads the OBJ at path and builds everything with up to `threads` threads; 0 on success
 * (errors are printed as file:line: message). */
int scene_load(scene *sc, const char *path, int threads, int quiet);
void scene_free(scene *sc);
/* Hit point on triangle h->tri from its barycentrics. */
vec3 scene_hit_point(const scene *sc, const hit *h);
/* The largest |coordinate| of triangle tri's corners: the scale of its rounding errors (stored). */
float scene_triangle_scale(const scene *sc, int tri);
#endif
