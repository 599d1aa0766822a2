/* mtl.h — the Wavefront MTL reader used by obj.c: newmtl, Kd, Ks, Ns, Ke (see obj.h for the rules). */
#ifndef PATHLAB_MTL_H
#define PATHLAB_MTL_H
#include "scene/mesh.h"

/* The largest MTL file read (bytes): a file a scene names has a bounded size (see obj.h). */
#define MTL_FILE_MAX ((size_t)64 << 20)

/* Appends the materials of MTL file path to m->mats. Returns 0 on success, -1 after printing a
 * "file:line: message" error, or a positive errno when the file can't be read (EFBIG: larger
 * than MTL_FILE_MAX; ENODEV, EISDIR: not a regular file): the caller, who knows which mtllib line
 * named it, reports that one. */
int mtl_load(const char *path, mesh *m, int quiet);
/* Index of the material called name in m->mats, the latest definition winning; -1 if none. */
int mtl_find(const mesh *m, const char *name);
#endif
