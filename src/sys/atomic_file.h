/* atomic_file.h — write a file whole or not at all (every image, page and sidecar pathlab writes).
 * atomic_file_open: opens "<path>.tmp.XXXXXX" in path's folder, with the permissions fopen would give;
 *   *tmp receives its name. NULL (and a message "path: reason" on stderr) on error.
 * atomic_file_close: when ok and every byte reached the disk, renames the temporary file over path;
 *   otherwise removes it. Frees tmp. Returns 0 when path now holds the new file. */
#ifndef PATHLAB_ATOMIC_FILE_H
#define PATHLAB_ATOMIC_FILE_H
#include <stdio.h>

FILE *atomic_file_open(const char *path, char **tmp);
int atomic_file_close(FILE *f, char *tmp, const char *path, int ok);
#endif
