/* obj.h — our Wavefront OBJ/MTL reader (v, vn, vt, f in every index form, usemtl, mtllib;
 * MTL: newmtl, Kd, Ks, Ns, Ke). Polygons are triangulated (concave ones too); degenerate triangles
 * are dropped and counted. Errors print "file:line: message" on stderr. */
#ifndef PATHLAB_OBJ_H
#define PATHLAB_OBJ_H
#include "mesh.h"

/* Loads path into m. Returns 0 on success, nonzero after printing the error. Warnings (ignored
 * MTL keys, once each; Kd+Ks > 1) go to stderr unless quiet. */
int obj_load(const char *path, mesh *m, int quiet);
#endif
