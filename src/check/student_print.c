/* student_print.c — check-sampler's lines: the verdicts and the diagnoses (student_print.h). */
#include "check/student_print.h"
#include "sys/shown.h"
#include <stdio.h>
#include <string.h>
#include "check/student_diagnosis.h"

#define ERR_LEN 512

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
    else snprintf(line, sizeof line, "%ld directions below the surface (z < 0)", r->below);
    failed += verdict("0. domain", student_domain_pass(r), line);
    snprintf(line, sizeof line, "chi2 = %.1f, %d dof, p = %.3g (fail below %.3g); %d x %d cells in (1 - cos theta%s, phi)%s",
             r->chi2.chi2.chi2, r->chi2.chi2.dof, r->chi2.chi2.p, r->alpha_each, r->chi2.rings, SPHERE_SECTORS,
             p->kind == SPDF_BLINN ? "_h" : "", p->kind == SPDF_BLINN ? " + below the surface" : "");
    if (r->n < STUDENT_MIN_SAMPLES)   /* its cells pool into few: a correct sampler would fail it */
        printf("%-16s -     not judged: only %ld samples, the chi-square needs %d (5 expected in each cell); write 100000\n",
               "1. chi-square", r->n, STUDENT_MIN_SAMPLES);
    else failed += verdict("1. chi-square", student_chi2_pass(r), line);
    if (r->n >= STUDENT_MIN_SAMPLES && r->chi2.chi2.dof < 1)
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
    snprintf(line, sizeof line, "your pdf / %s: median %.6g, from %.6g to %.6g; %ld of %ld directions off by more than 1e-3 (more near the horizon, where a printed digit weighs more)",
             p->kind == SPDF_BLINN ? "blinn" : name, r->ratio_median, r->ratio_min, r->ratio_max, r->ratio_bad, r->ratio_n);
    verdict("3. pdf column", ok, line);
    if (ok) return 0;
    printf("%-16s       worst: line %ld, your pdf %.6g, %s gives %.6g\n", "", r->worst_line, r->worst_col,
           p->kind == SPDF_BLINN ? "blinn" : name, r->worst_named);
    print_diagnosis(student_diagnose_pdf(s, p, r, why, sizeof why), why);
    return 1;
}

int student_print(const char *file, const sample_file *s, const student_report *r, const student_pdf *p, double alpha,
                  uint64_t seed)
{
    char name[128];
    int failed;
    student_pdf_name(p, name, sizeof name);
    printf("pathlab check-sampler %s: %ld directions%s, against %s\n", shown(file), s->n, s->pdf ? " and their pdf" : "", name);
    printf("alpha %g for the whole check: %.3g for each of its %d statistical tests (Sidak); seed %llu\n", alpha,
           r->alpha_each, s->pdf ? 2 : 1, (unsigned long long)seed);
    if (s->n < STUDENT_MIN_SAMPLES)
        printf("warning: only %ld samples: under %d the chi-square's cells pool into few, a correct sampler would fail it: "
               "not judged; write 100000\n", s->n, STUDENT_MIN_SAMPLES);
    if (p->kind == SPDF_BLINN) name[strcspn(name, " ")] = 0;
    failed = print_directions(r, p);
    failed += print_integrals(s, r, p, name);
    failed += print_ratio(s, r, p, name);
    if (!failed && s->n < STUDENT_MIN_SAMPLES)
        printf("NOT JUDGED: the other checks pass, but %ld samples are too few for the chi-square (at least %d)\n", s->n,
               STUDENT_MIN_SAMPLES);
    else printf("%s: %d check%s failed\n", failed ? "FAIL" : "pass", failed, failed == 1 ? "" : "s");
    return failed;
}
