/* atomic_file.h — write a file whole or not at all (every image, page, report and sidecar pathlab
 * writes), through one routine that nothing planted can divert:
 * atomic_file_create: creates "<path>.tmp.XXXXXX" in path's folder (mkstemp: O_CREAT | O_EXCL with
 *   a random name, so a symlink or file planted under any fixed name is never followed or reused),
 *   its name into tmp[cap]. The new file gets the mode of the file it will replace, or else the one
 *   fopen would give (0666 minus the umask). A target that exists and is not a regular file, or is
 *   read-only (no owner write bit: a teacher's protected reference), is refused. NULL (and "path:
 *   reason" on stderr) on error.
 * atomic_file_commit: when ok and every byte reached the file, renames it over path (rename replaces
 *   a symlink at path, never its target); otherwise removes it. 0 when path now holds the new file;
 *   else 1 after printing "path: cannot write: <the system's reason>" (when ok).
 * atomic_file_open / atomic_file_close: the same with a name allocated here (freed by close).
 * atomic_file_why: the reason of the last failure as it was printed ("cannot write: No space left on
 *   device"), for a report that says why an output is missing; "" when the last write did not fail. */
#ifndef PATHLAB_ATOMIC_FILE_H
#define PATHLAB_ATOMIC_FILE_H
#include <stddef.h>
#include <stdio.h>

/* A set of files renamed together (a render's image, variance, layers and sidecars: render_files.c)
 * is first written to "FINAL" ATOMIC_FILE_STAGED; a message about such a file names FINAL, the file
 * the user asked for: atomic_file_shown(path) is path without that suffix (static storage). */
#define ATOMIC_FILE_STAGED ".pending"
const char *atomic_file_shown(const char *path);
FILE *atomic_file_create(const char *path, char *tmp, size_t cap);
int atomic_file_commit(FILE *f, const char *tmp, const char *path, int ok);
FILE *atomic_file_open(const char *path, char **tmp);
int atomic_file_close(FILE *f, char *tmp, const char *path, int ok);
const char *atomic_file_why(void);
#endif
