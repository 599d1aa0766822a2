/* mtl.h — the Wavefront MTL reader used by obj.c: newmtl, Kd, Ks, Ns, Ke (see obj.h for the rules). */
#ifndef PATHLAB_MTL_H
#define PATHLAB_MTL_H
#include "scene/mesh.h"

/* Appends the materials of MTL file path to m->mats. Returns 0 on success, -1 after printing a
 * "file:line: message" error, or a positive errno when the file can't be read: the caller, who
 * knows which mtllib line named it, reports that one. */
int mtl_load(const char *path, mesh *m, int quiet);
/* Index of the material called name in m->mats, the latest definition winning; -1 if none. */
int mtl_find(const mesh *m, const char *name);
#endif
