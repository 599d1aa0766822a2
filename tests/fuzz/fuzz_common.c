/* fuzz_common.c — the private temporary folder of a harness (see fuzz_common.h). */
#include "fuzz_common.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NSLOTS 6
static char dir[4096];
static char paths[NSLOTS][4096 + 64];
static const char *names[NSLOTS];   /* what each slot last held, to be removed at exit */

static void remove_all(void)
{
    int i;
    for (i = 0; i < NSLOTS; i++)
        if (names[i]) unlink(paths[i]);
    rmdir(dir);
}

static void make_dir(void)
{
    const char *tmp = getenv("TMPDIR");
    if (dir[0]) return;
    snprintf(dir, sizeof dir, "%s/pathlab-fuzz.XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(dir)) {
        perror(dir);
        abort();
    }
    atexit(remove_all);
}

const char *fuzz_absent(int slot, const char *name)
{
    make_dir();
    if (slot < 0 || slot >= NSLOTS || strchr(name, '/')) abort();
    snprintf(paths[slot], sizeof paths[slot], "%s/%s", dir, name);
    names[slot] = name;
    unlink(paths[slot]);
    return paths[slot];
}

const char *fuzz_write(int slot, const char *name, const uint8_t *data, size_t n)
{
    const char *path = fuzz_absent(slot, name);
    FILE *f = fopen(path, "wb");
    if (!f || (n && fwrite(data, 1, n, f) != n) || fclose(f)) {
        perror(path);
        abort();
    }
    return path;
}
