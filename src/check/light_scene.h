/* light_scene.h — the little scenes the light cases sample: LIGHT_SCENE_FIVE, five emitters of
 * different areas, colours and sides (the fourth faces -z) and a wall that does not emit, so that
 * the area, triangle and power choices all differ; LIGHT_SCENE_ONE, the one emitter (0,0,0) (1,0,0)
 * (0.3,0.8,0); LIGHT_SCENE_MANY, 40 emitters scattered in [-2, 2]^3, of sizes 0.05 to 0.5, powers
 * over three decades and normals in every direction (for the light tree: from any point, some face
 * it and some do not). Built in place, with pathlab's own light_build. */
#ifndef PATHLAB_CHECK_LIGHT_SCENE_H
#define PATHLAB_CHECK_LIGHT_SCENE_H
#include "tracer/light.h"

#define LIGHT_SCENE_MAX 40        /* triangles in the largest scene */

typedef enum { LIGHT_SCENE_FIVE, LIGHT_SCENE_ONE, LIGHT_SCENE_MANY } light_scene_id;

typedef struct {
    vec3 P[3 * LIGHT_SCENE_MAX], Ng[LIGHT_SCENE_MAX];
    float area[LIGHT_SCENE_MAX];
    int tri[3 * LIGHT_SCENE_MAX], tri_mat[LIGHT_SCENE_MAX];
    material mats[LIGHT_SCENE_MAX];
    mesh m;
    light_set ls;
} light_scene;

/* Builds scene `which` in s (s->m points into s); 0 on success. */
int light_scene_build(light_scene *s, light_scene_id which);
/* Frees what light_scene_build allocated (the light set). */
void light_scene_free(light_scene *s);
#endif
