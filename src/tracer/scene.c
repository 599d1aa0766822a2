/* scene.c — from an OBJ file to a scene ready to trace. */
#include "tracer/scene.h"
#include "sys/shown.h"
#include "sys/clock.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int triangle_geometry(scene *sc)
{
    const mesh *m = &sc->m;
    int i;
    sc->Ng = malloc(sizeof(vec3) * (size_t)m->ntris);
    sc->area = malloc(sizeof(float) * (size_t)m->ntris);
    sc->scale = malloc(sizeof(float) * (size_t)m->ntris);
    if (!sc->Ng || !sc->area || !sc->scale) return 1;
    for (i = 0; i < m->ntris; i++) {
        const int *t = m->tri + 3 * i;
        vec3 c = v3_cross(v3_sub(m->P[t[1]], m->P[t[0]]), v3_sub(m->P[t[2]], m->P[t[0]]));
        float len = v3_length(c);
        sc->area[i] = 0.5f * len;
        sc->Ng[i] = v3_scale(c, 1.0f / len);   /* the parser dropped zero-area triangles */
        sc->scale[i] = triangle_scale(m->P[t[0]], m->P[t[1]], m->P[t[2]]);
    }
    return 0;
}

/* The vn made unit length (a zero one stays zero: the shading normal then falls back on Ng). */
static void normalize_normals(mesh *m)
{
    int i;
    for (i = 0; i < m->nnormals; i++) {
        float len = v3_length(m->N[i]);
        if (len > 0.0f && isfinite(len)) m->N[i] = v3_scale(m->N[i], 1.0f / len);
        else m->N[i] = v3(0, 0, 0);
    }
}

/* Kd + Ks > 1, said once for the whole scene: not under --material diffuse, which ignores Ks. */
static void warn_energy(const mesh *m, brdf_model model, int quiet)
{
    if (quiet || model == BRDF_DIFFUSE || m->n_energy == 0) return;
    fprintf(stderr, "%s: it creates energy (the image of a closed scene has no finite limit: README.md, Materials)", m->energy_note);
    if (m->n_energy > 1) fprintf(stderr, "; and %d other material%s", m->n_energy - 1, m->n_energy > 2 ? "s" : "");
    fprintf(stderr, "; --material diffuse ignores Ks\n");
}

/* The pairs of sc->wholly_seen and sc->near_blocker (visibility.h), for the emitters' triangles; 0 on success. */
static int wholly_seen_pairs(scene *sc)
{
    int *emitter_tri = malloc(sizeof(int) * (size_t)(sc->lights.n > 0 ? sc->lights.n : 1)), i, fails;
    sc->near_blocker = calloc((size_t)(sc->lights.n > 0 ? sc->lights.n : 1), 1);
    if (!emitter_tri || !sc->near_blocker) { free(emitter_tri); return 1; }
    for (i = 0; i < sc->lights.n; i++) emitter_tri[i] = sc->lights.e[i].tri;
    fails = pair_visibility_build(&sc->wholly_seen, sc->m.P, sc->m.tri, sc->m.ntris, emitter_tri, sc->lights.n);
    near_blockers_find(sc->near_blocker, sc->accel, sc->m.P, sc->m.tri, emitter_tri, sc->lights.n);
    free(emitter_tri);
    return fails;
}

int scene_load(scene *sc, const char *path, const scene_opts *so, int threads, int quiet)
{
    double t0;
    scene_opts none;
    memset(sc, 0, sizeof *sc);   /* so that scene_free is safe wherever loading stops */
    memset(&none, 0, sizeof none);
    if (!so) so = &none;
    sc->emitter_prob = 1.0f;
    t0 = clock_seconds();
    if (obj_load_with(path, &sc->m, &so->obj, quiet)) return 1;
    sc->load_seconds = clock_seconds() - t0;
    normalize_normals(&sc->m);
    warn_energy(&sc->m, so->model, quiet);
    if (triangle_geometry(sc) || light_build(&sc->lights, &sc->m, sc->Ng, sc->area)) {
        fprintf(stderr, "%s: out of memory\n", shown(path));
        scene_free(sc);
        return 1;
    }
    t0 = clock_seconds();
    sc->accel = bvh_build(sc->m.P, sc->m.tri, sc->m.ntris, threads);
    sc->bvh_seconds = clock_seconds() - t0;
    if (!sc->accel) {
        fprintf(stderr, "%s: out of memory building the BVH\n", shown(path));
        scene_free(sc);
        return 1;
    }
    t0 = clock_seconds();
    if (wholly_seen_pairs(sc)) {
        fprintf(stderr, "%s: out of memory finding the triangles that see a light wholly\n", shown(path));
        scene_free(sc);
        return 1;
    }
    sc->pairs_seconds = clock_seconds() - t0;
    return 0;
}

void scene_free(scene *sc)
{
    bvh_free(sc->accel);
    light_free(&sc->lights);
    pair_visibility_free(&sc->wholly_seen);
    free(sc->near_blocker);
    sky_free(&sc->sky);
    free(sc->Ng);
    free(sc->area);
    free(sc->scale);
    mesh_free(&sc->m);
}

int scene_add_sky(scene *sc, const sky_spec *spec)
{
    double emitters = 0.0, sky_power, radius;
    vec3 lo, hi;
    int i;
    sky_free(&sc->sky);
    if (sky_build(&sc->sky, spec)) return 1;
    if (!sky_present(&sc->sky)) {
        sky_free(&sc->sky);
        sc->sky_prob = 0.0, sc->emitter_prob = 1.0f;
        return 0;
    }
    for (i = 0; i < sc->lights.n; i++) emitters += PI * sc->lights.e[i].area * fmax(0.0, luminance(sc->lights.e[i].Le));
    mesh_bounds(&sc->m, &lo, &hi);
    radius = 0.5 * v3_length(v3_sub(hi, lo));
    sky_power = PI * radius * radius * sc->sky.integral;
    if (!(emitters > 0.0)) sc->sky_prob = 1.0;   /* no emitters: the sky is the only light */
    else sc->sky_prob = sky_power / (sky_power + emitters);
    sc->emitter_prob = (float)(1.0 - sc->sky_prob);
    return 0;
}

vec3 scene_hit_point(const scene *sc, const hit *h)
{
    const int *t = sc->m.tri + 3 * h->tri;
    vec3 a = sc->m.P[t[0]], b = sc->m.P[t[1]], c = sc->m.P[t[2]];
    return v3_add(a, v3_add(v3_scale(v3_sub(b, a), h->u), v3_scale(v3_sub(c, a), h->v)));
}

float scene_triangle_scale(const scene *sc, int tri)
{
    return sc->scale[tri];
}
