/* mtl.h — the Wavefront MTL reader used by obj.c: newmtl, Kd, Ks, Ns, Ke, map_Kd, map_Ks, map_Ke (see
 * obj.h for the rules). */
#ifndef PATHLAB_MTL_H
#define PATHLAB_MTL_H
#include "scene/mesh.h"

/* What the command line adds: --mtl FILE (NULL: none) replaces the OBJ's mtllib files, whose lines are
 * then skipped (FILE is not confined; its map_ files are, to FILE's folder); --texture-decode. */
typedef struct {
    const char *mtl;
    texture_decode decode;
    int quiet;             /* set by obj_load_with (obj.h) */
} mtl_opts;

/* The largest MTL file read (bytes): a file a scene names has a bounded size (see obj.h). */
#define MTL_FILE_MAX ((size_t)64 << 20)
/* The largest texture file read (bytes). */
#define TEXTURE_FILE_MAX ((size_t)512 << 20)

/* Appends the materials of MTL file path to m->mats; the textures they name (relative to path's folder)
 * must be inside folder root (resolved), and are read with o's decode. Returns 0 on success, -1 after printing a
 * "file:line: message" error, or a positive errno when the file can't be read (EFBIG: larger
 * than MTL_FILE_MAX; ENODEV, EISDIR: not a regular file): the caller, who knows which mtllib line
 * named it, reports that one. */
int mtl_load(const char *path, mesh *m, const char *root, const mtl_opts *o);
/* Index of the material called name in m->mats, the latest definition winning; -1 if none. */
int mtl_find(const mesh *m, const char *name);
#endif
