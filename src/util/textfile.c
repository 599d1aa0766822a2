/* textfile.c — atomic text outputs (see textfile.h). */
#include "util/textfile.h"
#include <errno.h>
#include <string.h>

FILE *textfile_open(const char *path, char *tmp, size_t cap)
{
    FILE *f;
    snprintf(tmp, cap, "%s.tmp", path);
    if (!(f = fopen(tmp, "w"))) fprintf(stderr, "%s: %s\n", tmp, strerror(errno));
    return f;
}

int textfile_close(FILE *f, const char *tmp, const char *path)
{
    int err = ferror(f);
    err |= fclose(f) != 0;
    if (err || rename(tmp, path)) {
        fprintf(stderr, "%s: could not write\n", path);
        remove(tmp);
        return 1;
    }
    return 0;
}
