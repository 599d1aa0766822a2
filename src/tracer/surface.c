/* surface.c — what a hit's surface is made of, as gKit makes it (docs/gkit.md): the shading normal
 * interpolated from the vn, the material with its textures at the hit's texcoord, the emission. */
#include "tracer/surface.h"

const char *const NORMALS_MODE_NAMES[] = {"shading", "geometric", 0};

/* The weights of a triangle's corners at barycentrics (u, v) (scene_hit_point's: a (1-u-v) + b u + c v). */
static vec3 corner_weights(float u, float v) { return v3(1.0f - u - v, u, v); }

vec3 surface_normal(const scene *sc, const hit *h, vec3 ng, vec3 wo)
{
    const int *id = sc->m.tri_n ? sc->m.tri_n + 3 * h->tri : NULL;
    vec3 w = corner_weights(h->u, h->v), n;
    float len;
    if (!id || id[0] < 0 || id[1] < 0 || id[2] < 0) return ng;
    n = v3_add(v3_add(v3_scale(sc->m.N[id[0]], w.x), v3_scale(sc->m.N[id[1]], w.y)), v3_scale(sc->m.N[id[2]], w.z));
    len = v3_length(n);
    if (!(len > 1e-6f) || !isfinite(len)) return ng;
    n = v3_scale(n, 1.0f / len);
    return v3_dot(n, wo) < 0.0f ? v3_scale(n, -1.0f) : n;
}

/* The texcoord (u, v) of the hit in *uv; 0 if a corner of its triangle has none. */
static int hit_texcoord(const scene *sc, int tri, vec3 w, float uv[2])
{
    const int *id = sc->m.tri_t ? sc->m.tri_t + 3 * tri : NULL;
    const float *T = sc->m.T;
    if (!id || id[0] < 0 || id[1] < 0 || id[2] < 0) return 0;
    uv[0] = T[2 * id[0]] * w.x + T[2 * id[1]] * w.y + T[2 * id[2]] * w.z;
    uv[1] = T[2 * id[0] + 1] * w.x + T[2 * id[1] + 1] * w.y + T[2 * id[2] + 1] * w.z;
    return 1;
}

/* c times texture tex (0: none) at uv, as gKit multiplies a colour by its texture. */
static vec3 mapped(const scene *sc, texture_filter filter, vec3 c, int tex, const float uv[2])
{
    return tex ? v3_mul(c, texture_lookup(&sc->m.textures[tex - 1], uv[0], uv[1], filter)) : c;
}

const material *surface_material(material *own, const scene *sc, brdf_model model, texture_filter filter, const hit *h)
{
    const material *m = &sc->m.mats[sc->m.tri_mat[h->tri]];
    float uv[2];
    int drop_Ks = model == BRDF_DIFFUSE && !v3_is_zero(m->Ks), textured = m->tex_Kd || m->tex_Ks;
    if (!drop_Ks && !textured) return m;
    own->Kd = m->Kd, own->Ks = drop_Ks ? v3(0, 0, 0) : m->Ks, own->Ke = m->Ke, own->Ns = m->Ns;
    if (textured && hit_texcoord(sc, h->tri, corner_weights(h->u, h->v), uv)) {
        own->Kd = mapped(sc, filter, own->Kd, m->tex_Kd, uv);
        own->Ks = mapped(sc, filter, own->Ks, drop_Ks ? 0 : m->tex_Ks, uv);
    }
    return own;
}

vec3 surface_Le_at(const scene *sc, texture_filter filter, const light_sample *s)
{
    int tri = sc->lights.e[s->emitter].tri;
    const material *m = &sc->m.mats[sc->m.tri_mat[tri]];
    vec3 pos = s->pos;
    const int *t = sc->m.tri + 3 * tri;
    vec3 a, e1, e2, d, w;
    float d11, d12, d22, dp1, dp2, det, uv[2];
    if (!m->tex_Ke) return s->Le;
    /* the barycentrics of pos: least squares in the triangle's plane */
    a = sc->m.P[t[0]], e1 = v3_sub(sc->m.P[t[1]], a), e2 = v3_sub(sc->m.P[t[2]], a), d = v3_sub(pos, a);
    d11 = v3_dot(e1, e1), d12 = v3_dot(e1, e2), d22 = v3_dot(e2, e2), dp1 = v3_dot(d, e1), dp2 = v3_dot(d, e2);
    det = d11 * d22 - d12 * d12;
    w = corner_weights((d22 * dp1 - d12 * dp2) / det, (d11 * dp2 - d12 * dp1) / det);
    return hit_texcoord(sc, tri, w, uv) ? mapped(sc, filter, m->Ke, m->tex_Ke, uv) : m->Ke;
}

vec3 surface_emitted(const scene *sc, texture_filter filter, const hit *h, vec3 dir)
{
    const material *m = &sc->m.mats[sc->m.tri_mat[h->tri]];
    float uv[2];
    if (!(v3_dot(sc->Ng[h->tri], dir) < 0.0f)) return v3(0, 0, 0);
    if (!m->tex_Ke || !hit_texcoord(sc, h->tri, corner_weights(h->u, h->v), uv)) return m->Ke;
    return mapped(sc, filter, m->Ke, m->tex_Ke, uv);
}

