/* replay.c — runs a harness of tests/fuzz/ on files without libFuzzer (any compiler): each
 * argument is one input. tests/test_fuzz_seeds.sh replays the seed corpus through it, and a
 * reproducer can be stepped through in a debugger built this way. */
#include <stdio.h>
#include <stdlib.h>
#include "fuzz_common.h"

static int replay(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    long n;
    if (!f || fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) {
        fprintf(stderr, "%s: cannot read\n", path);
        if (f) fclose(f);
        return 1;
    }
    buf = malloc(n ? (size_t)n : 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) {
        fprintf(stderr, "%s: cannot read\n", path);
        free(buf);
        fclose(f);
        return 1;
    }
    fclose(f);
    LLVMFuzzerTestOneInput(buf, (size_t)n);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    int i, err = 0;
    for (i = 1; i < argc; i++) err |= replay(argv[i]);
    printf("replayed %d inputs\n", argc - 1);   /* tests/test_fuzz_seeds.sh checks that all ran */
    return err;
}
