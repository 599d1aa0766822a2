/* check_sampling.c — `pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]`: runs the
 * cases of check/cases.h and prints one row per sampling routine (check/sampling_table.h). */
#include "cmd/check_sampling.h"
#include "check/cases.h"
#include "check/run.h"
#include "check/sampling_table.h"
#include "check/verdict.h"
#include "stats/significance.h"
#include "sys/clock.h"
#include "sys/parallel.h"
#include "util/cli.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_SAMPLES 1000000   /* per case (the BRDF cases draw half): a few seconds on two cores */
/* Fewer, and a correct sampler fails: its cells pool into one (0 dof). Measured on pathlab's own
 * samplers: 23 of 63 cases at 1000, 4 to 9 at 2000 to 3000, none at 4000 (several seeds). */
#define MIN_SAMPLES 10000

typedef struct { long samples; uint64_t seed; int threads, quiet; } options;

static const char *USAGE_LINE = "usage: pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]\n";
static const char *USAGE_FLAGS =
    "  --samples N   samples per case (default 1000000, at least 10000; the BRDF cases draw N/2)\n"
    "  --seed S      random seed (default 1)\n"
    "  --threads T   worker threads (default: every core); the results do not depend on it\n"
    "  --quiet       print only the failing rows and the summary line\n";

/* 0 when the flags are valid, 1 on an error (after printing why and the usage line), -1 for --help */
static int parse_options(options *o, int argc, char **argv)
{
    int samples = DEFAULT_SAMPLES, help = 0, nwords;
    const cli_flag flags[] = {
        {"--samples", CLI_INT, &samples, MIN_SAMPLES, 1 << 30, NULL, NULL, NULL},
        {"--seed", CLI_U64, &o->seed, 0, 0, NULL, NULL, NULL},
        {"--threads", CLI_INT, &o->threads, 1, PARALLEL_MAX_THREADS, NULL, NULL, NULL},
        {"--quiet", CLI_SWITCH, &o->quiet, 0, 0, NULL, NULL, NULL},
        {"--help", CLI_SWITCH, &help, 0, 0, NULL, NULL, NULL},
        {"-h", CLI_SWITCH, &help, 0, 0, NULL, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *const tables[] = {flags, NULL};
    o->seed = 1, o->quiet = 0;
    o->threads = parallel_default_threads();
    if (cli_parse("check-sampling", argc, argv, tables, NULL, NULL, 0, &nwords)) {
        fputs(USAGE_LINE, stderr);
        return 1;
    }
    o->samples = samples;
    return help ? -1 : 0;
}

int check_sampling_main(int argc, char **argv)
{
    sampling_case cases[CHECK_MAX_CASES];
    sampling_result *r;
    options o;
    double alpha_case, t0 = clock_seconds();
    int n, i, failed = 0;
    if ((i = parse_options(&o, argc, argv)) > 0) return 2;
    if (i < 0) {
        printf("%s%s", USAGE_LINE, USAGE_FLAGS);
        return 0;
    }
    n = check_sampling_cases(cases, CHECK_MAX_CASES);
    alpha_case = sidak_level(CHECK_ALPHA, n);
    if (!(r = malloc(sizeof *r * (size_t)n))) {
        fprintf(stderr, "pathlab: check-sampling: out of memory\n");
        return 1;
    }
    if (!o.quiet)
        printf("pathlab check-sampling: %d cases, %ld samples each (BRDF cases %ld), seed %llu, %d threads\n", n,
               o.samples, o.samples / 2, (unsigned long long)o.seed, o.threads);
    fflush(stdout);
    check_sampling_run_all(cases, n, o.samples, o.seed, o.threads, r);
    for (i = 0; i < n; i++) failed += !sampling_result_pass(&r[i], alpha_case);
    sampling_print_table(cases, r, n, alpha_case, o.quiet);
    if (!o.quiet) sampling_print_legend(n, alpha_case);
    printf("%d passed, %d failed (%.1f s)\n", n - failed, failed, clock_seconds() - t0);
    free(r);
    return failed ? 1 : 0;
}
