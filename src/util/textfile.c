/* textfile.c — atomic text outputs (see textfile.h). */
#include "util/textfile.h"
#include "sys/atomic_file.h"

FILE *textfile_open(const char *path, char *tmp, size_t cap) { return atomic_file_create(path, tmp, cap); }

int textfile_close(FILE *f, const char *tmp, const char *path) { return atomic_file_commit(f, tmp, path, 1); }
