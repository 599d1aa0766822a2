/* check_sampler.c — `pathlab check-sampler`: reads the flags and the student's file, runs the checks
 * of check/student_check.h and prints one verdict line per check, with the diagnoses of
 * check/student_diagnosis.h under the failing ones (check_sampler.h). */
#include "cmd/check_sampler.h"
#include "check/student_diagnosis.h"
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
    (void)flag;
    if (student_pdf_parse(value, &o->pdf, err, sizeof err)) {
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

/* One verdict line; returns 1 if it failed. */
static int verdict(const char *check, int ok, const char *detail)
{
    printf("%-16s %s  %s\n", check, ok ? "pass" : "FAIL", detail);
    return !ok;
}

static void print_diagnosis(int found, const char *why)
{
    if (found) printf("%-16s       -> %s\n", "", why);
}

/* 0 and 1: the directions; returns the number of failed checks. */
static int print_directions(const student_report *r, const student_pdf *p)
{
    char line[ERR_LEN], why[ERR_LEN];
    int failed = 0;
    if (p->kind == SPDF_BLINN)
        snprintf(line, sizeof line, "%ld directions below the surface, %.1f expected (their own chi-square cell)", r->below,
                 r->below_expected);
    else if (p->kind == SPDF_UNIFORM) snprintf(line, sizeof line, "the whole sphere");
    else snprintf(line, sizeof line, "%ld directions below the surface (z <= 0)", r->below);
    failed += verdict("0. domain", student_domain_pass(r), line);
    snprintf(line, sizeof line, "chi2 = %.1f, %d dof, p = %.3g (fail below %.3g); %d x %d cells in (1 - cos theta%s, phi)%s",
             r->chi2.chi2.chi2, r->chi2.chi2.dof, r->chi2.chi2.p, r->alpha_each, r->chi2.rings, SPHERE_SECTORS,
             p->kind == SPDF_BLINN ? "_h" : "", p->kind == SPDF_BLINN ? " + below the surface" : "");
    failed += verdict("1. chi-square", student_chi2_pass(r), line);
    if (r->chi2.chi2.dof < 1)
        printf("%-16s       -> too few samples: the cells pooled into one (each needs 5 expected); write 100000\n", "");
    if (r->K >= 0.0)
        printf("%-16s       the lobe: mean cos theta%s fits cos^K with K = %.3f +- %.3f (claimed %g)\n", "",
               p->kind == SPDF_BLINN ? "_h" : "", r->K, r->K_se, p->m);
    if (failed && r->chi2.chi2.dof >= 1) print_diagnosis(student_diagnose_directions(r, p, why, sizeof why), why);
    return failed;
}

/* 2: the named density's integral and the column's normalisation. */
static int print_integrals(const sample_file *s, const student_report *r, const student_pdf *p, const char *name)
{
    char line[ERR_LEN];
    int failed = 0;
    snprintf(line, sizeof line, "%s integrates to %.6f over %s (pathlab's formula, by quadrature)", name, r->integral,
             p->kind == SPDF_BLINN ? "the half vectors" : "the sphere");
    failed += verdict("2. integral", student_integral_pass(r), line);
    if (!s->pdf) return failed;
    snprintf(line, sizeof line, "mean of %s / your pdf = %.5g +- %.2g, want %.5g%s%s", p->kind == SPDF_BLINN ? "blinn" : name,
             r->norm, r->norm_se, r->binned_mass, p->kind == SPDF_BLINN ? " = P(above the surface)" : "",
             r->zero_pdf ? " (and some pdf are 0)" : "");
    failed += verdict("   normalisation", student_norm_pass(r), line);
    printf("%-16s       mean of 1 / your pdf over %s = %.5g +- %.2g, want %.5g (information: heavy-tailed)\n", "",
           p->kind == SPDF_UNIFORM ? "the sphere" : "z > 0", r->inv, r->inv_se, r->measure);
    return failed;
}

/* 3: the column against the named density. */
static int print_ratio(const sample_file *s, const student_report *r, const student_pdf *p, const char *name)
{
    char line[ERR_LEN], why[ERR_LEN];
    int ok = student_ratio_pass(r);
    if (!s->pdf) {
        printf("%-16s -     no pdf column in the file: write 'x y z pdf' to check the pdf your code returns\n", "3. pdf column");
        return 0;
    }
    snprintf(line, sizeof line, "your pdf / %s: median %.6g, from %.6g to %.6g; %ld of %ld directions off by more than 1e-3",
             p->kind == SPDF_BLINN ? "blinn" : name, r->ratio_median, r->ratio_min, r->ratio_max, r->ratio_bad, r->ratio_n);
    verdict("3. pdf column", ok, line);
    if (ok) return 0;
    printf("%-16s       worst: line %ld, your pdf %.6g, %s gives %.6g\n", "", r->worst_line, r->worst_col,
           p->kind == SPDF_BLINN ? "blinn" : name, r->worst_named);
    print_diagnosis(student_diagnose_pdf(s, p, r, why, sizeof why), why);
    return 1;
}

int check_sampler_main(int argc, char **argv)
{
    options o;
    sample_file s;
    student_report r;
    char err[ERR_LEN], name[128];
    int rc = parse_options(&o, argc, argv), failed;
    if (rc < 0) return printf("usage:\n%s%s", CHECK_SAMPLER_USAGE, USAGE_FLAGS), 0;
    if (rc > 0) return fprintf(stderr, "usage:\n%s", CHECK_SAMPLER_USAGE), 2;
    if (sample_file_read(o.file, &s, err, sizeof err)) return fprintf(stderr, "pathlab check-sampler: %s\n", err), 2;
    if (student_check_run(&s, &o.pdf, o.alpha, o.seed, &r)) {
        sample_file_free(&s);
        return fprintf(stderr, "pathlab check-sampler: out of memory\n"), 1;
    }
    student_pdf_name(&o.pdf, name, sizeof name);
    printf("pathlab check-sampler %s: %ld directions%s, against %s\n", o.file, s.n, s.pdf ? " and their pdf" : "", name);
    printf("alpha %g for the whole check: %.3g for each of its %d statistical tests (Sidak); seed %llu\n", o.alpha,
           r.alpha_each, s.pdf ? 2 : 1, (unsigned long long)o.seed);
    if (s.n < STUDENT_MIN_SAMPLES)
        printf("warning: only %ld samples: under %d the chi-square's cells pool into few; write 100000\n", s.n,
               STUDENT_MIN_SAMPLES);
    if (o.pdf.kind == SPDF_BLINN) name[strcspn(name, " ")] = 0;
    failed = print_directions(&r, &o.pdf);
    failed += print_integrals(&s, &r, &o.pdf, name);
    failed += print_ratio(&s, &r, &o.pdf, name);
    printf("%s: %d check%s failed\n", failed ? "FAIL" : "pass", failed, failed == 1 ? "" : "s");
    sample_file_free(&s);
    return failed ? 1 : 0;
}
