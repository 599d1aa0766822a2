/* path.c — a path's parts and what it names on disk (path.h). */
#include "util/path.h"
#include "sys/input_file.h"
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

const char *path_file_name(const char *path) { return strrchr(path, '/') ? strrchr(path, '/') + 1 : path; }

int path_ends_with(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n >= k && !strcmp(name + n - k, suffix);
}

int path_is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int path_is_readable(const char *path)
{
    FILE *f = input_file_open(path, 0);   /* never blocks on a FIFO: the reader that follows refuses it */
    if (f) fclose(f);
    return f != NULL && !path_is_dir(path);
}

int path_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}
