/* scene_file.c — the confinement of the files a scene names; see scene_file.h. */
/* realpath is POSIX 2008 but glibc declares it only for X/Open */
#define _XOPEN_SOURCE 700
#include "scene/scene_file.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

char *scene_file_sibling(const char *from, const char *name)
{
    const char *slash = strrchr(from, '/');
    size_t dir = name[0] == '/' || !slash ? 0 : (size_t)(slash - from) + 1;
    char *path = malloc(dir + strlen(name) + 1);
    if (!path) return NULL;
    memcpy(path, from, dir);
    strcpy(path + dir, name);
    return path;
}

char *scene_file_folder(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = !slash ? 0 : slash == path ? 1 : (size_t)(slash - path);
    char *dir, *real;
    if (!(dir = malloc(n + 2))) return NULL;
    memcpy(dir, n ? path : ".", n ? n : 1);
    dir[n ? n : 1] = '\0';
    real = realpath(dir, NULL);
    free(dir);
    return real;
}

/* Whether resolved path real is folder dir (resolved too) or below it. */
static int inside(const char *dir, const char *real)
{
    size_t n = strlen(dir);
    return n == 1 || (strncmp(real, dir, n) == 0 && real[n] == '/');   /* n == 1: dir is "/" */
}

int scene_file_check(const objtext *t, const char *root, const char *key, const char *name, const char *path, size_t max,
                     char **real_out)
{
    struct stat st;
    char *real;
    int ok = 0;
    if (!(real = realpath(path, NULL)))
        return objtext_fail(t, "cannot open '%.*s%s': %s", OBJTEXT_CUT(name), strerror(errno));
    if (!inside(root, real))
        objtext_fail(t, "%s '%.*s%s' is outside the scene's folder %s (it is %s): a scene may only name files in "
                        "its folder or below", key, OBJTEXT_CUT(name), root, real);
    else if (stat(real, &st) != 0)
        objtext_fail(t, "cannot open '%.*s%s': %s", OBJTEXT_CUT(name), strerror(errno));
    else if (S_ISDIR(st.st_mode))
        objtext_fail(t, "%s '%.*s%s' is a folder, not a file", key, OBJTEXT_CUT(name));
    else if (!S_ISREG(st.st_mode))
        objtext_fail(t, "%s '%.*s%s' is not a regular file (a device, FIFO or socket)", key, OBJTEXT_CUT(name));
    else if (st.st_size > (off_t)max)
        objtext_fail(t, "%s '%.*s%s' is larger than %d MiB, the limit of a file a scene names", key, OBJTEXT_CUT(name),
                     (int)(max >> 20));
    else
        ok = 1;
    if (ok && real_out) *real_out = real;
    else free(real);
    return ok;
}
