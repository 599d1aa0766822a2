/* folder.c — a class's folder expanded into its images (folder.h). */
#include "grade/folder.h"
#include "sys/shown.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/linear_file.h"
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

int grade_list_add_folder(grade_list *l, const char *dir, const char *ref)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int first = l->n;
    if (!d) { fprintf(stderr, "pathlab grade: cannot open the folder %s\n", shown(dir)); return 1; }
    while ((e = readdir(d)) != NULL) {
        char *path;
        if (!(path_ends_with(e->d_name, ".pfm") || img_is_rgbe(e->d_name)) || path_ends_with(e->d_name, "_var.pfm") || strstr(e->d_name, "_split_L") ||
            is_reference(dir, e->d_name, ref)) continue;
        if (l->n >= l->cap) { fprintf(stderr, "pathlab grade: more than %d images\n", l->cap); closedir(d); return 1; }
        path = malloc(strlen(dir) + strlen(e->d_name) + 2);
        if (!path) { closedir(d); return 1; }
        sprintf(path, "%s/%s", dir, e->d_name);
        l->images[l->n++] = l->owned[l->nowned++] = path;
    }
    closedir(d);
    qsort(l->images + first, (size_t)(l->n - first), sizeof *l->images, by_name);
    if (l->n == first) fprintf(stderr, "pathlab grade: warning: no .pfm or .hdr image to grade in the folder %s\n", shown(dir));
    return 0;
}
