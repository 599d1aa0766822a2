/* scene.c — from an OBJ file to a scene ready to trace. */
#include "tracer/scene.h"
#include "sys/clock.h"
#include "scene/obj.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int triangle_geometry(scene *s)
{
    const mesh *m = &s->m;
    int i;
    s->Ng = malloc(sizeof(vec3) * (size_t)m->ntris);
    s->area = malloc(sizeof(float) * (size_t)m->ntris);
    if (!s->Ng || !s->area) return 1;
    for (i = 0; i < m->ntris; i++) {
        const int *t = m->tri + 3 * i;
        vec3 c = v3_cross(v3_sub(m->P[t[1]], m->P[t[0]]), v3_sub(m->P[t[2]], m->P[t[0]]));
        float len = v3_length(c);
        s->area[i] = 0.5f * len;
        s->Ng[i] = v3_scale(c, 1.0f / len);   /* the parser dropped zero-area triangles */
    }
    return 0;
}

int scene_load(scene *s, const char *path, int threads, int quiet)
{
    double t0;
    memset(s, 0, sizeof *s);   /* so that scene_free is safe wherever loading stops */
    t0 = clock_seconds();
    if (obj_load(path, &s->m, quiet)) return 1;
    s->load_seconds = clock_seconds() - t0;
    if (triangle_geometry(s) || light_build(&s->lights, &s->m, s->Ng, s->area)) {
        fprintf(stderr, "%s: out of memory\n", path);
        scene_free(s);
        return 1;
    }
    t0 = clock_seconds();
    s->accel = bvh_build(s->m.P, s->m.tri, s->m.ntris, threads);
    s->bvh_seconds = clock_seconds() - t0;
    if (!s->accel) {
        fprintf(stderr, "%s: out of memory building the BVH\n", path);
        scene_free(s);
        return 1;
    }
    return 0;
}

void scene_free(scene *s)
{
    bvh_free(s->accel);
    light_free(&s->lights);
    free(s->Ng);
    free(s->area);
    mesh_free(&s->m);
}

vec3 scene_hit_point(const scene *s, const hit *h)
{
    const int *t = s->m.tri + 3 * h->tri;
    vec3 a = s->m.P[t[0]], b = s->m.P[t[1]], c = s->m.P[t[2]];
    return v3_add(a, v3_add(v3_scale(v3_sub(b, a), h->u), v3_scale(v3_sub(c, a), h->v)));
}

float scene_triangle_scale(const scene *s, int tri)
{
    const int *t = s->m.tri + 3 * tri;
    return triangle_scale(s->m.P[t[0]], s->m.P[t[1]], s->m.P[t[2]]);
}
