/* cli.h — strict parsing of flag values: every error names the flag and the value, for a student. */
#ifndef PATHLAB_CLI_H
#define PATHLAB_CLI_H
#include <stdint.h>
#include "vec.h"

/* Each returns 0 on success, or prints "pathlab: FLAG expects ..., got 'VALUE'" and returns 1. */
int cli_int(const char *flag, const char *s, int lo, int hi, int *out);
int cli_u64(const char *flag, const char *s, uint64_t *out);
int cli_float(const char *flag, const char *s, float *out);
int cli_vec3(const char *flag, const char *s, vec3 *out);
int cli_size(const char *flag, const char *s, int *w, int *h);
/* One of the names in a NULL-terminated list; *out is its index. */
int cli_choice(const char *flag, const char *s, const char *const *names, int *out);
/* The value after argv[*i], advancing *i; prints an error and returns NULL if missing. */
const char *cli_value(int argc, char **argv, int *i);
#endif
