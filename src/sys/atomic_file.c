/* atomic_file.c — files written whole or not at all: a temporary file next to the target, renamed
 * over it only after fflush and fclose succeeded, so that a crash, a full disk or Ctrl-C never leaves a
 * half-written file and an existing file stays untouched when the write fails. The temporary name is
 * random and created exclusively (mkstemp), and registered with interrupt.c, which removes it on a
 * signal. */
#include "sys/atomic_file.h"
#include "sys/interrupt.h"
#include "sys/output_path.h"
#include "sys/shown.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define TMP_SUFFIX ".tmp.XXXXXX"

const char *atomic_file_shown(const char *path)
{
    static char final[PATH_CAP];
    size_t n = strlen(path), k = strlen(ATOMIC_FILE_STAGED);
    if (n <= k || strcmp(path + n - k, ATOMIC_FILE_STAGED) || n - k >= sizeof final) return path;
    memcpy(final, path, n - k);
    final[n - k] = '\0';
    return final;
}

static char why[256];   /* the last failure's reason, for atomic_file_why() */

/* "path: text" on stderr, text kept as the reason. */
static void fail(const char *path, const char *text)
{
    snprintf(why, sizeof why, "%s", text);
    fprintf(stderr, "%s: %s\n", shown(atomic_file_shown(path)), text);
}

/* "what: the system's reason", as fail() says it. */
static void fail_errno(const char *path, const char *what, int err)
{
    char text[224];
    snprintf(text, sizeof text, "%s: %s", what, strerror(err));
    fail(path, text);
}

const char *atomic_file_why(void) { return why; }

/* The permissions fopen would have given the file: 0666 minus the umask. mkstemp creates files
 * 0600, which would make every image private. umask can only be read by setting it, so this is
 * not thread-safe; files are written from the main thread. */
static mode_t creation_mode(void)
{
    mode_t mask = umask(022);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

/* The mode the new file gets: the replaced file's (a private report stays private), or fopen's.
 * 0 after printing why when the target must not be replaced. */
static int target_mode(const char *path, mode_t *mode)
{
    struct stat st;
    *mode = creation_mode();
    if (lstat(path, &st) != 0) return 1;              /* a new file */
    if (S_ISLNK(st.st_mode)) return 1;                /* the rename replaces the link itself */
    if (!S_ISREG(st.st_mode)) {
        fail(path, "exists and is not a regular file: not replaced");
        return 0;
    }
    if (!(st.st_mode & S_IWUSR)) {
        fail(path, "is read-only: not replaced (chmod u+w it, or write elsewhere)");
        return 0;
    }
    *mode = st.st_mode & 07777;
    return 1;
}

FILE *atomic_file_create(const char *path, char *tmp, size_t cap)
{
    mode_t mode;
    int fd;
    FILE *f;
    why[0] = '\0';
    if (snprintf(tmp, cap, "%s" TMP_SUFFIX, path) >= (int)cap) {
        fail(path, "name too long");
        return NULL;
    }
    if (!target_mode(path, &mode)) return NULL;
    interrupt_hold();   /* a signal must find the file registered, to remove it */
    fd = mkstemp(tmp);
    if (fd >= 0) interrupt_temp_add(tmp);
    interrupt_release();
    if (fd < 0) {
        fail_errno(path, "cannot create a temporary file beside it", errno);
        return NULL;
    }
    if (fchmod(fd, mode) != 0 || !(f = fdopen(fd, "wb"))) {
        fail_errno(path, "cannot write", errno);
        close(fd);
        interrupt_hold();
        unlink(tmp);
        interrupt_temp_remove(tmp);
        interrupt_release();
        return NULL;
    }
    return f;
}

int atomic_file_commit(FILE *f, const char *tmp, const char *path, int ok)
{
    int err = 0;
    if (ok && fflush(f) != 0) err = errno;
    if (ok && !err && ferror(f)) err = errno ? errno : EIO;   /* the failed write's reason (ENOSPC), when still there */
    if (fclose(f) != 0 && ok && !err) err = errno;
    interrupt_hold();
    if (ok && !err && rename(tmp, path) != 0) err = errno;
    if (!ok || err) unlink(tmp);
    interrupt_temp_remove(tmp);
    interrupt_release();
    if (ok && err) fail_errno(path, "cannot write", err);
    if (ok && err) errno = err;   /* for the caller's own words (a report's row) */
    return (ok && !err) ? 0 : 1;
}

FILE *atomic_file_open(const char *path, char **tmp)
{
    size_t cap = strlen(path) + sizeof TMP_SUFFIX;
    FILE *f;
    if (!(*tmp = malloc(cap))) {
        fail(path, "out of memory");
        return NULL;
    }
    if (!(f = atomic_file_create(path, *tmp, cap))) {
        free(*tmp);
        *tmp = NULL;
    }
    return f;
}

int atomic_file_close(FILE *f, char *tmp, const char *path, int ok)
{
    int rc = atomic_file_commit(f, tmp, path, ok);
    free(tmp);
    return rc;
}
