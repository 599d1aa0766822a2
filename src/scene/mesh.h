/* mesh.h — the scene as the parser leaves it: triangles, their vertices and their materials.
 * Triangle i has corners P[tri[3i]], P[tri[3i+1]], P[tri[3i+2]] in counter-clockwise order; its
 * front face (the emitting side, the side the geometric normal points to) is given by that winding:
 * n = normalize((b - a) x (c - a)). */
#ifndef PATHLAB_MESH_H
#define PATHLAB_MESH_H
#include "math/vec.h"
#include "scene/texture.h"
#include <stddef.h>
#include <stdint.h>

/* The course's BRDF: f = Kd/pi + Ks (Ns+8)/(8 pi) cos^Ns(theta_h); Ke is emitted radiance. A map
 * multiplies its value by a texture's at the hit's texcoord, as gKit does (tex_Kd: 0 none, else
 * textures[tex_Kd - 1]). */
typedef struct {
    char name[128];
    vec3 Kd, Ks, Ke;
    float Ns;
    int tex_Kd, tex_Ks, tex_Ke;
} material;

typedef struct {
    vec3 *P;            /* vertex positions, nverts */
    int nverts;
    int *tri;           /* 3 vertex indices per triangle, ntris */
    int *tri_mat;       /* material index per triangle */
    int ntris;
    material *mats;     /* mats[0] is the default diffuse material for faces without usemtl */
    int nmats;
    int mats_cap;       /* the room of mats (0: exactly nmats, as a mesh made by hand) */
    int *mat_slots;     /* the materials by name (mtl.c): a hash table of indices into mats, -1 empty */
    int nslots;         /* its size, a power of two (0: none yet) */
    int mats_indexed;   /* mats[0 .. mats_indexed - 1] are in it */
    int ndegenerate;    /* triangles of zero area dropped at load time */
    int nnormals, ntexcoords; /* vn / vt lines read */
    vec3 *N;            /* the vn, nnormals of them, as written (normalized where they are used) */
    float *T;           /* the vt, 2 floats (u, v) each, ntexcoords of them (a missing v is 0) */
    int *tri_n, *tri_t; /* 3 vn / vt indices per triangle, -1 for a corner without one; NULL if no corner has one */
    texture *textures;  /* the images the materials name, each file once */
    int ntextures;
    char **mtl_files;   /* the MTL files its mtllib lines name (as joined to the OBJ's folder), each once:
                           inputs no output may replace */
    int nmtl_files;
    int n_energy;       /* materials with Kd + Ks > 1 in a channel; energy_note names the first one */
    char energy_note[320];
} mesh;

void mesh_free(mesh *m);
/* A 64-bit fingerprint (FNV-1a) of what is rendered: vertices, triangles, materials. Two renders
 * merge only if their scenes have the same; comments, names and unused vertices don't count. */
uint64_t mesh_fingerprint(const mesh *m);
/* h (a fingerprint so far) followed by n bytes of data: FNV-1a, 64 bits. */
uint64_t fingerprint_bytes(uint64_t h, const void *data, size_t n);
/* Bounds of the vertices used by triangles. */
void mesh_bounds(const mesh *m, vec3 *lo, vec3 *hi);
/* What the camera frames when no view gives the eye and target: the bounds of the scene, but not
 * of a backdrop that dwarfs the rest. A backdrop triangle emits nothing and has an edge at least
 * a quarter of the scene's bounding-box diagonal D (a floor, a wall, a sky dome made of a few
 * large triangles); if the other triangles' bounds have a diagonal of D / 4 at most (the objects
 * are dwarfed: a mesh on a floor 4 or more times its size), those bounds are framed, else the whole
 * scene (a Cornell box: its blocks and light span more than a quarter of the box). Nothing is
 * left out of the picture but the backdrop's far parts. */
void mesh_framing_bounds(const mesh *m, vec3 *lo, vec3 *hi);
#endif
