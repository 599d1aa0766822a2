/* scene_file.h — the files a scene names (mtllib, map_Kd...): a name is relative to the folder of
 * the file that names it, and must resolve (symlinks followed) to a regular file inside a root
 * folder, of bounded size: a grading machine renders students' files, which must not read
 * /etc/passwd, /dev/zero (forever) or a FIFO (blocks). */
#ifndef PATHLAB_SCENE_FILE_H
#define PATHLAB_SCENE_FILE_H
#include "scene/objtext.h"

/* The path of file name relative to the folder of file `from` unless absolute (malloc'd; NULL: out of memory). */
char *scene_file_sibling(const char *from, const char *name);
/* The folder of file path, resolved (realpath, malloc'd); NULL with errno set. */
char *scene_file_folder(const char *path);
/* Checks the file `path` that line `key name` of t names: it must resolve into folder root (resolved),
 * be a regular file of at most max bytes. 1 with *real (malloc'd: the resolved path, if real is not
 * NULL), or 0 after printing "file:line: why". */
int scene_file_check(const objtext *t, const char *root, const char *key, const char *name, const char *path, size_t max,
                     char **real);
#endif
