/* student_diagnosis.c — naming a student's mistake from the checks' numbers (student_diagnosis.h). */
#include "check/student_diagnosis.h"
#include <stdio.h>
#include <string.h>

#define MATCH_SHARE 0.99   /* a hypothesis explains the column if it fits this share of the samples */
#define K_SIGMAS 4.0       /* a fitted exponent K is "about M" within this many standard errors */

static int near_exponent(const student_report *r, double m) { return fabs(r->K - m) <= K_SIGMAS * r->K_se + 0.02 * (m + 1.0); }

int student_diagnose_directions(const student_report *r, const student_pdf *p, char *buf, int len)
{
    double M = p->m;
    if (r->below && p->kind != SPDF_BLINN)
        return snprintf(buf, (size_t)len, "%ld directions below the surface (z < 0; the first on line %ld): the pdf is 0 "
                        "there; is cos theta = z computed with the right sign?", r->below, r->first_below), 1;
    if (p->kind == SPDF_BLINN && r->below == 0 && r->below_expected >= 10.0)
        return snprintf(buf, (size_t)len, "no direction below the surface, but %.0f expected (P = %.3g): write every "
                        "reflected direction to the file, those below the surface too", r->below_expected,
                        1.0 - r->binned_mass), 1;
    if (r->theta_p >= r->alpha_each && M >= 0.0)
        return snprintf(buf, (size_t)len, "your directions are uniform in theta, not in cos theta: theta = (pi/2) u gives "
                        "the density 1/(pi^2 sin theta); take cos theta = u^(1/(m+1)) (m = %g)", M), 1;
    if (r->K < 0.0) return 0;
    if (M >= 1.0 && near_exponent(r, M - 1.0) && !near_exponent(r, M))
        return snprintf(buf, (size_t)len, "your directions follow cos^K with K = %.3f +- %.3f, not cos^%g: cos theta = "
                        "u^(1/%g) instead of u^(1/(m+1)) = u^(1/%g)?", r->K, r->K_se, M, M, M + 1.0), 1;
    if (!near_exponent(r, M))
        return snprintf(buf, (size_t)len, "your directions follow cos^K with K = %.3f +- %.3f, not cos^%g (cos theta = "
                        "u^(1/(K+1)) draws cos^K)", r->K, r->K_se, M), 1;
    return snprintf(buf, (size_t)len, "the mean cos theta fits cos^%g (K = %.3f +- %.3f) but the cells do not: check "
                    "phi = 2 pi u and (x, y, z) = (cos phi sin theta, sin phi sin theta, cos theta)%s", M, r->K,
                    r->K_se, p->kind == SPDF_BLINN ? ", and the reflection -wo + 2 (wo.h) h" : ""), 1;
}

/* A hypothesis about the column: it is the named density times factor(p, w, h). */
typedef struct {
    double (*factor)(const student_pdf *p, dvec w, dvec h);
    const char *what;
} pdf_mistake;

static double jac(const student_pdf *p, dvec w, dvec h) { (void)w; return 4.0 * dv_dot(p->wo, h); }
static double jac_twice(const student_pdf *p, dvec w, dvec h) { return 1.0 / jac(p, w, h); }
static double jac_times(const student_pdf *p, dvec w, dvec h) { return jac(p, w, h) * jac(p, w, h); }
static double cos_w(const student_pdf *p, dvec w, dvec h) { return pow(w.z / h.z, p->m); }
static double cos_w_jac(const student_pdf *p, dvec w, dvec h) { return cos_w(p, w, h) * jac(p, w, h); }

static const pdf_mistake BLINN_MISTAKES[] = {
    {jac, "your pdf is 4 (wo.h) times too large: the Jacobian of the reflection (dwh/dwo = 1/(4 wo.h)) is missing: "
          "it is the density of the half vector h, (m+1)/(2 pi) cos^m theta_h, not of the reflected direction"},
    {jac_twice, "your pdf is 4 (wo.h) times too small: it divides by the Jacobian 4 (wo.h) twice"},
    {jac_times, "your pdf is (4 wo.h)^2 times too large: it multiplies by 4 (wo.h) instead of dividing by it"},
    {cos_w, "your pdf takes cos^m of the direction's angle theta instead of the half vector's theta_h"},
    {cos_w_jac, "your pdf takes cos^m theta instead of cos^m theta_h, and misses the Jacobian 1/(4 wo.h)"},
    {NULL, NULL}};

/* The share of the compared samples where column = named x factor, within the ratio's tolerance. */
static double fit_share(const sample_file *s, const student_pdf *p, const pdf_mistake *m, double constant)
{
    long i, fit = 0, n = 0;
    for (i = 0; i < s->n; i++) {
        dvec w = dv_normalize(s->w[i]), h = dv_normalize(dv_lin(p->wo, 1.0, w, 1.0));
        double q = student_pdf_eval(p, w), f;
        if (!(q > 0.0)) continue;
        f = m ? m->factor(p, w, h) : constant;
        n++, fit += fabs(s->pdf[i] / (q * f) - 1.0) <= student_ratio_tol(p, w);
    }
    return n ? (double)fit / n : 0.0;
}

/* The name of a constant ratio c, or NULL. */
static const char *name_constant(const student_pdf *p, double c)
{
    double m = p->m;
    struct { double value; const char *what; int lobe; } k[] = {
        {PI, "your pdf is pi times too large: the 1/pi is missing", 0},
        {1.0 / PI, "your pdf is pi times too small: it divides by pi once too often", 0},
        {2.0 * PI, "your pdf is 2 pi times too large: the 1/(2 pi) is missing", 0},
        {1.0 / (2.0 * PI), "your pdf is 2 pi times too small: it divides by 2 pi once too often", 0},
        {2.0, "your pdf is 2 times too large: a hemisphere's 1/(2 pi) where the whole sphere takes 1/(4 pi)?", 0},
        {0.5, "your pdf is 2 times too small: the sphere's 1/(4 pi) where a hemisphere takes 1/(2 pi)?", 0},
        {4.0, "your pdf is 4 times too large: the 4 of the Jacobian 1/(4 wo.h) is missing", 0},
        {(m + 2.0) / (m + 1.0), "your pdf is normalised by (m+2)/(2 pi) instead of (m+1)/(2 pi)", 1},
        {m / (m + 1.0), "your pdf is normalised by m/(2 pi) instead of (m+1)/(2 pi)", 1},
        {(m + 8.0) / (4.0 * (m + 1.0)), "your pdf is normalised by (m+8)/(8 pi), the BRDF's, instead of the pdf's (m+1)/(2 pi)", 1}};
    size_t i;
    for (i = 0; i < sizeof k / sizeof k[0]; i++)
        if ((!k[i].lobe || p->kind >= SPDF_COSM) && k[i].value > 0.0 && fabs(c / k[i].value - 1.0) < 1e-3) return k[i].what;
    return NULL;
}

int student_diagnose_pdf(const sample_file *s, const student_pdf *p, const student_report *r, char *buf, int len)
{
    const pdf_mistake *m;
    const char *what;
    if (r->ratio_n == 0) return 0;
    if (fabs(r->ratio_median - 1.0) < 1e-3 && r->ratio_bad * 100 < r->ratio_n) return 0;   /* a few stray lines */
    if (fit_share(s, p, NULL, r->ratio_median) >= MATCH_SHARE) {
        if ((what = name_constant(p, r->ratio_median))) return snprintf(buf, (size_t)len, "%s", what), 1;
        return snprintf(buf, (size_t)len, "your pdf is %.6g times the right one everywhere: a normalisation constant "
                        "is wrong", r->ratio_median), 1;
    }
    for (m = BLINN_MISTAKES; p->kind == SPDF_BLINN && m->factor; m++)
        if (fit_share(s, p, m, 1.0) >= MATCH_SHARE) return snprintf(buf, (size_t)len, "%s", m->what), 1;
    if (p->m > 0.0 && r->ratio_max / r->ratio_min > 1.01)
        return snprintf(buf, (size_t)len, "your pdf / the right one varies from %.4g to %.4g over the directions: the "
                        "shape is wrong, not only a constant (compare with %s)", r->ratio_min, r->ratio_max,
                        p->kind == SPDF_BLINN ? "(m+1)/(2 pi) cos^m theta_h / (4 wo.h)" : "(m+1)/(2 pi) cos^m theta"), 1;
    return 0;
}
