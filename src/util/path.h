/* path.h — a path's parts and what it names on disk: the file name after the last '/', whether a
 * name ends with a suffix (".pfm"), whether a path is a folder, a readable file, or the same file
 * as another path (two spellings of one file: ./ref.pfm and ref.pfm). */
#ifndef PATHLAB_PATH_H
#define PATHLAB_PATH_H

/* The part after the last '/' (all of it without one). */
const char *path_file_name(const char *path);
/* 1 if name ends with suffix. */
int path_ends_with(const char *name, const char *suffix);
/* 1 if path is a folder. */
int path_is_dir(const char *path);
/* 1 if path is a file that can be opened for reading (not a folder). */
int path_is_readable(const char *path);
/* 1 if the two paths name the same file or folder. */
int path_same_file(const char *a, const char *b);
#endif
