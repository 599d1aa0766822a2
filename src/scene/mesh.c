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
