/* mesh.c — freeing a mesh and measuring it. */
#include "scene/mesh.h"
#include <stdlib.h>
#include <string.h>

void mesh_free(mesh *m)
{
    if (!m) return;
    free(m->P);
    free(m->tri);
    free(m->tri_mat);
    free(m->mats);
    free(m->mat_slots);
    free(m->N);
    free(m->T);
    free(m->tri_n);
    free(m->tri_t);
    while (m->ntextures > 0) texture_free(&m->textures[--m->ntextures]);
    free(m->textures);
    while (m->nmtl_files > 0) free(m->mtl_files[--m->nmtl_files]);
    free(m->mtl_files);
    memset(m, 0, sizeof *m); /* a second mesh_free, or a look at the counts, stays harmless */
}

void mesh_bounds(const mesh *m, vec3 *lo, vec3 *hi)
{
    int i;
    if (m->ntris == 0) { /* nothing to bound: an empty box at the origin rather than inf/-inf */
        *lo = *hi = v3(0.0f, 0.0f, 0.0f);
        return;
    }
    *lo = *hi = m->P[m->tri[0]];
    /* Only vertices used by triangles count: OBJ files often carry unused ones (points, lines). */
    for (i = 1; i < 3 * m->ntris; i++) {
        vec3 p = m->P[m->tri[i]];
        *lo = v3_min(*lo, p);
        *hi = v3_max(*hi, p);
    }
}

/* 1 if triangle i emits nothing and has an edge of length >= len */
static int is_backdrop(const mesh *m, int i, float len)
{
    const int *t = m->tri + 3 * i;
    int k;
    if (!v3_is_zero(m->mats[m->tri_mat[i]].Ke)) return 0;
    for (k = 0; k < 3; k++)
        if (v3_length(v3_sub(m->P[t[k]], m->P[t[(k + 1) % 3]])) >= len) return 1;
    return 0;
}

void mesh_framing_bounds(const mesh *m, vec3 *lo, vec3 *hi)
{
    vec3 olo = v3(0, 0, 0), ohi = olo;
    float quarter;
    int i, k, objects = 0;
    mesh_bounds(m, lo, hi);
    quarter = 0.25f * v3_length(v3_sub(*hi, *lo));
    for (i = 0; i < m->ntris; i++) {
        if (is_backdrop(m, i, quarter)) continue;
        for (k = 0; k < 3; k++) {
            vec3 p = m->P[m->tri[3 * i + k]];
            olo = objects ? v3_min(olo, p) : p;
            ohi = objects++ ? v3_max(ohi, p) : p;
        }
    }
    if (objects && v3_length(v3_sub(ohi, olo)) <= quarter) *lo = olo, *hi = ohi;
}

uint64_t fingerprint_bytes(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    size_t i;
    for (i = 0; i < n; i++) h = (h ^ p[i]) * 0x100000001B3ULL;
    return h;
}

/* The vn, vt and textures of the triangles (none: h unchanged). */
static uint64_t mesh_fingerprint_more(const mesh *m, uint64_t h)
{
    int i;
    for (i = 0; m->tri_n && i < 3 * m->ntris; i++)
        if (m->tri_n[i] >= 0) h = fingerprint_bytes(h, &m->N[m->tri_n[i]], sizeof(vec3));
    for (i = 0; m->tri_t && i < 3 * m->ntris; i++)
        if (m->tri_t[i] >= 0) h = fingerprint_bytes(h, &m->T[2 * m->tri_t[i]], 2 * sizeof(float));
    for (i = 0; i < m->ntextures; i++) {
        const texture *t = &m->textures[i];
        h = fingerprint_bytes(h, t->rgb, 3 * (size_t)t->w * (size_t)t->h * sizeof(float));
        h = fingerprint_bytes(h, &t->w, sizeof t->w);
        h = fingerprint_bytes(h, &t->h, sizeof t->h);
    }
    return h;
}

uint64_t mesh_fingerprint(const mesh *m)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    int i, k;
    for (i = 0; i < m->ntris; i++) {
        for (k = 0; k < 3; k++) h = fingerprint_bytes(h, &m->P[m->tri[3 * i + k]], sizeof(vec3));
        h = fingerprint_bytes(h, &m->tri_mat[i], sizeof(int));
    }
    for (i = 0; i < m->nmats; i++) {
        const material *t = &m->mats[i];
        h = fingerprint_bytes(h, &t->Kd, sizeof t->Kd);
        h = fingerprint_bytes(h, &t->Ks, sizeof t->Ks);
        h = fingerprint_bytes(h, &t->Ke, sizeof t->Ke);
        h = fingerprint_bytes(h, &t->Ns, sizeof t->Ns);
        /* what is new since the first sidecars only when present: their scenes keep their ids */
        if (t->tex_Kd || t->tex_Ks || t->tex_Ke) {
            h = fingerprint_bytes(h, &t->tex_Kd, sizeof(int));
            h = fingerprint_bytes(h, &t->tex_Ks, sizeof(int));
            h = fingerprint_bytes(h, &t->tex_Ke, sizeof(int));
        }
    }
    return mesh_fingerprint_more(m, h);
}
