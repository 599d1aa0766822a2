/* textfile.c — atomic text outputs (see textfile.h). */
#include "util/textfile.h"
#include "sys/interrupt.h"
#include <errno.h>
#include <string.h>

FILE *textfile_open(const char *path, char *tmp, size_t cap)
{
    FILE *f;
    snprintf(tmp, cap, "%s.tmp", path);
    interrupt_hold();   /* a second Ctrl-C must find the file registered, to remove it */
    f = fopen(tmp, "w");
    if (f) interrupt_temp_add(tmp);
    interrupt_release();
    if (!f) fprintf(stderr, "%s: %s\n", tmp, strerror(errno));
    return f;
}

int textfile_close(FILE *f, const char *tmp, const char *path)
{
    int err = ferror(f);
    err |= fclose(f) != 0;
    interrupt_hold();
    err = err || rename(tmp, path);
    if (err) remove(tmp);
    interrupt_temp_remove(tmp);
    interrupt_release();
    if (err) fprintf(stderr, "%s: could not write\n", path);
    return err ? 1 : 0;
}
