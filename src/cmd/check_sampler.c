/* check_sampler.c — `pathlab check-sampler`: reads the flags and the student's file, runs the checks
 * of check/student_check.h and prints them (check/student_print.h). */
#include "cmd/check_sampler.h"
#include "check/student_print.h"
#include "util/cli.h"
#include <stdio.h>
#include <string.h>

#define ERR_LEN 512

typedef struct {
    const char *file;
    student_pdf pdf;
    int has_pdf, has_wo;
    vec3 wo;
    double alpha;
    uint64_t seed;
} options;

static const char *USAGE_FLAGS =
    "  FILE.txt     one direction per line, 'x y z' or 'x y z pdf' (# comments and blank lines ignored):\n"
    "               unit vectors in the local frame where the normal is +z, pdf per steradian\n"
    "  --pdf NAME   the density the directions should follow: uniform (sphere, 1/(4 pi)), hemisphere (1/(2 pi)),\n"
    "               cosine (cos theta / pi), cosm:M ((M+1)/(2 pi) cos^M theta), blinn:M (the reflection of --wo\n"
    "               about a half vector of density (M+1)/(2 pi) cos^M theta_h: pdf = that / (4 wo.h))\n"
    "  --wo X,Y,Z   blinn: the direction toward the eye (z > 0)\n"
    "  --alpha A    chance of a false alarm of the whole check (default 0.01)\n"
    "  --seed S     seed of the reference sample that places the chi-square's cells (default 1)\n"
    "exit status: 0 every check passes, 1 one fails, 2 bad flags or a bad file (FILE:LINE: what is wrong)\n";

static int parse_pdf(void *ctx, const char *flag, const char *value)
{
    options *o = ctx;
    char err[ERR_LEN];
    static const char *const names[] = {"uniform", "hemisphere", "cosine", "cosm:M", "blinn:M", NULL};
    size_t len = strcspn(value, ":");
    int k;
    if (student_pdf_parse(value, &o->pdf, err, sizeof err)) {
        for (k = 0; names[k] && (strncmp(names[k], value, len) || (names[k][len] && names[k][len] != ':')); k++) continue;
        if (!names[k]) return cli_fail_choice("check-sampler", flag, value, names);   /* not a name: the closest */
        fprintf(stderr, "pathlab check-sampler: %s\n", err);
        return 1;
    }
    return 0;
}

/* 0 when the arguments are valid, 1 on an error (after printing why), -1 for --help */
static int parse_options(options *o, int argc, char **argv)
{
    int help = 0, nwords = 0;
    char err[ERR_LEN];
    const cli_flag flags[] = {
        {"--pdf", CLI_CUSTOM, NULL, 0, 0, NULL, parse_pdf, &o->has_pdf},
        {"--wo", CLI_VEC3, &o->wo, 0, 0, NULL, NULL, &o->has_wo},
        {"--alpha", CLI_DOUBLE, &o->alpha, 1e-12, 0.5, NULL, NULL, NULL},
        {"--seed", CLI_U64, &o->seed, 0, 0, NULL, NULL, NULL},
        {"--help", CLI_SWITCH, &help, 0, 0, NULL, NULL, NULL},
        {"-h", CLI_SWITCH, &help, 0, 0, NULL, NULL, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *const tables[] = {flags, NULL};
    memset(o, 0, sizeof *o);
    o->alpha = 0.01, o->seed = 1;
    if (cli_parse("check-sampler", argc, argv, tables, o, &o->file, 1, &nwords)) return 1;
    if (help) return -1;
    if (!nwords || !o->has_pdf) {
        fprintf(stderr, "pathlab check-sampler: %s\n", !nwords ? "which file? (FILE.txt)" : "--pdf is required");
        return 1;
    }
    if ((o->pdf.kind == SPDF_BLINN) != o->has_wo) {
        fprintf(stderr, "pathlab check-sampler: %s\n", o->has_wo ? "--wo is for --pdf blinn:M only" : "--pdf blinn:M needs --wo X,Y,Z");
        return 1;
    }
    if (o->has_wo && student_pdf_set_wo(&o->pdf, dv_of(o->wo), err, sizeof err)) {
        fprintf(stderr, "pathlab check-sampler: %s\n", err);
        return 1;
    }
    return 0;
}

int check_sampler_main(int argc, char **argv)
{
    options o;
    sample_file s;
    student_report r;
    char err[ERR_LEN];
    int rc = parse_options(&o, argc, argv), failed;
    if (rc < 0) return printf("usage:\n%s%s", CHECK_SAMPLER_USAGE, USAGE_FLAGS), 0;
    if (rc > 0) return fprintf(stderr, "usage:\n%s", CHECK_SAMPLER_USAGE), 2;
    if (sample_file_read(o.file, &s, err, sizeof err)) return fprintf(stderr, "pathlab check-sampler: %s\n", err), 2;
    if (student_check_run(&s, &o.pdf, o.alpha, o.seed, &r)) {
        sample_file_free(&s);
        return fprintf(stderr, "pathlab check-sampler: out of memory\n"), 1;
    }
    failed = student_print(o.file, &s, &r, &o.pdf, o.alpha, o.seed);
    rc = failed ? 1 : s.n < STUDENT_MIN_SAMPLES ? 2 : 0;   /* too few to judge: neither pass nor fail */
    sample_file_free(&s);
    return rc;
}
