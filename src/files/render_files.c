/* render_files.c — a render's files and their sidecars, written and read back. */
#include "files/render_files.h"
#include "scene/scene_file.h"
#include "sys/shown.h"
#include "util/path.h"
#include "render/render.h"
#include "sys/atomic_file.h"
#include "sys/input_file.h"
#include "sys/interrupt.h"
#include "sys/output_path.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void render_files_layer_path(char *dst, size_t cap, const char *out, int k)
{
    const char *e = img_extension(out);
    snprintf(dst, cap, "%.*s_L%d%s", (int)(strlen(out) - strlen(e)), out, k, e);
}

static int same_files(const render_input *inputs, int ninputs, const char *out, const char *var_out, const char *count_out,
                      const char *view_out, int split, int bmin, int bmax);

int render_files_check_outputs(const render_input *inputs, int ninputs, const char *out, const char *var_out, const char *count_out,
                               const char *view_out, int split, int bmin, int bmax)
{
    char layer[PATH_CAP];
    int k;
    if (output_path_check("render", "-o", out, IMG_EXTENSIONS)) return 1;
    for (k = bmin; split && bmax != BOUNCES_NO_END && k <= bmax; k++) {
        render_files_layer_path(layer, sizeof layer, out, k);
        if (output_path_check("render", "--split", layer, IMG_EXTENSIONS)) return 1;
        if (!var_out) continue;
        render_files_layer_path(layer, sizeof layer, var_out, k);
        if (output_path_check("render", "--split --variance", layer, IMG_PFM_EXTENSION)) return 1;
    }
    if (var_out && img_format_of(var_out) != IMG_PFM) {
        fprintf(stderr, "pathlab render: --variance %s: the variance is written as .pfm\n", shown(var_out));
        return 1;
    }
    if (var_out && output_path_check("render", "--variance", var_out, IMG_PFM_EXTENSION)) return 1;
    if (count_out && output_path_check("render", "--sample-count", count_out, NULL)) return 1;   /* .pfm: render_adaptive_check */
    if (view_out && output_path_check("render", "--write-view", view_out, NULL)) return 1;
    if (view_out && render_files_view_name_bad("render", view_out)) return 1;
    return same_files(inputs, ninputs, out, var_out, count_out, view_out, split, bmin, bmax);
}

int render_files_view_name_bad(const char *cmd, const char *view_out)
{
    static const char *const not_views[] = {".obj", ".mtl", ".pfm", ".ppm", ".pgm", ".pbm", ".pnm", ".png", ".hdr", ".jpg", ".jpeg",
                                            ".tga", ".bmp", NULL};
    char low[64];
    const char *dot = strrchr(view_out, '.');
    size_t i;
    int k;
    if (!dot || strchr(dot, '/') || strlen(dot) >= sizeof low) return 0;
    for (i = 0; dot[i]; i++) low[i] = (char)(dot[i] >= 'A' && dot[i] <= 'Z' ? dot[i] - 'A' + 'a' : dot[i]);
    low[i] = '\0';
    for (k = 0; not_views[k] && strcmp(low, not_views[k]); k++) continue;
    if (!not_views[k]) return 0;
    /* a scene's MTL (named by its mtllib line) or texture would be replaced by a camera */
    fprintf(stderr, "pathlab %s: --write-view %s: a view file is text, not an image, an OBJ or an MTL: name it FILE.view\n", cmd,
            shown(view_out));
    return 1;
}

int render_files_scene_clash(const char *cmd, const char *const *outs, int n, const mesh *m)
{
    int i, k;
    for (k = 0; k < n; k++) {
        if (!outs[k]) continue;
        for (i = 0; i < m->ntextures; i++)
            if (path_same_file(outs[k], m->textures[i].path)) {
                fprintf(stderr, "pathlab %s: %s is the texture %s of the scene: write to another file\n", cmd, shown(outs[k]),
                        shown(m->textures[i].path));
                return 1;
            }
        for (i = 0; i < m->nmtl_files; i++)
            if (path_same_file(outs[k], m->mtl_files[i])) {
                fprintf(stderr, "pathlab %s: %s is the MTL file %s of the scene: write to another file\n", cmd, shown(outs[k]),
                        shown(m->mtl_files[i]));
                return 1;
            }
    }
    return 0;
}

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

/* The folder of p, "" for the current one ("dir/" kept with its slash). */
static void folder_of(char *dst, size_t cap, const char *p)
{
    snprintf(dst, cap, "%.*s", (int)(base_name(p) - p), p);
}

/* A file's name as its folder's real path and its own name, so that two spellings of one file
 * (o/a.pfm, ./o/a.pfm, o/../o/a.pfm) give one key; a folder that does not resolve is kept as written. */
void render_files_key(char *dst, size_t cap, const char *path)
{
    char dir[PATH_CAP], *real = scene_file_folder(path);
    int n;
    folder_of(dir, sizeof dir, path);
    n = snprintf(dst, cap, "%s/%s", real ? real : dir, base_name(path));
    if (n < 0 || (size_t)n >= cap) snprintf(dst, cap, "%s", path);   /* too long to resolve: as written */
    free(real);
}

/* The files a render writes (and those it reads), by what names them: NULL where not given. */
#define OUTPUT_NAMES (7 + RENDER_MAX_INPUTS)
typedef struct { const char *what[OUTPUT_NAMES]; char key[OUTPUT_NAMES][PATH_CAP]; int n; } output_names;

static void add_name(output_names *o, const char *what, const char *path, const char *suffix)
{
    char name[PATH_CAP];
    if (!path) return;
    snprintf(name, sizeof name, "%s%s", path, suffix);
    o->what[o->n] = what;
    render_files_key(o->key[o->n++], PATH_CAP, name);
}

/* 1 (said) if the file of key is one of o's, other than o's own entry skip. */
static int clash(const output_names *o, int skip, const char *what, const char *key)
{
    int i;
    for (i = 0; i < o->n; i++)
        if (i != skip && !strcmp(o->key[i], key)) {
            fprintf(stderr, "pathlab render: %s and %s are the same file (%s): give each its own name\n", what, o->what[i],
                    shown(key));
            return 1;
        }
    return 0;
}

/* 1 (said) if o's entry i (an output) is the file of an entry before it (an input, the first nin, or
 * an output), named output first. */
static int clash_before(const output_names *o, int i, int nin)
{
    int k;
    for (k = 0; k < i; k++)
        if (!strcmp(o->key[k], o->key[i])) {
            fprintf(stderr, "pathlab render: %s and %s are the same file (%s): give each its own name\n", o->what[k < nin ? i : k],
                    o->what[k < nin ? k : i], shown(o->key[i]));
            return 1;
        }
    return 0;
}

/* No two of the files a render writes are one file, whatever their spelling, and none is an input:
 * -o, --variance, --sample-count, their sidecars, --write-view, and with --split every layer of -o
 * and of --variance with its sidecar (a layer named as the variance was written, then overwritten). */
static int same_files(const render_input *inputs, int ninputs, const char *out, const char *var_out, const char *count_out,
                      const char *view_out, int split, int bmin, int bmax)
{
    static output_names o;   /* 60 kB: not on the stack */
    char layer[PATH_CAP], key[PATH_CAP];
    int i, k, v, nin;
    o.n = 0;
    for (i = 0; i < ninputs && i < RENDER_MAX_INPUTS; i++) add_name(&o, inputs[i].what, inputs[i].path, "");
    nin = o.n;
    add_name(&o, "-o", out, ""); add_name(&o, "-o's sidecar", out, ".meta");
    add_name(&o, "--variance", var_out, ""); add_name(&o, "--variance's sidecar", var_out, ".meta");
    add_name(&o, "--sample-count", count_out, ""); add_name(&o, "--sample-count's sidecar", count_out, ".meta");
    add_name(&o, "--write-view", view_out, "");
    for (i = nin; i < o.n; i++)   /* each output against the inputs and the outputs before it */
        if (clash_before(&o, i, nin)) return 1;
    for (k = bmin; split && bmax != BOUNCES_NO_END && k <= bmax; k++)
        for (v = 0; v < 4; v++) {
            const char *base = v < 2 ? out : var_out;
            if (!base) continue;
            render_files_layer_path(layer, sizeof layer, base, k);
            if (v % 2) strncat(layer, ".meta", sizeof layer - strlen(layer) - 1);
            render_files_key(key, sizeof key, layer);
            if (clash(&o, -1, v < 2 ? "a layer of -o (--split)" : "a layer of --variance (--split)", key)) return 1;
        }
    return 0;
}

/* How a sidecar names the variance file: its path from the image's folder when it sits in that
 * folder or below ("ref_var.pfm", "vars/ref_var.pfm"), so that the pair can be moved together (to
 * another machine, for merge) and the readers find it (they look nowhere else:
 * render_files_variance_path); else the path as given, which the readers refuse, saying why. */
static void variance_name(char *dst, size_t cap, const char *image_path, const char *var_path)
{
    char a[PATH_CAP];
    size_t n;
    folder_of(a, sizeof a, image_path);
    n = strlen(a);
    if (strncmp(var_path, a, n) || strstr(var_path + n, "..")) n = 0;   /* not below the image's folder: as given */
    if (snprintf(dst, cap, "%s", var_path + n) >= (int)cap) dst[0] = '\0';   /* too long to name */
}

/* The files of a render are written under temporary names (FILE.pending), then renamed together
 * with signals held: a failed write or a second Ctrl-C leaves the previous set whole, never a
 * new image beside an old variance. */
typedef struct {
    char **final, **pending;
    int n, cap;
} file_set;

/* The temporary name of `final`, registered so that a second signal removes it; NULL if out of memory. */
static const char *stage(file_set *fs, const char *final)
{
    size_t len = strlen(final);
    if (fs->n == fs->cap) {
        int cap = fs->cap ? 2 * fs->cap : 16;
        char **f = realloc(fs->final, sizeof *f * (size_t)cap), **p;
        if (f) fs->final = f;
        p = f ? realloc(fs->pending, sizeof *p * (size_t)cap) : NULL;
        if (!p) { fprintf(stderr, "%s: out of memory\n", shown(final)); return NULL; }
        fs->pending = p;
        fs->cap = cap;
    }
    fs->final[fs->n] = malloc(len + 1);
    fs->pending[fs->n] = malloc(len + sizeof ATOMIC_FILE_STAGED);
    if (!fs->final[fs->n] || !fs->pending[fs->n]) {
        free(fs->final[fs->n]);
        free(fs->pending[fs->n]);
        fprintf(stderr, "%s: out of memory\n", shown(final));
        return NULL;
    }
    memcpy(fs->final[fs->n], final, len + 1);
    memcpy(fs->pending[fs->n], final, len);
    memcpy(fs->pending[fs->n] + len, ATOMIC_FILE_STAGED, sizeof ATOMIC_FILE_STAGED);   /* messages name the final file */
    interrupt_hold();
    interrupt_temp_add(fs->pending[fs->n]);
    interrupt_release();
    return fs->pending[fs->n++];
}

/* 0 if every final name can take a rename: none is a folder (rename would fail there after the
 * files before it were renamed, leaving a new image beside an old variance). 1 after saying which. */
static int renamable(const file_set *fs)
{
    struct stat st;
    int i;
    for (i = 0; i < fs->n; i++) {
        if (stat(fs->final[i], &st) == 0 && S_ISDIR(st.st_mode)) {
            fprintf(stderr, "%s: cannot write: a folder has that name (none of the %d files of this render was written)\n",
                    shown(fs->final[i]), fs->n);
            return 1;
        }
        if (lstat(fs->final[i], &st) == 0 && S_ISREG(st.st_mode) && !(st.st_mode & S_IWUSR)) {
            fprintf(stderr, "%s: is read-only: not replaced (none of the %d files of this render was written)\n",
                    shown(fs->final[i]), fs->n);
            return 1;
        }
    }
    return 0;
}

/* A rewritten file keeps the mode of the one it replaces (a private image stays private). */
static void keep_mode(const char *pending, const char *final)
{
    struct stat st;
    if (lstat(final, &st) == 0 && S_ISREG(st.st_mode)) (void)chmod(pending, st.st_mode & 07777);
}

/* Renames every staged file over its final name (commit), or removes them all; frees the set. */
static int finish(file_set *fs, int commit)
{
    int i, err = commit && renamable(fs);
    interrupt_hold();
    for (i = 0; i < fs->n; i++) {
        if (commit && !err) keep_mode(fs->pending[i], fs->final[i]);
        if (commit && !err && rename(fs->pending[i], fs->final[i]) != 0) {
            fprintf(stderr, "%s: cannot write: %s\n", shown(fs->final[i]), strerror(errno));
            err = 1;
        }
        if (!commit || err) unlink(fs->pending[i]);
        interrupt_temp_remove(fs->pending[i]);
    }
    interrupt_release();
    for (i = 0; i < fs->n; i++) {
        free(fs->final[i]);
        free(fs->pending[i]);
    }
    free(fs->final);
    free(fs->pending);
    return err;
}

/* One image file and, for a PFM, its sidecar (an 8-bit PPM or PNG is for viewing: nothing reads it back). */
static int write_one(file_set *fs, const char *path, const image *im, float exposure, const sidecar *meta)
{
    char meta_path[PATH_CAP];
    const char *tmp = stage(fs, path), *mtmp;
    img_format fmt = img_format_of(path);
    int err = !tmp || (fmt == IMG_PFM ? img_write_pfm(im, tmp) : fmt == IMG_PPM ? img_write_ppm(im, tmp, exposure)
                                                                               : img_write_png(im, tmp, exposure));
    if (err || fmt != IMG_PFM) return err;
    sidecar_path(meta_path, sizeof meta_path, path);
    mtmp = stage(fs, meta_path);
    return !mtmp || sidecar_write_to(meta, path, mtmp);
}

int render_files_write(const char *out, const char *var_out, float exposure, const sidecar *meta,
                       const image *mean, const image *var, int nlayers, int bmin)
{
    return render_files_write_all(out, var_out, NULL, NULL, exposure, meta, mean, var, nlayers, bmin);
}

int render_files_write_all(const char *out, const char *var_out, const char *count_out, const image *count,
                           float exposure, const sidecar *meta, const image *mean, const image *var, int nlayers, int bmin)
{
    char path[PATH_CAP], vpath[PATH_CAP];
    sidecar m = *meta;
    file_set fs = {NULL, NULL, 0, 0};
    int i, err = 0;
    if (count_out) variance_name(m.sample_count, sizeof m.sample_count, out, count_out);
    else m.sample_count[0] = '\0';
    for (i = 0; i < nlayers && !err; i++) {
        int k = render_bounce_of_layer(i, bmin);
        /* the total, or a --split layer merged alone (merge keeps its name: it must not pass for a total) */
        if (i == 0) snprintf(path, sizeof path, "%s", out), snprintf(m.layer, sizeof m.layer, "%s", meta->layer[0] ? meta->layer : "total");
        else render_files_layer_path(path, sizeof path, out, k), snprintf(m.layer, sizeof m.layer, "L%d", k);
        if (var_out && i == 0) snprintf(vpath, sizeof vpath, "%s", var_out);
        else if (var_out) render_files_layer_path(vpath, sizeof vpath, var_out, k);
        strcpy(m.kind, "mean");
        if (var_out) variance_name(m.variance, sizeof m.variance, path, vpath);
        else m.variance[0] = '\0';
        m.layers_first = bmin;   /* only the total lists the layers */
        m.layers_n = i == 0 ? nlayers - 1 : 0;
        err = write_one(&fs, path, &mean[i], exposure, &m);
        if (!err && var_out) {
            strcpy(m.kind, "variance");
            m.variance[0] = '\0';
            m.layers_n = 0;
            err = write_one(&fs, vpath, &var[i], 0.0f, &m);
        }
        if (i == 0) m.sample_count[0] = '\0';   /* only the total names the counts */
    }
    if (!err && count_out) {
        strcpy(m.kind, "sample-count");
        strcpy(m.layer, "total");
        m.variance[0] = '\0';
        m.layers_n = 0;
        err = write_one(&fs, count_out, count, 0.0f, &m);
    }
    return finish(&fs, !err) || err;
}

const char *render_files_variance_path(char *dst, size_t cap, const char *image_path, const char *name)
{
    return input_file_beside(dst, cap, image_path, name);
}

/* The size a sidecar's camera line gives ("... size WxH"); 0 if it has none. */
static int camera_size(const sidecar *m, int *w, int *h)
{
    const char *s = strstr(m->camera, "size ");
    return s && sscanf(s, "size %dx%d", w, h) == 2 && *w > 0 && *h > 0;
}

/* 1 if both sidecars know their --sky image's pixels and they differ (one written before sky-id: unknown). */
static int sky_differs(const sidecar *a, const sidecar *b) { return a->sky_id[0] && b->sky_id[0] && strcmp(a->sky_id, b->sky_id); }

/* A file that goes with the image whose sidecar is `of` (its layer, its variance) must be of that
 * same render: scene, seed, flags, camera. 0, or 1 after printing why. */
/* The first key in which m and of are not the same render (scene-id, seed, flags, camera, sky-id), or NULL. */
static const char *render_key_differs(const sidecar *m, const sidecar *of)
{
    return strcmp(m->scene_id, of->scene_id) ? "scene-id" : m->seed != of->seed ? "seed" : strcmp(m->flags, of->flags) ? "flags"
           : strcmp(m->camera, of->camera) ? "camera" : sky_differs(m, of) ? "sky-id" : NULL;
}

static int same_render(const char *cmd, const char *path, const sidecar *m, const sidecar *of)
{
    const char *key = render_key_differs(m, of);
    if (!key) return 0;
    fprintf(stderr, "pathlab %s: %s is not of the render it goes with: its sidecar's %s differs: files of two renders mixed up\n",
            cmd, path, key);
    return 1;
}

/* Reads image `path` and its sidecar into *im and *m, checking it is what `kind` and `of` (the
 * sidecar of the render's total, NULL for the total itself) say, and from its header before any
 * pixel is read that it is w x h (0: the size of the camera line). */
static int check_one(const char *cmd, const char *path, const char *kind, const sidecar *of, sidecar *m, int w, int h)
{
    char a[SIDECAR_RANGES_TEXT], b[SIDECAR_RANGES_TEXT];
    img_pfm_info info;
    int rc = sidecar_read(m, path);
    if (rc < 0) fprintf(stderr, "pathlab %s: %s has no sidecar %s.meta: it was not written by pathlab render "
                                "(or the .meta was not copied with it), so its samples are unknown\n", cmd, shown(path), shown(path));
    if (rc) return 1;
    if (strcmp(m->kind, kind)) {
        fprintf(stderr, "pathlab %s: %s is a %s image, expected a %s image\n", cmd, shown(path), shown(m->kind), shown(kind));
        return 1;
    }
    sidecar_ranges_text(m, a, sizeof a);
    sidecar_ranges_text(of ? of : m, b, sizeof b);
    if (strcmp(a, b)) {
        fprintf(stderr, "pathlab %s: %s holds samples %s, but its image holds %s: files of two renders mixed up\n", cmd, shown(path), shown(a), shown(b));
        return 1;
    }
    if (of && same_render(cmd, path, m, of)) return 1;
    if (img_format_of(path) != IMG_PFM) {
        fprintf(stderr, "pathlab %s: %s: need the .pfm (linear float) image, not an 8-bit one\n", cmd, shown(path));
        return 1;
    }
    if (img_read_pfm_header(path, &info)) return 1;
    if ((w > 0 || camera_size(m, &w, &h)) && (info.w != w || info.h != h)) {
        fprintf(stderr, "pathlab %s: %s is %dx%d, but its render is %dx%d: files of two renders mixed up\n", cmd, path, info.w,
                info.h, w, h);
        return 1;
    }
    return 0;
}

static int read_one(const char *cmd, const char *path, const char *kind, const sidecar *of, image *im, sidecar *m, int w, int h)
{
    return check_one(cmd, path, kind, of, m, w, h) || img_read_pfm(im, path);
}

/* The variance of layer p (named `name` by its sidecar) into vp[cap]: 0, or 1 after printing why. */
static int variance_file(char *vp, size_t cap, const char *p, const char *name, const char *cmd)
{
    const char *why;
    if (!name[0]) {
        fprintf(stderr, "pathlab %s: %s was rendered without --variance: its variance is unknown\n", cmd, p);
        return 1;
    }
    if (!(why = render_files_variance_path(vp, cap, p, name))) return 0;
    fprintf(stderr, "pathlab %s: %s.meta names its variance '%s': %s\n", cmd, p, name, why);
    return 1;
}

/* 1 if vm (a variance's sidecar) says it is the variance of the render of m: kind, samples, scene,
 * seed, flags, camera. */
static int variance_of(const sidecar *vm, const sidecar *m)
{
    char a[SIDECAR_RANGES_TEXT], b[SIDECAR_RANGES_TEXT];
    sidecar_ranges_text(vm, a, sizeof a);
    sidecar_ranges_text(m, b, sizeof b);
    return !strcmp(vm->kind, "variance") && !strcmp(a, b) && !render_key_differs(vm, m);
}

/* Candidate `name` (from the image's folder) for the variance of image_path, of sidecar m (NULL: none):
 * 0 taken (into dst), -1 not there, 2 there but its sidecar is of another render (nothing said),
 * 1 refused (said: a link leading out, a malformed sidecar). */
static int variance_candidate(char *dst, size_t cap, const char *image_path, const sidecar *m, const char *name, int trusted,
                              const char *cmd)
{
    sidecar vm;
    img_pfm_info info;
    const char *why = trusted ? input_file_beside_trusted(dst, cap, image_path, name) : render_files_variance_path(dst, cap, image_path, name);
    int rc;
    if (why && errno == ENOENT) return -1;
    if (why) { fprintf(stderr, "pathlab %s: %s: %s\n", cmd, shown(dst), why); return 1; }
    if ((rc = sidecar_read(&vm, dst)) > 0) return 1;
    if (rc < 0 || !m) return 0;   /* no sidecar on one side: as found, unchecked (a pair copied without its .meta) */
    if (!variance_of(&vm, m)) return 2;
    return img_read_pfm_header(image_path, &info) || check_one(cmd, dst, "variance", m, &vm, info.w, info.h);   /* its size */
}

int render_files_find_variance(char *dst, size_t cap, const char *image_path, const sidecar *m, int how, const char *cmd)
{
    int trusted = how & FIND_VARIANCE_TRUSTED;
    size_t n = strlen(image_path), stem = n > 4 && !strcmp(image_path + n - 4, ".pfm") ? n - 4 : n;
    const char *slash = strrchr(image_path, '/'), *base = slash ? slash + 1 : image_path;
    char beside[PATH_CAP], named[PATH_CAP];
    int rc = -1, rb;
    sidecar vm;
    if (m && m->variance[0] && ((rc = variance_candidate(named, sizeof named, image_path, m, m->variance, trusted, cmd)) == 0 || rc == 1)) {
        if (rc == 0) snprintf(dst, cap, "%s", named);
        return rc;
    }
    snprintf(beside, sizeof beside, "%.*s_var.pfm", (int)(stem - (size_t)(base - image_path)), base);
    rb = m && m->variance[0] && !strcmp(beside, m->variance) ? -1 : variance_candidate(dst, cap, image_path, m, beside, trusted, cmd);
    if (rb == 0 && rc == 2 && (sidecar_read(&vm, dst) != 0 || !variance_of(&vm, m))) rb = -1;   /* unverified: no way out */
    if (rb == 0 && rc == 2)   /* the name reused by another render since (tmp_var.pfm), the pair renamed */
        fprintf(stderr, "pathlab %s: note: %s.meta names its variance %s, now of another render; %s beside it is this "
                "render's: used\n", cmd, shown(image_path), shown(m->variance), shown(dst));
    if (rb == 0 || rb == 1) return rb;
    if (rc == 2) {   /* named, of another render, and nothing better: two renders mixed up, said as merge says it */
        img_pfm_info info;
        if (sidecar_read(&vm, named) == 0 && img_read_pfm_header(image_path, &info) == 0) check_one(cmd, named, "variance", m, &vm, info.w, info.h);
        return 1;
    }
    if (rb == 2)
        fprintf(stderr, "pathlab %s: note: %s is not the variance of %s (its sidecar is of another render): not used\n", cmd,
                shown(dst), shown(image_path));
    else if (m && m->variance[0] && !(how & FIND_VARIANCE_QUIET))
        fprintf(stderr, "pathlab %s: note: %s.meta names its variance %s, which is not there: none used\n", cmd,
                shown(image_path), shown(m->variance));
    return -1;
}

/* Layer i (0: the total) and, with_var, its variance. */
static int read_layer(render_files *rf, int i, const char *path, int with_var, const char *cmd)
{
    char p[PATH_CAP], vp[PATH_CAP];
    sidecar m, vm;
    int w = i ? rf->mean[0].w : 0, h = i ? rf->mean[0].h : 0;
    if (i == 0) snprintf(p, sizeof p, "%s", path);
    else render_files_layer_path(p, sizeof p, path, render_bounce_of_layer(i, rf->bmin));
    if (read_one(cmd, p, "mean", i ? &rf->meta : NULL, &rf->mean[i], i ? &m : &rf->meta, w, h)) return 1;
    if (!with_var) return 0;
    if (variance_file(vp, sizeof vp, p, (i ? m.variance : rf->meta.variance), cmd)) return 1;
    return read_one(cmd, vp, "variance", &rf->meta, &rf->var[i], &vm, rf->mean[0].w, rf->mean[0].h);
}

int render_files_read(render_files *rf, const char *path, int with_var, const char *cmd)
{
    sidecar first;
    int i, n, rc;
    memset(rf, 0, sizeof *rf);
    if ((rc = sidecar_read(&first, path)) < 0) return read_one(cmd, path, "mean", NULL, NULL, &first, 0, 0);   /* prints why */
    if (rc) return 1;
    rf->bmin = first.layers_first;
    n = 1 + first.layers_n;
    rf->mean = calloc((size_t)n, sizeof(image));
    rf->var = with_var ? calloc((size_t)n, sizeof(image)) : NULL;
    if (!rf->mean || (with_var && !rf->var)) {
        fprintf(stderr, "pathlab %s: out of memory\n", cmd);
        render_files_free(rf);
        return 1;
    }
    rf->nlayers = n;
    for (i = 0; i < n; i++)
        if (read_layer(rf, i, path, with_var, cmd)) {
            render_files_free(rf);
            return 1;
        }
    return 0;
}

void render_files_free(render_files *rf)
{
    int i;
    for (i = 0; i < rf->nlayers; i++) {
        if (rf->mean) img_free(&rf->mean[i]);
        if (rf->var) img_free(&rf->var[i]);
    }
    free(rf->mean);
    free(rf->var);
    rf->mean = rf->var = NULL;
    rf->nlayers = 0;
}
