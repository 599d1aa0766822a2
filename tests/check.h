/* check.h — the whole test framework: check() prints one "PASS name" or "FAIL name: detail" line;
 * tests/run.sh counts those lines over every test program and script. A test program ends with
 * `return check_summary();`, which exits nonzero when any check failed. */
#ifndef PATHLAB_CHECK_H
#define PATHLAB_CHECK_H
#include <stdarg.h>
#include <stdio.h>

static int check_failures = 0;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static int check(int ok, const char *name, const char *fmt, ...)
{
    va_list ap;
    printf("%s %s", ok ? "PASS" : "FAIL", name);
    if (fmt && *fmt) {
        printf(ok ? " (" : ": ");
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        if (ok) printf(")");
    }
    printf("\n");
    fflush(stdout);
    if (!ok) check_failures++;
    return ok;
}

static int check_summary(void) { return check_failures ? 1 : 0; }
#endif
