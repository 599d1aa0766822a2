/* cli.c — flag value parsing. */
#include "cli.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int bad(const char *flag, const char *what, const char *s)
{
    fprintf(stderr, "pathlab: %s expects %s, got '%s'\n", flag, what, s);
    return 1;
}

int cli_int(const char *flag, const char *s, int lo, int hi, int *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi) {
        char what[96];
        sprintf(what, "a whole number from %d to %d", lo, hi);
        return bad(flag, what, s);
    }
    *out = (int)v;
    return 0;
}

int cli_u64(const char *flag, const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (end == s || *end || errno || s[0] == '-') return bad(flag, "a whole number >= 0", s);
    *out = (uint64_t)v;
    return 0;
}

int cli_float(const char *flag, const char *s, float *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v)) return bad(flag, "a number", s);
    *out = (float)v;
    return 0;
}

int cli_vec3(const char *flag, const char *s, vec3 *out)
{
    double v[3];
    char *end;
    const char *p = s;
    int i;
    for (i = 0; i < 3; i++) {
        v[i] = strtod(p, &end);
        if (end == p || !isfinite(v[i]) || *end != (i < 2 ? ',' : '\0')) return bad(flag, "three numbers x,y,z", s);
        p = end + 1;
    }
    *out = v3((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

int cli_size(const char *flag, const char *s, int *w, int *h)
{
    char *end;
    long a, b;
    a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X')) return bad(flag, "WIDTHxHEIGHT, e.g. 512x512", s);
    s = end + 1;
    b = strtol(s, &end, 10);
    if (end == s || *end || a < 1 || b < 1 || a > 65536 || b > 65536) return bad(flag, "WIDTHxHEIGHT, each 1 to 65536", s);
    *w = (int)a;
    *h = (int)b;
    return 0;
}

int cli_choice(const char *flag, const char *s, const char *const *names, int *out)
{
    char what[256] = "one of";
    int i;
    for (i = 0; names[i]; i++) {
        if (!strcmp(s, names[i])) { *out = i; return 0; }
    }
    for (i = 0; names[i] && strlen(what) + strlen(names[i]) + 3 < sizeof what; i++) {
        strcat(what, i ? ", " : " ");
        strcat(what, names[i]);
    }
    return bad(flag, what, s);
}

const char *cli_value(int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        fprintf(stderr, "pathlab: %s needs a value (see pathlab help)\n", argv[*i]);
        return NULL;
    }
    return argv[++*i];
}
