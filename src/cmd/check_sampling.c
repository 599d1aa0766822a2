/* check_sampling.c — `pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]`: runs the
 * cases of check/cases.h and prints one row per sampling routine (check_sampling.h). */
#include "cmd/check_sampling.h"
#include "check/cases.h"
#include "check/run.h"
#include "check/verdict.h"
#include "stats/significance.h"
#include "sys/clock.h"
#include "sys/parallel.h"
#include "util/cli.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_SAMPLES 1000000   /* per case (the BRDF cases draw half): a few seconds on two cores */
#define NAME_WIDTH 47

typedef struct { long samples; uint64_t seed; int threads, quiet; } options;

static const char *USAGE_LINE = "usage: pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]\n";
static const char *USAGE_FLAGS =
    "  --samples N   samples per case (default 1000000; the BRDF cases draw N/2)\n"
    "  --seed S      random seed (default 1)\n"
    "  --threads T   worker threads (default: every core); the results do not depend on it\n"
    "  --quiet       print only the failing rows and the summary line\n";

/* 0 when the flags are valid, 1 on an error (after printing why and the usage line), -1 for --help */
static int parse_options(options *o, int argc, char **argv)
{
    int samples = DEFAULT_SAMPLES, help = 0, nwords;
    const cli_flag flags[] = {
        {"--samples", CLI_INT, &samples, 1000, 1 << 30, NULL, NULL, NULL},
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

static const char *group_title(sampling_case_kind k)
{
    switch (k) {
    case CASE_WARP: return "sampling.c: directions about the normal (cos_power: Blinn's half vector); cells in (1 - cos theta, phi)";
    case CASE_BRDF: return "brdf.c: brdf_sample (glossy: the reflected direction; mixed: both lobes); cells of the half vector";
    case CASE_TRIANGLE: return "sampling.c: a uniform point on a triangle; 16 x 16 sub-triangles";
    case CASE_LIGHT_CHOICE: return "light.c: the choice of an emitter among 5; one cell per emitter";
    case CASE_LIGHT_POINT: return "light.c: the point on the emitter; sub-triangles, or Arvo's (u1, u2) for solid-angle";
    }
    return "";
}

static void print_row(const sampling_result *r, double alpha_case)
{
    char p[16], integral[32], gap[16], verdict[48] = "pass", why[40] = "";
    int k, ok_integrals = 1;
    for (k = 0; k < r->nintegrals; k++) ok_integrals &= sampling_integral_pass(r, k);
    snprintf(p, sizeof p, r->chi2.p >= 1e-3 ? "%.3f" : "%.1e", r->chi2.p);
    if (r->nintegrals) snprintf(integral, sizeof integral, "%8.5f %8.5f", r->integral[0], r->integral_want[0]);
    else snprintf(integral, sizeof integral, "%8s %8s", "-", "-");
    if (r->has_formula) snprintf(gap, sizeof gap, "%.1e", r->formula_gap);
    else snprintf(gap, sizeof gap, "-");
    if (!sampling_chi2_pass(r, alpha_case)) strcat(why, ", chi2");
    if (!ok_integrals) strcat(why, ", integral");
    if (!sampling_pdf_pass(r)) strcat(why, ", pdf");
    if (!sampling_samples_pass(r)) strcat(why, ", samples");
    if (*why) snprintf(verdict, sizeof verdict, "FAIL (%s)", why + 2);
    printf("  %-*.*s %9.1f %5d %8s %s %8s  %s\n", NAME_WIDTH, NAME_WIDTH, r->routine, r->chi2.chi2, r->chi2.dof, p,
           integral, gap, verdict);
}

static void print_table(const sampling_case *c, const sampling_result *r, int n, double alpha_case, int quiet)
{
    int i, header = 0;
    for (i = 0; i < n; i++) {
        if (quiet && sampling_result_pass(&r[i], alpha_case)) continue;
        if (!header++)
            printf("  %-*s %9s %5s %8s %8s %8s %8s  %s\n", NAME_WIDTH, "routine", "chi2", "dof", "p-value", "integral",
                   "want", "pdf err", "verdict");
        if (!quiet && (i == 0 || c[i].kind != c[i - 1].kind)) printf("%s\n", group_title(c[i].kind));
        print_row(&r[i], alpha_case);
    }
}

static void print_legend(int n, double alpha_case)
{
    printf("chi2: Pearson's statistic over the cells (those expected under 5 pooled into one); p-value:\n"
           "the chance of a chi2 this large if the samples follow the pdf. FAIL below %.3g, so that all\n"
           "%d cases together pass with probability 1 - %g (Sidak: 1 - (1 - %g)^(1/%d)).\n"
           "integral: the pdf integrated numerically over its domain, to %g of want (want < 1: that share\n"
           "of the reflected directions goes below the surface).\n"
           "pdf err: worst relative gap between the pdf function and the course's formula in double. Also\n"
           "checked: the pdf a sampler returns is the function's; the samples are where they belong (unit\n"
           "directions above the surface, points on their triangle).\n",
           alpha_case, n, CHECK_ALPHA, CHECK_ALPHA, n, CHECK_INTEGRAL_TOL);
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
    print_table(cases, r, n, alpha_case, o.quiet);
    if (!o.quiet) print_legend(n, alpha_case);
    printf("%d passed, %d failed (%.1f s)\n", n - failed, failed, clock_seconds() - t0);
    free(r);
    return failed ? 1 : 0;
}
