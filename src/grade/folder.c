/* folder.c — a class's folder expanded into its images (folder.h). */
#include "grade/folder.h"
#include "sys/shown.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/linear_file.h"
#include "files/render_files.h"
#include <sys/stat.h>
#include "sys/output_path.h"
#include "util/path.h"

int grade_list_init(grade_list *l, int cap)
{
    memset(l, 0, sizeof *l);
    l->cap = cap;
    l->images = calloc((size_t)cap, sizeof *l->images);
    l->owned = calloc((size_t)cap, sizeof *l->owned);
    return !l->images || !l->owned;
}

void grade_list_add(grade_list *l, const char *image)
{
    if (l->n < l->cap) l->images[l->n++] = image;
}

void grade_list_free(grade_list *l)
{
    int k;
    for (k = 0; k < l->nowned; k++) free(l->owned[k]);
    free(l->owned);
    free((void *)l->images);
}

static int by_name(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

/* 1 if dir/name is the reference or a file made beside it (REF-64x64.pfm, REF_split.pfm, ...). */
static int is_reference(const char *dir, const char *name, const char *ref)
{
    const char *slash = strrchr(ref, '/'), *base = slash ? slash + 1 : ref;
    char path[PATH_CAP], ref_dir[PATH_CAP];
    size_t stem = path_ends_with(base, ".pfm") ? strlen(base) - 4 : strlen(base);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    snprintf(ref_dir, sizeof ref_dir, "%.*s", slash ? (int)(slash - ref) : 1, slash ? ref : ".");
    if (path_same_file(path, ref)) return 1;
    return path_same_file(dir, ref_dir) && !strncmp(name, base, stem) && (name[stem] == '_' || name[stem] == '-');
}

/* What the folder's entry `name` is to grade: 0 an image, 1 a variance (*_var.pfm), 2 a split layer
 * (*_split_L*), 3 the reference or a file made beside it, 4 not an image (.pfm or .hdr, in any case:
 * a student's Bob.PFM is graded, not silently left out), 5 a sidecar (.meta). */
static int entry_kind(const char *dir, const char *name, const char *ref)
{
    char low[512];
    size_t i;
    for (i = 0; name[i] && i + 1 < sizeof low; i++) low[i] = (char)(name[i] >= 'A' && name[i] <= 'Z' ? name[i] - 'A' + 'a' : name[i]);
    low[i] = '\0';
    if (path_ends_with(low, ".meta")) return 5;   /* a sidecar: expected, not counted */
    if (img_format_of(low) != IMG_PFM && img_format_of(low) != IMG_HDR) return 4;
    if (path_ends_with(low, "_var.pfm")) return 1;
    if (strstr(low, "_split_l")) return 2;
    {
        char path[PATH_CAP], a[PATH_CAP], b[PATH_CAP];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, name);
        render_files_key(a, sizeof a, path);
        render_files_key(b, sizeof b, ref);
        if (!strcmp(a, b)) return 3;   /* --ref itself, whatever it is (a teacher's link to elsewhere too) */
        /* any other link is graded: one leading out is refused in its row, one to the reference
         * (a student's bob.pfm -> ref.pfm) is flagged as a copy of it, not left out as the reference */
        if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) return 0;
    }
    return is_reference(dir, name, ref) ? 3 : 0;
}

/* Says what the folder held besides the images it grades, so that no student's file disappears unsaid. */
static void say_left_out(const char *dir, const long left[5])
{
    static const char *const what[5] = {"", "variance (*_var.pfm)", "split layer (*_split_L*)", "the reference or made beside it",
                                         "not .pfm or .hdr"};
    int k, first = 1;
    if (!left[1] && !left[2] && !left[3] && !left[4]) return;
    fprintf(stderr, "pathlab grade: the folder %s: not graded:", shown(dir));
    for (k = 1; k < 5; k++)
        if (left[k]) fprintf(stderr, "%s %ld %s", first ? "" : ",", left[k], what[k]), first = 0;
    fprintf(stderr, "\n");
}

int grade_list_add_folder(grade_list *l, const char *dir, const char *ref)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int first = l->n, kind;
    long left[6] = {0, 0, 0, 0, 0, 0};
    if (!d) { fprintf(stderr, "pathlab grade: cannot open the folder %s\n", shown(dir)); return 1; }
    while ((e = readdir(d)) != NULL) {
        char *path;
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        if ((kind = entry_kind(dir, e->d_name, ref)) != 0) { left[kind]++; continue; }
        if (l->n >= l->cap) { fprintf(stderr, "pathlab grade: more than %d images\n", l->cap); closedir(d); return 1; }
        path = malloc(strlen(dir) + strlen(e->d_name) + 2);
        if (!path) { closedir(d); return 1; }
        sprintf(path, "%s/%s", dir, e->d_name);
        l->images[l->n++] = l->owned[l->nowned++] = path;
    }
    closedir(d);
    qsort(l->images + first, (size_t)(l->n - first), sizeof *l->images, by_name);
    say_left_out(dir, left);
    if (l->n == first) fprintf(stderr, "pathlab grade: warning: no .pfm or .hdr image to grade in the folder %s\n", shown(dir));
    return 0;
}
