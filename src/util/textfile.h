/* textfile.h — a text output (report, table, sidecar, view file) written atomically through
 * sys/atomic_file.h: to a temporary file of a random name beside PATH, created exclusively, renamed
 * over PATH only when complete, so that a failed or interrupted write leaves no half file and no
 * planted link is followed. */
#ifndef PATHLAB_TEXTFILE_H
#define PATHLAB_TEXTFILE_H
#include <stdio.h>
#include <stddef.h>

/* Opens the temporary file of path (its name in tmp[cap]); NULL after printing why. */
FILE *textfile_open(const char *path, char *tmp, size_t cap);
/* Closes f and renames tmp over path; 0, or 1 after printing "path: cannot write: reason" (tmp
 * removed). */
int textfile_close(FILE *f, const char *tmp, const char *path);
#endif
