/* input_file.c — see input_file.h. O_NONBLOCK: opening a FIFO without a writer returns at once;
 * the flag is cleared after the checks, so that a pipe given on purpose (regular_only = 0) is read. */
#include "sys/input_file.h"
#include <errno.h>
#include <fcntl.h>
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
