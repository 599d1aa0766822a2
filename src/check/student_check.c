/* student_check.c — the checks of a student's directions against a named density (student_check.h). */
#include "check/student_check.h"
#include "stats/significance.h"
#include <stdlib.h>
#include <string.h>

#define PRINT_EPS 2e-6      /* how far 6 printed digits may move a cosine */
#define RATIO_TOL 1e-3
#define THETA_BINS 20

/* The file's samples one after the other, as a sphere_draw_fn (the rng is not used). */
typedef struct { const sample_file *s; const student_pdf *p; long next; } file_stream;

static int draw_file(void *ctx, pcg32 *rng, dvec *x)
{
    file_stream *f = ctx;
    (void)rng;
    return student_pdf_bin_coords(f->p, f->s->w[f->next++], x);
}

static void count_below(const sample_file *s, const student_pdf *p, student_report *r)
{
    long i;
    for (i = 0; i < s->n; i++)   /* z = 0 (as printed: %f writes any z under 5e-7 as 0.000000) is on the surface */
        if (!(s->w[i].z >= 0.0)) {
            if (!r->below++) r->first_below = s->line[i];
        }
    r->below_allowed = p->kind == SPDF_UNIFORM || p->kind == SPDF_BLINN;
    if (p->kind == SPDF_BLINN) r->below_expected = (double)s->n * (1.0 - r->binned_mass);
}

/* cos^K has mean cosine E = (K+1)/(K+2) on z > 0, so K = (2E - 1)/(1 - E), and its standard error
 * by the delta method is se(E)/(1 - E)^2. Below-surface samples are left out (counted apart). */
static void fit_exponent(const sample_file *s, const student_pdf *p, student_report *r)
{
    double sum = 0.0, sum2 = 0.0, E, var;
    long i, m = 0;
    r->K = r->K_se = -1.0;
    if (p->kind == SPDF_UNIFORM) return;
    for (i = 0; i < s->n; i++) {
        double c = student_pdf_lobe_cos(p, s->w[i]);
        if (p->kind != SPDF_BLINN && !(c > 0.0)) continue;
        sum += c, sum2 += c * c, m++;
    }
    if (m < 2) return;
    E = sum / m, var = fmax(0.0, sum2 / m - E * E) / (m - 1);
    if (E >= 1.0) return;
    r->K = fmax(0.0, (2.0 * E - 1.0) / (1.0 - E)), r->K_se = sqrt(var) / ((1.0 - E) * (1.0 - E));
}

/* The classic mistake theta = (pi/2) u: a chi-square of theta in equal bins of [0, pi/2]. */
static void theta_uniform(const sample_file *s, const student_pdf *p, student_report *r)
{
    double obs[THETA_BINS], expct[THETA_BINS];
    long i, m = 0;
    int k;
    r->theta_p = -1.0;
    if (p->kind == SPDF_UNIFORM) return;
    memset(obs, 0, sizeof obs);
    for (i = 0; i < s->n; i++) {
        double c = student_pdf_lobe_cos(p, s->w[i]);
        if (!(c > 0.0)) continue;
        k = (int)(acos(fmin(1.0, c)) / (0.5 * PI) * THETA_BINS);
        obs[k < THETA_BINS ? k : THETA_BINS - 1] += 1.0, m++;
    }
    for (k = 0; k < THETA_BINS; k++) expct[k] = (double)m / THETA_BINS;
    if (m >= 5 * THETA_BINS) r->theta_p = chi2_test(obs, expct, THETA_BINS).p;
}

double student_ratio_tol(const student_pdf *p, dvec w)
{
    double c = student_pdf_lobe_cos(p, w), tol = RATIO_TOL;
    if (p->m > 0.0 && c > 0.0) tol += p->m * PRINT_EPS / c;
    if (p->kind == SPDF_BLINN) {
        dvec h = dv_normalize(dv_lin(p->wo, 1.0, w, 1.0));
        tol += PRINT_EPS / fmax(1e-12, dv_dot(p->wo, h));
    }
    return tol;
}

/* 2: mean(named / column) and mean(1 / column) on z > 0 (the sphere for uniform), with their
 * standard errors; a zero column where the named density is positive is counted apart. */
static void column_integrals(const sample_file *s, const student_pdf *p, student_report *r)
{
    double a = 0.0, a2 = 0.0, b = 0.0, b2 = 0.0, n = (double)s->n;
    long i;
    for (i = 0; i < s->n; i++) {
        double q, x, y;
        if (p->kind != SPDF_UNIFORM && !(s->w[i].z >= 0.0)) continue;
        q = student_pdf_eval(p, dv_normalize(s->w[i]));
        if (!(s->pdf[i] > 0.0)) {
            r->zero_pdf += q > 0.0;
            continue;
        }
        x = q / s->pdf[i], y = 1.0 / s->pdf[i];
        a += x, a2 += x * x, b += y, b2 += y * y;
    }
    r->norm = a / n, r->inv = b / n;
    r->norm_se = n > 1 ? sqrt(fmax(0.0, a2 / n - r->norm * r->norm) / (n - 1)) : INFINITY;
    r->inv_se = n > 1 ? sqrt(fmax(0.0, b2 / n - r->inv * r->inv) / (n - 1)) : INFINITY;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* 3: column / named at every direction where the named density is positive. */
static int ratio_stats(const sample_file *s, const student_pdf *p, student_report *r)
{
    double *ratio = malloc(sizeof(double) * (size_t)s->n), worst = -1.0;
    long i;
    if (!ratio) return 1;
    r->ratio_min = INFINITY, r->ratio_max = 0.0;
    for (i = 0; i < s->n; i++) {
        dvec w = dv_normalize(s->w[i]);
        double q = student_pdf_eval(p, w), x, off;
        if (!(q > 0.0)) continue;
        x = s->pdf[i] / q, off = fabs(x - 1.0) / student_ratio_tol(p, w);
        ratio[r->ratio_n++] = x;
        r->ratio_min = fmin(r->ratio_min, x), r->ratio_max = fmax(r->ratio_max, x);
        r->ratio_bad += off > 1.0;
        if (off > worst) worst = off, r->worst_line = s->line[i], r->worst_col = s->pdf[i], r->worst_named = q;
    }
    if (r->ratio_n) {
        qsort(ratio, (size_t)r->ratio_n, sizeof(double), cmp_double);
        r->ratio_median = ratio[r->ratio_n / 2];
    }
    free(ratio);
    return 0;
}

int student_check_run(const sample_file *s, const student_pdf *p, double alpha, uint64_t seed, student_report *r)
{
    file_stream f;
    sphere_domain d;
    double tmax;
    pcg32 rng, pilot;
    memset(r, 0, sizeof *r);
    r->n = s->n, r->alpha = alpha, r->alpha_each = sidak_level(alpha, s->pdf ? 2 : 1);
    r->integral = student_pdf_integral(p), r->binned_mass = student_pdf_binned_mass(p);
    r->measure = student_pdf_measure(p);
    count_below(s, p, r);
    fit_exponent(s, p, r);
    theta_uniform(s, p, r);
    f.s = s, f.p = p, f.next = 0;
    student_pdf_domain(p, &d, &tmax);
    pcg32_init(&rng, seed, 0), pcg32_init(&pilot, seed, 1);
    r->chi2 = chi2_directions_piloted(&d, draw_file, &f, student_pdf_draw, (void *)p, tmax, 1.0 - r->binned_mass, s->n,
                                      rng, pilot);
    if (!s->pdf) return 0;
    column_integrals(s, p, r);
    return ratio_stats(s, p, r);
}

int student_domain_pass(const student_report *r) { return r->below == 0 || r->below_allowed; }
int student_chi2_pass(const student_report *r) { return r->chi2.chi2.dof >= 1 && r->chi2.chi2.p >= r->alpha_each; }
int student_integral_pass(const student_report *r) { return fabs(r->integral - 1.0) < STUDENT_INTEGRAL_TOL; }

int student_norm_pass(const student_report *r)
{
    double z = normal_quantile(1.0 - 0.5 * r->alpha_each);
    /* a sum that overflowed (a pdf 1e156 times too small) makes the error infinite: that is no pass */
    return r->zero_pdf == 0 && isfinite(r->norm) && isfinite(r->norm_se) && fabs(r->norm - r->binned_mass) <= z * r->norm_se + STUDENT_NORM_TOL;
}

int student_ratio_pass(const student_report *r) { return r->ratio_bad == 0; }
