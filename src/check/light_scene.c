/* light_scene.c — the test scenes of the light cases (light_scene.h). */
#include "check/light_scene.h"
#include "math/rng.h"
#include <string.h>

/* Scene FIVE: five emitters of different areas, colours and sides (the fourth faces -z), a wall. */
static const float FIVE_P[18][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},       {2, 0, 0},    {4, 0, 0},       {2, 1, 0},
                                    {0, 2, 0}, {0.3f, 2, 0}, {0, 2.2f, 0}, {0, 0, 1},    {0, 1, 1},       {3, 0, 1},
                                    {5, 5, 5}, {7, 5, 5},    {5, 7, 5},    {0, 0, 3},    {0, 0.01f, 3},   {0.02f, 0, 3}};
static const float FIVE_KE[6][3] = {{1, 1, 1}, {5, 0, 0}, {0, 0, 20}, {0.2f, 0.5f, 0.1f}, {0, 0, 0}, {100, 100, 100}};
static const float ONE_P[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.3f, 0.8f, 0}};

/* Scene MANY: emitter i, a triangle about a random centre, facing a random direction, of random
 * size, colour and power (a fixed stream: the same scene every time) */
static void many_emitter(pcg32 *rng, vec3 *P, vec3 *Ke)
{
    vec3 c, n;
    frame f;
    float size, z, phi, power;
    c = v3(4.0f * pcg32_float(rng) - 2.0f, 4.0f * pcg32_float(rng) - 2.0f, 4.0f * pcg32_float(rng) - 2.0f);
    z = 2.0f * pcg32_float(rng) - 1.0f, phi = 2.0f * PI_F * pcg32_float(rng);
    n = v3(sqrtf(1.0f - z * z) * cosf(phi), sqrtf(1.0f - z * z) * sinf(phi), z);
    f = frame_from_normal(n);
    size = 0.05f + 0.45f * pcg32_float(rng);
    P[0] = v3_madd(c, f.t, size);   /* counterclockwise about n: the front faces n */
    P[1] = v3_madd(v3_madd(c, f.t, -0.5f * size), f.b, 0.866f * size);
    P[2] = v3_madd(v3_madd(c, f.t, -0.5f * size), f.b, -0.866f * size);
    power = powf(10.0f, 3.0f * pcg32_float(rng) - 1.0f);
    *Ke = v3(power * (0.2f + pcg32_float(rng)), power * (0.2f + pcg32_float(rng)), power * (0.2f + pcg32_float(rng)));
}

int light_scene_build(light_scene *s, light_scene_id which)
{
    int i, ntris = which == LIGHT_SCENE_FIVE ? 6 : which == LIGHT_SCENE_MANY ? LIGHT_SCENE_MAX : 1;
    vec3 many_Ke[LIGHT_SCENE_MAX];
    pcg32 rng;
    memset(s, 0, sizeof *s);
    pcg32_init(&rng, 2018, 0);
    for (i = 0; i < 3 * ntris; i++) {
        const float *p = which == LIGHT_SCENE_FIVE ? FIVE_P[i] : ONE_P[i % 3];
        if (which == LIGHT_SCENE_MANY && i % 3 == 0) many_emitter(&rng, &s->P[i], &many_Ke[i / 3]);
        if (which != LIGHT_SCENE_MANY) s->P[i] = v3(p[0], p[1], p[2]);
        s->tri[i] = i;
    }
    for (i = 0; i < ntris; i++) {
        vec3 c = v3_cross(v3_sub(s->P[3 * i + 1], s->P[3 * i]), v3_sub(s->P[3 * i + 2], s->P[3 * i]));
        const float *Ke = which == LIGHT_SCENE_FIVE ? FIVE_KE[i] : FIVE_KE[0];
        s->area[i] = 0.5f * v3_length(c);
        s->Ng[i] = v3_normalize(c);
        s->mats[i].Kd = v3(0.5f, 0.5f, 0.5f);
        s->mats[i].Ke = which == LIGHT_SCENE_MANY ? many_Ke[i] : v3(Ke[0], Ke[1], Ke[2]);
        s->tri_mat[i] = i;
    }
    s->m.P = s->P, s->m.nverts = 3 * ntris, s->m.tri = s->tri, s->m.tri_mat = s->tri_mat, s->m.ntris = ntris;
    s->m.mats = s->mats, s->m.nmats = ntris;
    return light_build(&s->ls, &s->m, s->Ng, s->area);
}

void light_scene_free(light_scene *s) { light_free(&s->ls); }
