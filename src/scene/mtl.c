/* mtl.c — the Wavefront MTL reader declared in mtl.h. Only what the course's BRDF uses is read
 * (Kd, Ks, Ns, Ke); every other key is accepted, counted, and summarised in one line per file at
 * its end ("FILE: ignored keys: illum (8), Ka (8); not supported: transmission (Ni, d) ..."). */
#include "scene/mtl.h"
#include "sys/shown.h"
#include "scene/objtext.h"
#include "math/rng.h"
#include "scene/scene_file.h"
#include "image/decode.h"
#include <errno.h>
#include <limits.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The keys of a file that pathlab ignores, with their counts; past IGNORED_MAX distinct keys the
 * others are only counted. Keys are kept to their first OBJTEXT_SEEN_LEN - 1 characters. */
#define IGNORED_MAX 32
typedef struct {
    char key[IGNORED_MAX][OBJTEXT_SEEN_LEN];
    int count[IGNORED_MAX], cut[IGNORED_MAX];
    int n, others;
} ignored_keys;

static void note_ignored(ignored_keys *ig, const char *kw)
{
    size_t len = strlen(kw), n = len < OBJTEXT_SEEN_LEN - 1 ? len : OBJTEXT_SEEN_LEN - 1;
    int i;
    for (i = 0; i < ig->n; i++)
        if (strncmp(ig->key[i], kw, n) == 0 && ig->key[i][n] == '\0' && ig->cut[i] == (len > n)) {
            ig->count[i]++;
            return;
        }
    if (ig->n == IGNORED_MAX) { ig->others++; return; }
    memcpy(ig->key[ig->n], kw, n);
    ig->key[ig->n][n] = '\0';
    ig->cut[ig->n] = len > n;
    ig->count[ig->n++] = 1;
}

/* Transmission (transparent and refracting surfaces): filter, index of refraction, dissolve. */
static int is_transmission(const char *kw)
{
    return !strcmp(kw, "Tf") || !strcmp(kw, "Ni") || !strcmp(kw, "d") || !strcmp(kw, "Tr");
}

/* Prints the ignored keys that are (or are not) transmission keys, "key (count)" comma-separated. */
static void print_keys(const ignored_keys *ig, int transmission)
{
    int i, any = 0;
    for (i = 0; i < ig->n; i++)
        if (is_transmission(ig->key[i]) == transmission)
            fprintf(stderr, "%s%s%s (%d)", any++ ? ", " : "", shown(ig->key[i]), ig->cut[i] ? "..." : "", ig->count[i]);
}

/* The one line that sums up the ignored keys of a file, transmission named apart: a glass
 * material renders as an opaque one, which a user should know. */
static void print_ignored(const objtext *t, const ignored_keys *ig)
{
    int i, trans = 0;
    if (t->quiet || ig->n == 0) return;
    for (i = 0; i < ig->n; i++) trans += is_transmission(ig->key[i]);
    fprintf(stderr, "%s: ", shown(t->path));
    if (trans < ig->n) {
        fprintf(stderr, "ignored keys: ");
        print_keys(ig, 0);
        if (ig->others) fprintf(stderr, ", %d other keys", ig->others);
        fprintf(stderr, trans ? "; " : " (pathlab reads Kd, Ks, Ns, Ke, map_Kd, map_Ks, map_Ke)\n");
    }
    if (trans) {
        fprintf(stderr, "not supported: transmission (");
        print_keys(ig, 1);
        fprintf(stderr, "): every surface is opaque\n");
    }
}

/* Materials by name: an open-addressing hash table (linear probing) of indices into m->mats, kept
 * at most half full, so that a newmtl or a usemtl costs the same among 200,000 materials as among 2
 * (a linear search made 50,000 materials take 9 s to load). A later material of the same name takes
 * its slot: the latest definition wins. The hash is FNV-1a from a basis drawn once per process (the
 * time and the stack's address, which ASLR moves), scattered by SplitMix64's finaliser so that every
 * bit of the index depends on every byte: names made to collide in a fixed hash (100,000 whose FNV-1a
 * agreed in their low 20 bits took 73 s to load) do not collide here. The table is only looked up:
 * nothing's order depends on the basis. */
static uint32_t name_hash(const char *name)
{
    static uint32_t basis;
    uint32_t h;
    if (!basis) {
        uint32_t seed = (uint32_t)time(NULL);
        basis = (uint32_t)splitmix64_mix((uint64_t)seed << 32 ^ (uint64_t)(uintptr_t)&seed) | 1u;
    }
    for (h = basis; *name; name++) h = (h ^ (unsigned char)*name) * 16777619u;
    return (uint32_t)splitmix64_mix(h);
}

/* The slot of name: where it is, or the empty slot where it would go. */
static int *slot_of(const mesh *m, const char *name)
{
    uint32_t mask = (uint32_t)m->nslots - 1, i = name_hash(name) & mask;
    while (m->mat_slots[i] >= 0 && strcmp(m->mats[m->mat_slots[i]].name, name) != 0) i = (i + 1) & mask;
    return &m->mat_slots[i];
}

/* Puts mats[mats_indexed .. nmats - 1] into the table, growing it first if they would fill more
 * than half. 0 if memory ran out. */
static int index_materials(mesh *m)
{
    if (2 * (int64_t)m->nmats > m->nslots) {
        int n = 16, i, *slots;
        while (n < 2 * m->nmats) n *= 2;
        if (!(slots = malloc((size_t)n * sizeof *slots))) return 0;
        for (i = 0; i < n; i++) slots[i] = -1;
        free(m->mat_slots);
        m->mat_slots = slots, m->nslots = n, m->mats_indexed = 0;
    }
    for (; m->mats_indexed < m->nmats; m->mats_indexed++) *slot_of(m, m->mats[m->mats_indexed].name) = m->mats_indexed;
    return 1;
}

int mtl_find(const mesh *m, const char *name)
{
    /* a mesh made by hand (or whose table could not grow) has no table: search it */
    int i;
    if (m->mats_indexed == m->nmats && m->nslots > 0) return *slot_of(m, name);
    for (i = m->nmats - 1; i >= 0; i--)
        if (strcmp(m->mats[i].name, name) == 0) return i;
    return -1;
}

/* Appends a material with every value zero: an absent key means zero (see obj.h). The array grows
 * by half each time (scenes of 200,000 materials exist). */
static int new_material(mesh *m, const objtext *t, const char *name)
{
    int cap = m->mats_cap > m->nmats ? m->mats_cap : m->nmats;
    if (strlen(name) >= sizeof m->mats->name)
        return objtext_fail(t, "material name longer than %d characters", (int)sizeof m->mats->name - 1);
    if (!index_materials(m)) return objtext_fail(t, "out of memory");
    if (mtl_find(m, name) > 0)
        objtext_warn(t, t->line, "material '%s' defined again; the later one wins", name);
    if (m->nmats == cap) {
        material *mats;
        if (cap > INT_MAX / 2 - 16) return objtext_fail(t, "too many materials");
        cap += cap / 2 + 16;
        if (!(mats = realloc(m->mats, (size_t)cap * sizeof *mats))) return objtext_fail(t, "out of memory");
        m->mats = mats, m->mats_cap = cap;
    }
    memset(&m->mats[m->nmats], 0, sizeof *m->mats);
    strcpy(m->mats[m->nmats++].name, name);
    if (!index_materials(m)) return objtext_fail(t, "out of memory");
    return 1;
}

/* "Kd r g b", or "Kd g" for grey; negative values are refused. */
static int read_color(const objtext *t, char *s, const char *kw, vec3 *c)
{
    float v[3];
    int n = objtext_numbers(t, &s, kw, v, 1, 3);
    if (n < 0) return 0;
    if (n == 2) return objtext_fail(t, "'%s' needs 1 (grey) or 3 numbers (r g b), found 2", kw);
    if (n == 1) v[1] = v[2] = v[0];
    if (v[0] < 0 || v[1] < 0 || v[2] < 0) return objtext_fail(t, "negative value in '%s'", kw);
    *c = v3(v[0], v[1], v[2]);
    return 1;
}

/* A surface reflecting more light than it receives makes the path tracer's estimates grow: noted in
 * the mesh (the first such material named), and said once by the scene's loader, unless the
 * material model ignores Ks (scene.c). */
static void check_energy(const objtext *t, mesh *m, const material *mat, int line)
{
    float most = v3_max_comp(v3_add(mat->Kd, mat->Ks));
    if (most > 1.0f && m->n_energy++ == 0)
        snprintf(m->energy_note, sizeof m->energy_note, "%s:%d: material '%.128s' has Kd + Ks = %g > 1", t->path, line,
                 mat->name, most);
}

/* The texture file of path (resolved), read once per scene: its number + 1 in *tex. 1, or 0 after
 * printing why. */
static int find_or_load_texture(const objtext *t, mesh *m, char *real, const mtl_opts *o, int *tex)
{
    texture *more;
    long used = 0;
    int i;
    for (i = 0; i < m->ntextures; i++)
        if (!strcmp(m->textures[i].path, real)) break;
    if (i == m->ntextures) {
        for (i = 0; i < m->ntextures; i++) used += (long)m->textures[i].w * m->textures[i].h;
        if (!(more = realloc(m->textures, ((size_t)m->ntextures + 1) * sizeof *more))) return objtext_fail(t, "out of memory");
        m->textures = more;
        if (texture_load(&m->textures[i], real, o->decode, TEXTURE_SCENE_MAX_TEXELS - used))   /* shown by objtext_fail */
            return TEXTURE_SCENE_MAX_TEXELS - used < IMG_DECODE_MAX_PIXELS
                   ? objtext_fail(t, "cannot read the texture %s (a scene's textures hold at most %ld texels together; those before "
                                  "it, %ld)", real, TEXTURE_SCENE_MAX_TEXELS, used)
                   : objtext_fail(t, "cannot read the texture %s", real);
        m->ntextures++;
    }
    *tex = i + 1;
    return 1;
}

/* "map_Kd FILE" (map_Ks, map_Ke): FILE relative to the MTL's folder, confined to root. */
static int read_map(const objtext *t, char *s, const char *kw, mesh *m, const char *root, const mtl_opts *o, int *tex)
{
    const char *name = objtext_rest(s);
    char *path, *real = NULL, *slash;
    int ok;
    if (!*name) return objtext_fail(t, "'%s' without a file name", kw);
    if (name[0] == '-')
        return objtext_fail(t, "'%s' options (%.*s%s) are not supported: give the file name alone", kw, OBJTEXT_CUT(name));
    if (!(path = scene_file_sibling(t->path, name))) return objtext_fail(t, "out of memory");
    for (slash = path; *slash; slash++)
        if (*slash == '\\') *slash = '/';   /* a Windows exporter's ".\\wall.jpg" */
    if (access(path, F_OK) != 0 && errno == ENOENT) {   /* scenes from the wild often lack theirs */
        objtext_warn(t, t->line, "%s '%.*s%s': no such file; the material renders without it", kw, OBJTEXT_CUT(name));
        free(path);
        return 1;
    }
    ok = scene_file_check(t, root, kw, name, path, TEXTURE_FILE_MAX, &real) && find_or_load_texture(t, m, real, o, tex);
    free(path);
    free(real);
    return ok;
}

/* One statement other than newmtl, for material mat (NULL before the first newmtl). */
static int statement(objtext *t, const char *kw, char *s, material *mat, ignored_keys *ig)
{
    float ns;
    int used = !strcmp(kw, "Kd") || !strcmp(kw, "Ks") || !strcmp(kw, "Ke") || !strcmp(kw, "Ns");
    if (!used) {
        note_ignored(ig, kw);
        return 1;
    }
    if (!mat) return objtext_fail(t, "'%s' before the first newmtl", kw);
    if (strcmp(kw, "Kd") == 0) return read_color(t, s, kw, &mat->Kd);
    if (strcmp(kw, "Ks") == 0) return read_color(t, s, kw, &mat->Ks);
    if (strcmp(kw, "Ke") == 0) return read_color(t, s, kw, &mat->Ke);
    if (objtext_numbers(t, &s, kw, &ns, 1, 1) < 0) return 0;
    if (ns < 0) return objtext_fail(t, "negative value in 'Ns'");
    mat->Ns = ns;
    return 1;
}

/* map_Kd, map_Ks, map_Ke of the latest material (cur_is_new: it is of this file); 0 if kw is none of them (*done unset), else 1 with *done = 1 or 0
 * after printing why. */
static int map_statement(objtext *t, const char *kw, char *s, mesh *m, int cur_is_new, const char *root, const mtl_opts *o,
                         int *done)
{
    int which = !strcmp(kw, "map_Kd") ? 1 : !strcmp(kw, "map_Ks") ? 2 : !strcmp(kw, "map_Ke") ? 3 : 0;
    material *mat = &m->mats[m->nmats - 1];
    if (!which) return 0;
    *done = 1;
    if (!cur_is_new) return objtext_fail(t, "'%s' before the first newmtl", kw);
    return read_map(t, s, kw, m, root, o, which == 1 ? &mat->tex_Kd : which == 2 ? &mat->tex_Ks : &mat->tex_Ke);
}

/* The energy check of a material runs when it is complete: at the next newmtl or at the end. */
static int parse(objtext *t, mesh *m, const char *root, const mtl_opts *o)
{
    int first = m->nmats, mat_line = 0; /* materials of this file start at index first */
    char *s, *kw;
    ignored_keys ig;
    memset(&ig, 0, sizeof ig);
    while ((s = objtext_line(t))) {
        material *cur = m->nmats > first ? &m->mats[m->nmats - 1] : NULL;
        if (!(kw = objtext_word(&s))) continue;
        if (strcmp(kw, "newmtl") != 0) {
            int done = 0;
            if (!map_statement(t, kw, s, m, cur != NULL, root, o, &done) && done) return 0;
            if (!done && !statement(t, kw, s, cur, &ig)) return 0;
            continue;
        }
        if (cur) check_energy(t, m, cur, mat_line);
        if (!new_material(m, t, objtext_rest(s))) return 0;
        mat_line = t->line;
    }
    if (t->oom) return objtext_fail(t, "out of memory");
    if (m->nmats > first) check_energy(t, m, &m->mats[m->nmats - 1], mat_line);
    print_ignored(t, &ig);
    return 1;
}

int mtl_load(const char *path, mesh *m, const char *root, const mtl_opts *o)
{
    objtext t;
    int err = objtext_open_bounded(&t, path, o->quiet, MTL_FILE_MAX), ok;
    if (err) return err;
    ok = objtext_check(&t) && parse(&t, m, root, o);
    objtext_close(&t);
    return ok ? 0 : -1;
}
