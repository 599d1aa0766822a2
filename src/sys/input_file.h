/* input_file.h — opening a file to read that a student may have made anything: a FIFO, a device,
 * a folder. input_file_open never blocks on a FIFO without a writer (it would hang a whole class's
 * grading); with regular_only, anything but a regular file is refused at once (errno EISDIR for a
 * folder, ENODEV for the rest). NULL with errno set. */
#ifndef PATHLAB_INPUT_FILE_H
#define PATHLAB_INPUT_FILE_H
#include <stdio.h>

FILE *input_file_open(const char *path, int regular_only);
/* The reason for errno after a failed input_file_open, for messages: "a folder, not a file",
 * "not a regular file (a FIFO or a device)", or strerror's. */
const char *input_file_why(int err);
/* A file that another file names (the variance an image's sidecar names): an input, never a place
 * to write, and confined to the folder of `owner` (the image) as a scene's mtllib is. name is joined
 * to owner's folder into dst[cap]; it must not be absolute nor hold a ".." part, its real path
 * (symlinks followed, of the file and of any folder on the way) must lie in owner's folder or below,
 * and it must be a regular file. NULL if so, else the reason, for "NAME: reason" (errno ENOENT when
 * the file does not exist, so that a caller may treat a missing file apart). */
const char *input_file_beside(char *dst, size_t cap, const char *owner, const char *name);
/* input_file_beside for the files of a user's own reference (grade's and compare's --ref): the same
 * name rules, but links are followed wherever they lead (a teacher's store of references). */
const char *input_file_beside_trusted(char *dst, size_t cap, const char *owner, const char *name);
/* The real path of path if path is a symbolic link, links followed (malloc'd); NULL if it is no link
 * or cannot be resolved: for the files a teacher names, whose links to a store of references are
 * theirs, not a student's. */
char *input_file_resolved(const char *path);
/* NULL unless path is a symbolic link whose file lies outside path's folder (or is not a regular
 * file there); then the reason. A dangling link gives NULL: opening it says it is missing. */
const char *input_file_link_out(const char *path);
#endif
