/* obj.h — our Wavefront OBJ/MTL reader (v, vn, vt, f in every index form, usemtl, mtllib;
 * MTL: newmtl, Kd, Ks, Ns, Ke). Polygons are triangulated (concave ones too); degenerate triangles
 * are dropped and counted. Errors print "file:line: message" on stderr.
 *
 * Where the format leaves a choice, pathlab decides:
 * - Indices refer to elements defined earlier in the file; negative ones count back from the
 *   latest. 'v' takes 3 to 6 numbers (x y z, then w or r g b, checked and ignored), 'vt' 1 to 3,
 *   'vn' 3; every number must be a finite float, written as a whole word ("1.5x" is an error).
 * - '#' starts a comment anywhere on a line, names included; a line ending in '\' goes on with
 *   the next one. Lines have no length limit; CRLF, tabs, a UTF-8 BOM and a missing final newline
 *   are fine. Files with NUL bytes (UTF-16, binaries) are refused.
 * - 'o', 'g', 's' are accepted; 'l', 'p' are ignored (one warning); other keywords get one warning.
 * - vn and vt are kept: a triangle's corners carry them (tri_n, tri_t) for shading normals and textures.
 * - mtllib takes one or more file names, split at blanks, relative to the OBJ's folder; each file
 *   is read at its mtllib line (once: a repeated name is skipped). A usemtl name (the rest of
 *   the line, trimmed) must be defined by a newmtl in those files, else it is an error; the
 *   latest definition of a name wins. Exception: a usemtl before any mtllib (exporters
 *   write a lone "usemtl Default") selects the default material, with a warning.
 * - MTL: a key a material doesn't give is zero (Kd, Ks, Ke = 0 and Ns = 0): what the file says is
 *   all there is. The defaults some guides quote (Kd 0.8, Ks 1.0) would sum to 1.8 > 1.
 *   "Kd g" means grey g. Negative values are errors. Other keys are ignored (one warning per
 *   key and file). Kd + Ks > 1 in a channel gets a warning naming file:line and the material.
 * - mats[0] is "(default)", Kd 0.5 grey, for faces before any usemtl.
 * - A face has at most OBJ_FACE_MAX (4096) corners, else it is an error: ear clipping takes time
 *   in the square of the corners (100k corners: 50 s), and a face line can be any length.
 * - Polygons are ear-clipped in the plane facing their Newell normal. A triangle is degenerate,
 *   dropped and counted, when |(b - a) x (c - a)| computed in float is 0 or not finite; so
 *   normalizing a kept triangle's cross product is always safe.
 * - A file with no triangle left (only points or lines, or only zero-area faces) is an error:
 *   there would be nothing to render. */
#ifndef PATHLAB_OBJ_H
#define PATHLAB_OBJ_H
#include "scene/mesh.h"
#include "scene/mtl.h"

#define OBJ_FACE_MAX 4096   /* corners of a face; more is an error (see above) */

/* Loads path into m. Returns 0 on success, nonzero after printing the error. Warnings (ignored
 * MTL keys, once each) go to stderr unless quiet; Kd+Ks > 1 is noted in m (n_energy, energy_note). */
int obj_load(const char *path, mesh *m, int quiet);
/* The same with the command line's options (NULL: none). */
int obj_load_with(const char *path, mesh *m, const mtl_opts *o, int quiet);
#endif
