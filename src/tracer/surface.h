/* surface.h — the surface at a hit, as gKit makes it (docs/gkit.md): the normal interpolated from the
 * OBJ's vn (the shading normal), the material with its map_Kd and map_Ks applied at the hit's vt and
 * Ks dropped under --material diffuse, and the emitted radiance Ke times its map_Ke, on the front
 * face only. */
#ifndef PATHLAB_SURFACE_H
#define PATHLAB_SURFACE_H
#include "tracer/brdf.h"
#include "tracer/scene.h"

/* --normals: shading normals interpolated from the vn (where every corner has one), or the
 * triangle's own normal everywhere. */
typedef enum { NORMALS_SHADING, NORMALS_GEOMETRIC } normals_mode;
extern const char *const NORMALS_MODE_NAMES[];

/* The vn interpolated at hit h with its barycentrics, unit length, turned toward wo as gKit does; ng
 * (the triangle's normal, already facing wo) where a corner has none or they cancel out. */
vec3 surface_normal(const scene *sc, const hit *h, vec3 ng, vec3 wo);
/* The material at hit h: the scene's, or *own (its name not copied) holding Kd and Ks times their
 * textures at the hit's texcoord, and no Ks under BRDF_DIFFUSE. */
const material *surface_material(material *own, const scene *sc, brdf_model model, texture_filter filter, const hit *h);
/* Le seen along dir at hit h: Ke (times map_Ke) on the front face only, else 0. */
vec3 surface_emitted(const scene *sc, texture_filter filter, const hit *h, vec3 dir);
/* Le at the light sample s: its Le, times map_Ke at its point when its material has one. */
vec3 surface_Le_at(const scene *sc, texture_filter filter, const light_sample *s);
#endif
