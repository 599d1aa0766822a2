/* atomic_file.c — files written whole or not at all: a temporary file next to the target, renamed
 * over it only after fflush and fclose succeeded, so that a crash, a full disk or Ctrl-C never leaves a
 * half-written file and an existing file stays untouched when the write fails. The temporary name is
 * registered with interrupt.c, which removes it on a second signal. */
#include "sys/atomic_file.h"
#include "sys/interrupt.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The permissions fopen would have given the file: 0666 minus the umask. mkstemp creates files
 * 0600, which would make every image private. umask can only be read by setting it, so this is
 * not thread-safe; images are written from the main thread after rendering. */
static mode_t creation_mode(void)
{
    mode_t mask = umask(022);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

/* Opens a temporary file next to path; *tmp receives its name (to free). NULL on error. */
FILE *atomic_file_open(const char *path, char **tmp)
{
    size_t n = strlen(path);
    int fd;
    FILE *f;
    *tmp = malloc(n + sizeof ".tmp.XXXXXX");
    if (!*tmp) {
        fprintf(stderr, "%s: out of memory\n", path);
        return NULL;
    }
    memcpy(*tmp, path, n);
    memcpy(*tmp + n, ".tmp.XXXXXX", sizeof ".tmp.XXXXXX");
    interrupt_hold();   /* a second Ctrl-C must find the file registered, to remove it */
    fd = mkstemp(*tmp);
    if (fd >= 0) interrupt_temp_add(*tmp);
    interrupt_release();
    if (fd < 0) {
        fprintf(stderr, "%s: cannot create a temporary file: %s\n", path, strerror(errno));
        free(*tmp);
        *tmp = NULL;
        return NULL;
    }
    if (fchmod(fd, creation_mode()) != 0 || !(f = fdopen(fd, "wb"))) {
        fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
        close(fd);
        unlink(*tmp);
        interrupt_temp_remove(*tmp);
        free(*tmp);
        *tmp = NULL;
        return NULL;
    }
    return f;
}

/* Finishes an atomic write: when ok and the data reached the file, renames tmp over path.
 * Otherwise removes tmp. Frees tmp. Returns 0 when path now holds the new file. */
int atomic_file_close(FILE *f, char *tmp, const char *path, int ok)
{
    int err = 0;
    if (ok && fflush(f) != 0) err = errno;
    if (ok && !err && ferror(f)) err = EIO;
    if (fclose(f) != 0 && ok && !err) err = errno;
    interrupt_hold();
    if (ok && !err && rename(tmp, path) != 0) err = errno;
    if (!ok || err) unlink(tmp);
    interrupt_temp_remove(tmp);
    interrupt_release();
    if (ok && err) fprintf(stderr, "%s: cannot write: %s\n", path, strerror(err));
    free(tmp);
    return (ok && !err) ? 0 : 1;
}
