/* obj.c — the Wavefront OBJ reader declared in obj.h.
 * Lines come from objtext.c (comments, CR, '\' continuations, no length limit) and MTL files from
 * mtl.c, read when their mtllib line is. Polygons are triangulated by ear clipping in their
 * best-fit plane, keeping the winding of the file. */
#include "scene/obj.h"
#include "sys/shown.h"
#include "scene/mtl.h"
#include "scene/objtext.h"
#include "sys/input_file.h"
#include "scene/scene_file.h"
#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One corner of the polygon being ear-clipped: its projection and its neighbours still left. */
typedef struct { double x, y; int prev, next; } corner;
/* The indices of a face corner: v, vt and vn (-1 without one), 0-based. */
typedef struct { int v, t, n; } corner_ids;

typedef struct {
    mesh *m;
    objtext *obj;              /* the OBJ file being read: mtllib paths and messages refer to it */
    size_t capP, capT;         /* allocated vertices, triangles */
    size_t capN, capUV;        /* allocated vn, vt */
    int cur_mat;               /* material of the faces that follow */
    char **libs;               /* paths of the mtllib files read so far */
    int nlibs;
    corner_ids *face;          /* the corners of the face being read */
    size_t capface;
    corner *poly;              /* scratch of the ear clipper */
    size_t cappoly;
    long long ear_work;        /* corners tested by is_ear in this file, bounded by OBJ_EAR_WORK_MAX */
    char *dir_real;            /* the OBJ's folder, resolved (realpath), once an mtllib needs it */
    mtl_opts opts;
    int mtl_given;             /* --mtl FILE was read: the mtllib lines are skipped */
} loader;

/* Returns arr with room for need items of size bytes (*cap updated), or NULL when out of memory,
 * in which case arr is still valid and owned by the caller. */
static void *grow(void *arr, size_t *cap, size_t need, size_t size)
{
    size_t n = *cap ? *cap : 16;
    void *bigger;
    if (need <= *cap) return arr;
    while (n < need) n *= 2;
    if (n > SIZE_MAX / size) return NULL;
    bigger = realloc(arr, n * size);
    if (bigger) *cap = n;
    return bigger;
}

/* ---- triangles and polygons ---- */

/* ids (3 a triangle, NULL: none yet) grown from old to cap triangles; 0 if memory ran out. */
static int grow_corner_ids(int **ids, size_t old, size_t cap)
{
    int *bigger;
    size_t i;
    if (!*ids) return 1;
    if (!(bigger = realloc(*ids, 3 * cap * sizeof *bigger))) return 0;
    for (i = 3 * old; i < 3 * cap; i++) bigger[i] = -1;
    *ids = bigger;
    return 1;
}

/* A corner id array made on its first use, -1 for the triangles before it; 0 if out of memory. */
static int first_corner_ids(int **ids, size_t cap)
{
    size_t i;
    if (*ids) return 1;
    if (!(*ids = malloc(3 * cap * sizeof **ids))) return 0;
    for (i = 0; i < 3 * cap; i++) (*ids)[i] = -1;
    return 1;
}

/* The vt and vn of the corners i, j, k of the face, for triangle m->ntris (not counted yet). */
static int corner_attributes(loader *L, int i, int j, int k)
{
    mesh *m = L->m;
    const corner_ids *f = L->face;
    size_t t = 3 * (size_t)m->ntris;
    int has_t = f[i].t >= 0 || f[j].t >= 0 || f[k].t >= 0, has_n = f[i].n >= 0 || f[j].n >= 0 || f[k].n >= 0;
    if (has_t && !first_corner_ids(&m->tri_t, L->capT)) return 0;
    if (has_n && !first_corner_ids(&m->tri_n, L->capT)) return 0;
    if (m->tri_t) m->tri_t[t] = f[i].t, m->tri_t[t + 1] = f[j].t, m->tri_t[t + 2] = f[k].t;
    if (m->tri_n) m->tri_n[t] = f[i].n, m->tri_n[t + 1] = f[j].n, m->tri_n[t + 2] = f[k].n;
    return 1;
}

/* Appends triangle (a, b, c) in that order, unless its area is zero: those are dropped and
 * counted, since they can't be hit and have no normal. The area is judged as users compute the
 * normal, |(b - a) x (c - a)| in float, so that normalizing it never divides by 0 or inf. */
static int add_triangle(loader *L, int i, int j, int k)
{
    mesh *m = L->m;
    int a = L->face[i].v, b = L->face[j].v, c = L->face[k].v;
    float len = v3_length(v3_cross(v3_sub(m->P[b], m->P[a]), v3_sub(m->P[c], m->P[a])));
    size_t old = L->capT;
    int *tri, *mat;
    if (!(len > 0.0f) || !isfinite(len)) {
        m->ndegenerate++;
        return 1;
    }
    if (m->ntris >= INT_MAX / 3) return objtext_fail(L->obj, "too many triangles");
    if (!(mat = grow(m->tri_mat, &L->capT, (size_t)m->ntris + 1, sizeof *mat))) goto oom;
    m->tri_mat = mat;
    if (L->capT != old) { /* tri follows tri_mat's capacity, 3 ints per triangle */
        if (!(tri = realloc(m->tri, 3 * L->capT * sizeof *tri))) goto oom;
        m->tri = tri;
        if (!grow_corner_ids(&m->tri_t, old, L->capT) || !grow_corner_ids(&m->tri_n, old, L->capT)) goto oom;
    }
    if (!corner_attributes(L, i, j, k)) goto oom;
    tri = m->tri;
    tri[3 * m->ntris] = a;
    tri[3 * m->ntris + 1] = b;
    tri[3 * m->ntris + 2] = c;
    mat[m->ntris++] = L->cur_mat;
    return 1;
oom:
    return objtext_fail(L->obj, "out of memory");
}

/* Twice the signed area of 2D triangle (a, b, c), positive when it turns counter-clockwise. */
static double orient(const corner *a, const corner *b, const corner *c)
{
    return (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
}

static int same_point(const corner *a, const corner *b) { return a->x == b->x && a->y == b->y; }

/* Whether collinear corner c lies strictly between p and n: a straight angle. */
static int straight(const corner *p, const corner *c, const corner *n)
{
    return (c->x - p->x) * (n->x - c->x) + (c->y - p->y) * (n->y - c->y) > 0;
}

/* Whether corner c (between p and n) is an ear: convex, with no other corner in its triangle.
 * sign makes the polygon counter-clockwise. A repeated point (a polygon touching itself) does
 * not block. A zero-area corner is cut (the triangle is dropped) if it is a repeated point or a
 * spike; a straight one stays until it is a corner of some triangle: cutting it would leave a
 * T-junction, where rays may slip through a crack between triangles. */
static int is_ear(const corner *poly, int p, int c, int n, double sign, long long *work)
{
    double area = sign * orient(&poly[p], &poly[c], &poly[n]);
    int v;
    if (area < 0) return 0; /* reflex */
    if (area == 0) return !straight(&poly[p], &poly[c], &poly[n]);
    for (v = poly[n].next; v != p; v = poly[v].next) {
        const corner *q = &poly[v];
        ++*work;
        if (same_point(q, &poly[p]) || same_point(q, &poly[c]) || same_point(q, &poly[n])) continue;
        if (sign * orient(&poly[p], &poly[c], q) >= 0 && sign * orient(&poly[c], &poly[n], q) >= 0
            && sign * orient(&poly[n], &poly[p], q) >= 0)
            return 0;
    }
    return 1;
}

/* The ear tests of a file are bounded: a face of OBJ_FACE_MAX corners takes about 8e6 steps if
 * convex, but the search can be cubic in the corners on a self-crossing one. 2e9 steps: seconds. */
#define OBJ_EAR_WORK_MAX 2000000000LL

/* Cuts ears off polygon L->face[0..n) until one triangle is left; each triangle keeps the
 * polygon's order of corners, hence its winding. Each ear test costs O(n), and ears are usually
 * found at once. A polygon without ears (it crosses itself) is finished with any convex corner,
 * then with any corner: a full turn without a cut lowers the level, so the loop always ends.
 * The first ear tried is corner 1, then the corner after each cut: a convex polygon gives the fan
 * 0 1 2, 0 2 3, 0 3 4 ... of gKit's read_mesh (and Blender's, tinyobjloader's). A warped quad has
 * two shapes, one per diagonal; starting at corner 0 took the other one, and McGuire's boxes (whose
 * left wall is warped) came out 1.3% darker on that wall than in Cycles or a student's gKit render. */
static int clip_ears(loader *L, int n, double sign)
{
    corner *poly = L->poly;
    int left = n, c = 1, tries = 0, level = 2; /* 2: true ears, 1: convex corners, 0: anything */
    while (left > 3) {
        int p = poly[c].prev, nx = poly[c].next;
        int ok = level == 2 ? is_ear(poly, p, c, nx, sign, &L->ear_work)
               : level == 1 ? sign * orient(&poly[p], &poly[c], &poly[nx]) >= 0 : 1;
        if (ok) {
            if (!add_triangle(L, p, c, nx)) return 0;
            poly[p].next = nx;
            poly[nx].prev = p;
            left--;
            tries = 0;
        } else if (++tries > left) {
            level--;
            tries = 0;
        }
        c = nx;
        if (L->ear_work > OBJ_EAR_WORK_MAX)
            return objtext_fail(L->obj, "polygons too slow to triangulate: ear clipping gave up after %.0e steps in this "
                                "file (self-crossing or very large faces); split them", (double)OBJ_EAR_WORK_MAX);
    }
    return add_triangle(L, poly[c].prev, c, poly[c].next);
}

/* Triangulates the face L->face[0..n). The polygon is projected on the coordinate plane most
 * facing its Newell normal (a best-fit normal that also works for concave and warped polygons);
 * the two kept axes are a cyclic pair, so the 2D winding has the sign of that normal component. */
static int triangulate(loader *L, int n)
{
    const vec3 *P = L->m->P;
    const corner_ids *f = L->face;
    double nrm[3] = {0, 0, 0};
    corner *poly;
    int i, axis;
    if (n == 3) return add_triangle(L, 0, 1, 2);
    if (!(poly = grow(L->poly, &L->cappoly, (size_t)n, sizeof *poly)))
        return objtext_fail(L->obj, "out of memory");
    L->poly = poly;
    for (i = 0; i < n; i++) {
        vec3 a = P[f[i].v], b = P[f[(i + 1) % n].v];
        nrm[0] += ((double)a.y - b.y) * ((double)a.z + b.z);
        nrm[1] += ((double)a.z - b.z) * ((double)a.x + b.x);
        nrm[2] += ((double)a.x - b.x) * ((double)a.y + b.y);
    }
    axis = fabs(nrm[0]) > fabs(nrm[1]) ? (fabs(nrm[0]) > fabs(nrm[2]) ? 0 : 2)
                                      : (fabs(nrm[1]) > fabs(nrm[2]) ? 1 : 2);
    for (i = 0; i < n; i++) {
        poly[i].x = v3_comp(P[f[i].v], (axis + 1) % 3);
        poly[i].y = v3_comp(P[f[i].v], (axis + 2) % 3);
        poly[i].prev = (i + n - 1) % n;
        poly[i].next = (i + 1) % n;
    }
    return clip_ears(L, n, nrm[axis] < 0 ? -1.0 : 1.0);
}

/* ---- OBJ statements ---- */

/* Reads an optionally signed decimal integer at *s and advances *s; 0 if there is none. Values
 * saturate far beyond any valid index, so that huge ones are reported as out of range. */
static int read_int(const char **s, long long *out)
{
    const char *p = *s;
    long long v = 0;
    int neg = *p == '-';
    if (*p == '-' || *p == '+') p++;
    if (*p < '0' || *p > '9') return 0;
    for (; *p >= '0' && *p <= '9'; p++)
        if (v < 10000000000LL) v = 10 * v + (*p - '0');
    *out = neg ? -v : v;
    *s = p;
    return 1;
}

/* Turns an OBJ index (1-based, or negative: counted back from the latest) into a 0-based one. */
static int resolve(const objtext *t, long long i, int count, const char *what, int *out)
{
    long long r = i > 0 ? i - 1 : count + i;
    if (i == 0) return objtext_fail(t, "%s index 0 (OBJ indices start at 1)", what);
    if (r < 0 || r >= count)
        return objtext_fail(t, "%s index %lld out of range (%d defined so far)", what, i, count);
    *out = (int)r;
    return 1;
}

/* Reads one face corner "v", "v/t", "v/t/n" or "v//n" and checks all its indices into *ids. */
static int read_corner(loader *L, const char *w, corner_ids *ids)
{
    const objtext *t = L->obj;
    const mesh *m = L->m;
    const char *s = w;
    long long v, vt = 0, vn = 0;
    int ok = read_int(&s, &v), has_vt = 0, has_vn = 0;
    ids->t = ids->n = -1;
    if (ok && *s == '/' && *++s != '/') ok = has_vt = read_int(&s, &vt);
    if (ok && *s == '/') {
        s++;
        ok = has_vn = read_int(&s, &vn);
    }
    if (!ok || *s != '\0') return objtext_fail(t, "bad face corner '%.*s%s' (expected v, v/t, v/t/n or v//n)", OBJTEXT_CUT(w));
    return resolve(t, v, m->nverts, "vertex", &ids->v)
        && (!has_vt || resolve(t, vt, m->ntexcoords, "texture coordinate", &ids->t))
        && (!has_vn || resolve(t, vn, m->nnormals, "normal", &ids->n));
}

static int read_face(loader *L, char *s)
{
    char *w;
    int n = 0;
    corner_ids *face;
    while ((w = objtext_word(&s))) {
        if (n == OBJ_FACE_MAX)   /* refused before anything more is read or stored */
            return objtext_fail(L->obj, "face with more than %d corners: pathlab refuses larger polygons (their "
                                "triangulation takes time in the square of the corners); split it", OBJ_FACE_MAX);
        if (!(face = grow(L->face, &L->capface, (size_t)n + 1, sizeof *face)))
            return objtext_fail(L->obj, "out of memory");
        L->face = face;
        if (!read_corner(L, w, &face[n++])) return 0;
    }
    if (n < 3) return objtext_fail(L->obj, "face with %d vertices (needs at least 3)", n);
    return triangulate(L, n);
}

static int read_vertex(loader *L, char *s)
{
    mesh *m = L->m;
    float v[6]; /* x y z, then w or r g b, which are checked and ignored */
    vec3 *P;
    if (objtext_numbers(L->obj, &s, "v", v, 3, 6) < 0) return 0;
    if (m->nverts == INT_MAX) return objtext_fail(L->obj, "too many vertices");
    if (!(P = grow(m->P, &L->capP, (size_t)m->nverts + 1, sizeof *P)))
        return objtext_fail(L->obj, "out of memory");
    m->P = P;
    P[m->nverts++] = v3(v[0], v[1], v[2]);
    return 1;
}

/* "vn x y z" or "vt u [v [w]]" (w ignored, a missing v is 0), kept for shading and textures. */
static int read_vn_vt(loader *L, const char *kw, char *s)
{
    mesh *m = L->m;
    float v[3] = {0, 0, 0};
    int normal = kw[1] == 'n', *count = normal ? &m->nnormals : &m->ntexcoords;
    void *arr;
    if (objtext_numbers(L->obj, &s, kw, v, normal ? 3 : 1, 3) < 0) return 0;
    if (*count == INT_MAX) return objtext_fail(L->obj, "too many '%s'", kw);
    if (normal ? !(arr = grow(m->N, &L->capN, (size_t)*count + 1, sizeof *m->N))
               : !(arr = grow(m->T, &L->capUV, (size_t)*count + 1, 2 * sizeof *m->T)))
        return objtext_fail(L->obj, "out of memory");
    if (normal) m->N = arr, m->N[*count] = v3(v[0], v[1], v[2]);
    else m->T = arr, m->T[2 * *count] = v[0], m->T[2 * *count + 1] = v[1];
    ++*count;
    return 1;
}

/* "usemtl name". Without any mtllib there is nothing to look the name up in (exporters write
 * "usemtl Default" alone): the default material is used, with a warning. */
static int use_material(loader *L, const char *name)
{
    objtext *t = L->obj;
    int i = mtl_find(L->m, name);
    if (i >= 0) { L->cur_mat = i; return 1; }
    if (L->nlibs > 0 || L->mtl_given)
        return objtext_fail(t, "unknown material '%.*s%s' (no newmtl of that name in the mtllib files read so far)",
                            OBJTEXT_CUT(name));
    if (objtext_first_time(t, "usemtl"))
        objtext_warn(t, t->line, "usemtl '%.*s%s' but no mtllib before it: using the default material", OBJTEXT_CUT(name));
    L->cur_mat = 0;
    return 1;
}

static int load_mtl(loader *L, const char *name);

/* One OBJ statement: keyword kw, the rest of the line in s. */
static int statement(loader *L, const char *kw, char *s)
{
    objtext *t = L->obj;
    char *name;
    int n = 0;
    if (strcmp(kw, "v") == 0) return read_vertex(L, s);
    if (strcmp(kw, "f") == 0) return read_face(L, s);
    if (strcmp(kw, "vn") == 0 || strcmp(kw, "vt") == 0) return read_vn_vt(L, kw, s);
    if (strcmp(kw, "usemtl") == 0) return use_material(L, objtext_rest(s));
    if (strcmp(kw, "mtllib") == 0) {
        for (; (name = objtext_word(&s)); n++)
            if (!load_mtl(L, name)) return 0;
        if (n == 0) return objtext_fail(t, "mtllib without a file name");
        return 1;
    }
    /* object and group names, smoothing groups: nothing to render */
    if (strcmp(kw, "o") == 0 || strcmp(kw, "g") == 0 || strcmp(kw, "s") == 0) return 1;
    if (strcmp(kw, "l") == 0 || strcmp(kw, "p") == 0) {
        if (objtext_first_time(t, "l"))
            objtext_warn(t, t->line, "ignoring points and lines ('p', 'l'): pathlab renders faces");
    } else if (objtext_first_time(t, kw)) {
        objtext_warn(t, t->line, "ignoring unknown keyword '%.*s%s'", OBJTEXT_CUT(kw));
    }
    return 1;
}

/* ---- the whole file ---- */

/* The OBJ's folder, resolved once (realpath) into L->dir_real: files the scene names must be in it. */
static int scene_folder(loader *L)
{
    if (L->dir_real) return 1;
    L->dir_real = scene_file_folder(L->obj->path);
    if (!L->dir_real) return objtext_fail(L->obj, "cannot resolve the scene's folder: %s", strerror(errno));
    return 1;
}

/* Reads MTL file name, relative to the OBJ's folder; its materials are then usable. A file read
 * already is skipped: some exporters repeat the mtllib line before every object. */
static int load_mtl(loader *L, const char *name)
{
    char *path = scene_file_sibling(L->obj->path, name), **libs;
    int i, err;
    for (i = 0; path && i < L->nlibs; i++)
        if (strcmp(L->libs[i], path) == 0) {
            free(path);
            return 1;
        }
    if (!path || !(libs = realloc(L->libs, ((size_t)L->nlibs + 1) * sizeof *libs))) {
        free(path);
        return objtext_fail(L->obj, "out of memory");
    }
    L->libs = libs;
    L->libs[L->nlibs++] = path;
    if (L->mtl_given) return 1;   /* --mtl FILE replaces the OBJ's own */
    if (!scene_folder(L) || !scene_file_check(L->obj, L->dir_real, "mtllib", name, path, MTL_FILE_MAX, NULL)) return 0;
    err = mtl_load(path, L->m, L->dir_real, &L->opts);
    if (err > 0) return objtext_fail(L->obj, "cannot open '%.*s%s': %s", OBJTEXT_CUT(name), strerror(err));
    return err == 0;
}

static int add_default_material(mesh *m)
{
    if (!(m->mats = calloc(1, sizeof *m->mats))) {
        fprintf(stderr, "out of memory\n");
        return 0;
    }
    strcpy(m->mats[0].name, "(default)");
    m->mats[0].Kd = v3(0.5f, 0.5f, 0.5f);
    m->nmats = 1;
    return 1;
}

/* An emitting triangle's three corners, sorted: the same key for a face written twice, in either winding. */
typedef struct { float c[9]; } corners_key;

static int by_corners(const void *a, const void *b) { return memcmp(a, b, sizeof(corners_key)); }

static void corner_key(const mesh *m, int i, corners_key *k)
{
    int order[3] = {0, 1, 2}, a, b, tmp;
    for (a = 0; a < 2; a++)   /* the three corners sorted by their bytes: any winding, any first corner */
        for (b = a + 1; b < 3; b++)
            if (memcmp(&m->P[m->tri[3 * i + order[b]]], &m->P[m->tri[3 * i + order[a]]], sizeof(vec3)) < 0)
                tmp = order[a], order[a] = order[b], order[b] = tmp;
    for (a = 0; a < 3; a++) {
        vec3 p = m->P[m->tri[3 * i + order[a]]];
        k->c[3 * a] = p.x, k->c[3 * a + 1] = p.y, k->c[3 * a + 2] = p.z;
    }
}

/* Emitting triangles with the same three corners as another (a lamp written twice, or back to back):
 * a ray hits one of them, whichever the BVH meets first, while light sampling draws each, so light
 * and BRDF sampling disagree there. Counted for a warning (0 if memory runs out: no warning). */
static long coincident_emitters(const mesh *m)
{
    corners_key *k;
    long n = 0, i, same = 0;
    for (i = 0; i < m->ntris; i++) n += !v3_is_zero(m->mats[m->tri_mat[i]].Ke);
    if (n < 2 || !(k = malloc((size_t)n * sizeof *k))) return 0;
    for (i = 0, n = 0; i < m->ntris; i++)
        if (!v3_is_zero(m->mats[m->tri_mat[i]].Ke)) corner_key(m, (int)i, &k[n++]);
    qsort(k, (size_t)n, sizeof *k, by_corners);
    for (i = 1; i < n; i++) same += !memcmp(&k[i], &k[i - 1], sizeof *k);
    free(k);
    return same;
}

/* Checks that something is left to render and gives the arrays back their unused room. */
static int finish(loader *L)
{
    mesh *m = L->m;
    objtext *t = L->obj;
    void *fit;
    long twice;
    t->line = 0; /* messages about the whole file */
    if (m->ntris == 0 && m->ndegenerate > 0)
        return objtext_fail(t, "no triangles: all %d had zero area", m->ndegenerate);
    if (m->ntris == 0) return objtext_fail(t, "no triangles (no faces with 3 or more vertices)");
    if (m->ndegenerate > 0) objtext_warn(t, 0, "dropped %d triangles of zero area", m->ndegenerate);
    if ((twice = coincident_emitters(m)) > 0)
        objtext_warn(t, 0, "%ld emitting triangle%s the same three corners as another (a lamp written twice, or back to back): "
                     "a ray sees one of them, light sampling draws each, so --direct light and --direct brdf disagree; keep one "
                     "(an emitter lights the side its winding faces)", twice, twice == 1 ? " has" : "s have");
    if ((fit = realloc(m->P, (size_t)m->nverts * sizeof *m->P))) m->P = fit;
    if ((fit = realloc(m->tri, 3 * (size_t)m->ntris * sizeof *m->tri))) m->tri = fit;
    if ((fit = realloc(m->tri_mat, (size_t)m->ntris * sizeof *m->tri_mat))) m->tri_mat = fit;
    return 1;
}

static int parse(loader *L)
{
    objtext *t = L->obj;
    char *s, *kw;
    while ((s = objtext_line(t)))
        if ((kw = objtext_word(&s)) && !statement(L, kw, s)) return 0;
    if (t->oom) return objtext_fail(t, "out of memory");
    return finish(L);
}

/* --mtl FILE: a path given on the command line, not confined to the scene's folder; its textures are
 * confined to FILE's folder. 1, or 0 after printing why. */
static int load_given_mtl(loader *L, const char *file)
{
    char *root = scene_file_folder(file);
    int err = root ? mtl_load(file, L->m, root, &L->opts) : errno;
    free(root);
    if (err > 0) fprintf(stderr, "%s: cannot open (--mtl): %s\n", shown(file), strerror(err));
    L->mtl_given = 1;
    return err == 0;
}

int obj_load(const char *path, mesh *m, int quiet) { return obj_load_with(path, m, NULL, quiet); }

int obj_load_with(const char *path, mesh *m, const mtl_opts *o, int quiet)
{
    objtext t;
    loader L;
    int err, ok = 0;
    memset(m, 0, sizeof *m);
    memset(&L, 0, sizeof L);
    L.m = m;
    L.obj = &t;
    if (o) L.opts = *o;
    L.opts.quiet = quiet;
    if ((err = objtext_open(&t, path, quiet)))
        fprintf(stderr, "%s: cannot open: %s\n", shown(path), input_file_why(err));
    else
        ok = objtext_check(&t) && add_default_material(m) && (!L.opts.mtl || load_given_mtl(&L, L.opts.mtl)) && parse(&L);
    objtext_close(&t);
    free(L.face);
    free(L.poly);
    m->mtl_files = L.libs, m->nmtl_files = L.nlibs;   /* the mesh's now: freed by mesh_free */
    free(L.dir_real);
    if (!ok) mesh_free(m);
    return ok ? 0 : 1;
}
