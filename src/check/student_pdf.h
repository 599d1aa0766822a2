/* student_pdf.h — the densities a student may claim for their directions (pathlab check-sampler):
 * uniform (the sphere, 1/(4 pi)), hemisphere (1/(2 pi) on z > 0), cosine (cos theta / pi), cosm:M
 * ((M+1)/(2 pi) cos^M theta) and blinn:M, the slides' reflected half vector for a given wo:
 * pdf(w) = (M+1)/(2 pi) cos^M theta_h / (4 wo.h), h = (wo + w)/|wo + w|. Each in double, with what
 * the chi-square needs: its cells' domain and a reference sampler for the pilot sample that places
 * the rings. The blinn chi-square bins the half vector (as check/brdf_check.c does: the lobe is
 * round there at any wo); its reflections below the surface are a cell of their own. */
#ifndef PATHLAB_STUDENT_PDF_H
#define PATHLAB_STUDENT_PDF_H
#include "check/chi2_sphere.h"

typedef enum { SPDF_UNIFORM, SPDF_HEMISPHERE, SPDF_COSINE, SPDF_COSM, SPDF_BLINN } student_pdf_kind;

typedef struct {
    student_pdf_kind kind;
    double m;          /* the lobe's exponent: 0 hemisphere, 1 cosine, M for cosm and blinn */
    dvec wo;           /* blinn: unit, wo.z > 0 */
    double theta_o;    /* blinn: wo's polar angle and azimuth */
    double phi_o;
} student_pdf;

/* "uniform", "hemisphere", "cosine", "cosm:M", "blinn:M" (wo set apart); 0, or 1 with err. */
int student_pdf_parse(const char *text, student_pdf *p, char *err, int errlen);
/* blinn's wo, any length; 0, or 1 with err when it is zero or not above the surface. */
int student_pdf_set_wo(student_pdf *p, dvec wo, char *err, int errlen);
/* "cosm:20", "blinn:20 with wo = (x, y, z)"... */
void student_pdf_name(const student_pdf *p, char *buf, int len);

/* The density at the unit direction w per steradian; blinn: the slides' formula above the surface,
 * 0 below (where the reflections are not binned by direction). */
double student_pdf_eval(const student_pdf *p, dvec w);
/* The solid angle where the column is checked by mean(1/pdf): 4 pi (uniform) or 2 pi (z > 0). */
double student_pdf_measure(const student_pdf *p);
/* The cosine the lobe is a power of: w.z, or blinn's h.z (h turned to z > 0); 0 if undefined. */
double student_pdf_lobe_cos(const student_pdf *p, dvec w);

/* The chi-square's domain (ctx: p) and its t range; blinn: the half vector, clipped to the
 * reflections above the surface. */
void student_pdf_domain(const student_pdf *p, sphere_domain *d, double *tmax);
/* Integral of the density over its whole domain (want 1), and the probability that a sample lands
 * in the binned part of the domain (blinn: P(reflection above the surface); else 1). */
double student_pdf_integral(const student_pdf *p);
double student_pdf_binned_mass(const student_pdf *p);
/* A student's direction mapped to the chi-square's domain: 1 with x set, 0 if discarded (below the
 * surface for a hemisphere pdf or for blinn). */
int student_pdf_bin_coords(const student_pdf *p, dvec w, dvec *x);
/* The reference sampler in the chi-square's domain (a sphere_draw_fn; ctx: the student_pdf). */
int student_pdf_draw(void *ctx, pcg32 *rng, dvec *x);
#endif
