/* textfile.h — a text output (report, table) written atomically: to PATH.tmp, renamed over PATH
 * only when complete, so that a failed or interrupted write leaves no half file. */
#ifndef PATHLAB_TEXTFILE_H
#define PATHLAB_TEXTFILE_H
#include <stdio.h>
#include <stddef.h>

/* Opens path.tmp (its name in tmp[cap]); NULL after printing why. */
FILE *textfile_open(const char *path, char *tmp, size_t cap);
/* Closes f and renames tmp over path; 0, or 1 after printing why (tmp removed). */
int textfile_close(FILE *f, const char *tmp, const char *path);
#endif
