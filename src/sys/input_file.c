/* input_file.c — see input_file.h. O_NONBLOCK: opening a FIFO without a writer returns at once;
 * the flag is cleared after the checks, so that a pipe given on purpose (regular_only = 0) is read. */
/* realpath is POSIX 2008 but glibc declares it only for X/Open */
#define _XOPEN_SOURCE 700
#include "sys/input_file.h"
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

FILE *input_file_open(const char *path, int regular_only)
{
    struct stat st;
    int fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK), err = 0;
    FILE *f;
    if (fd < 0) return NULL;
    if (regular_only && fstat(fd, &st) == 0 && !S_ISREG(st.st_mode)) err = S_ISDIR(st.st_mode) ? EISDIR : ENODEV;
    if (!err && fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) < 0) err = errno;
    if (!err && (f = fdopen(fd, "rb"))) return f;
    err = err ? err : errno;
    close(fd);
    errno = err;
    return NULL;
}

const char *input_file_why(int err)
{
    if (err == EISDIR) return "a folder, not a file";
    if (err == ENODEV) return "not a regular file (a FIFO or a device)";
    return strerror(err);
}

/* 1 if name has a ".." part ("..", "../x", "x/..", "x/../y"). */
static int climbs(const char *name)
{
    const char *p = name;
    for (;;) {
        size_t n = strcspn(p, "/");
        if (n == 2 && p[0] == '.' && p[1] == '.') return 1;
        if (!p[n]) return 0;
        p += n + 1;
    }
}

/* Whether real (resolved) is folder dir (resolved) or below it. */
static int below(const char *dir, const char *real)
{
    size_t n = strlen(dir);
    return (n == 1 && dir[0] == '/') || (strncmp(real, dir, n) == 0 && real[n] == '/');
}

const char *input_file_beside(char *dst, size_t cap, const char *owner, const char *name)
{
    const char *slash = strrchr(owner, '/');
    int dir = slash ? (int)(slash - owner + 1) : 0;
    char *folder, *real;
    const char *why = NULL;
    struct stat st;
    int err = 0;
    errno = 0;
    if (!name[0]) return "an empty name";
    if (name[0] == '/') return "an absolute path: only a file in the image's folder (or below) may be named";
    if (climbs(name)) return "a path with '..': only a file in the image's folder (or below) may be named";
    if (snprintf(dst, cap, "%.*s%s", dir, owner, name) >= (int)cap) return "a path too long";
    folder = dir ? malloc((size_t)dir + 1) : NULL;
    if (folder) memcpy(folder, owner, (size_t)dir), folder[dir] = '\0';
    if (dir && !folder) return strerror(ENOMEM);
    real = realpath(dst, NULL);
    if (!real) err = errno, why = strerror(err);
    if (!why) {
        char *top = realpath(dir ? folder : ".", NULL);
        if (!top) why = strerror(errno);
        else if (!below(top, real)) why = "outside the image's folder (a symbolic link leads out): only a file in the image's folder (or below) may be named";
        free(top);
    }
    if (!why && stat(real, &st) != 0) why = strerror(errno);
    else if (!why && !S_ISREG(st.st_mode)) why = input_file_why(S_ISDIR(st.st_mode) ? EISDIR : ENODEV);
    free(real);
    free(folder);
    errno = err;   /* ENOENT: the file does not exist */
    return why;
}

const char *input_file_beside_trusted(char *dst, size_t cap, const char *owner, const char *name)
{
    const char *slash = strrchr(owner, '/');
    int dir = slash ? (int)(slash - owner + 1) : 0;
    struct stat st;
    errno = 0;
    if (!name[0]) return "an empty name";
    if (name[0] == '/') return "an absolute path: only a file in the image's folder (or below) may be named";
    if (climbs(name)) return "a path with '..': only a file in the image's folder (or below) may be named";
    if (snprintf(dst, cap, "%.*s%s", dir, owner, name) >= (int)cap) return "a path too long";
    if (stat(dst, &st) != 0) return strerror(errno);   /* ENOENT: not there */
    if (!S_ISREG(st.st_mode)) return input_file_why(S_ISDIR(st.st_mode) ? EISDIR : ENODEV);
    return NULL;
}

char *input_file_resolved(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISLNK(st.st_mode)) return NULL;
    return realpath(path, NULL);
}

const char *input_file_link_out(const char *path)
{
    struct stat st;
    char dst[4096];
    const char *slash = strrchr(path, '/'), *why;
    if (lstat(path, &st) != 0 || !S_ISLNK(st.st_mode)) return NULL;
    why = input_file_beside(dst, sizeof dst, path, slash ? slash + 1 : path);
    if (!why || errno == ENOENT) return NULL;   /* a dangling link: unreadable, said as any missing file */
    return "a symbolic link leading out of its folder: not read";
}
