/* student_pdf.c — the densities a student may claim, and their chi-square domains (student_pdf.h). */
#include "check/student_pdf.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_EXPONENT 1e6

static const char *const KIND_NAMES[] = {"uniform", "hemisphere", "cosine", "cosm", "blinn"};

int student_pdf_parse(const char *text, student_pdf *p, char *err, int errlen)
{
    const char *colon = strchr(text, ':');
    size_t len = colon ? (size_t)(colon - text) : strlen(text);
    int k;
    memset(p, 0, sizeof *p);
    for (k = 0; k < 5; k++)
        if (strlen(KIND_NAMES[k]) == len && !strncmp(text, KIND_NAMES[k], len)) break;
    if (k == 5 || (k >= SPDF_COSM) != (colon != NULL)) {
        snprintf(err, (size_t)errlen, "--pdf expects uniform, hemisphere, cosine, cosm:M or blinn:M, got '%s'", text);
        return 1;
    }
    p->kind = (student_pdf_kind)k, p->m = k == SPDF_COSINE ? 1.0 : 0.0;
    if (colon) {
        char *end;
        p->m = strtod(colon + 1, &end);
        if (end == colon + 1 || *end || !(p->m >= 0.0 && p->m <= MAX_EXPONENT)) {
            snprintf(err, (size_t)errlen, "--pdf %.*s:M expects an exponent M from 0 to %g, got '%s'", (int)len, text,
                     MAX_EXPONENT, colon + 1);
            return 1;
        }
    }
    p->wo = dv(0, 0, 1);
    return 0;
}

int student_pdf_set_wo(student_pdf *p, dvec wo, char *err, int errlen)
{
    double len = sqrt(dv_dot(wo, wo));
    if (!(len > 0.0) || !(wo.z > 1e-6 * len)) {
        snprintf(err, (size_t)errlen, "--wo must point above the surface (z > 0), got (%g, %g, %g)", wo.x, wo.y, wo.z);
        return 1;
    }
    p->wo = dv_lin(wo, 1.0 / len, wo, 0.0);
    p->theta_o = acos(fmin(1.0, p->wo.z));
    p->phi_o = atan2(p->wo.y, p->wo.x);
    return 0;
}

void student_pdf_name(const student_pdf *p, char *buf, int len)
{
    if (p->kind == SPDF_BLINN)
        snprintf(buf, (size_t)len, "blinn:%g with wo = (%.4g, %.4g, %.4g)", p->m, p->wo.x, p->wo.y, p->wo.z);
    else if (p->kind == SPDF_COSM) snprintf(buf, (size_t)len, "cosm:%g", p->m);
    else snprintf(buf, (size_t)len, "%s", KIND_NAMES[p->kind]);
}

static double lobe(double m, double c) { return c > 0.0 ? (m + 1.0) / (2.0 * PI) * pow(c, m) : 0.0; }

double student_pdf_eval(const student_pdf *p, dvec w)
{
    dvec h;
    switch (p->kind) {
    case SPDF_UNIFORM: return 1.0 / (4.0 * PI);
    case SPDF_HEMISPHERE: return w.z >= 0.0 ? 1.0 / (2.0 * PI) : 0.0;   /* z = 0: on the surface */
    case SPDF_COSINE: return w.z > 0.0 ? w.z / PI : 0.0;
    case SPDF_COSM: return lobe(p->m, w.z);
    case SPDF_BLINN: break;
    }
    if (!(w.z > 0.0)) return 0.0;
    h = dv_normalize(dv_lin(p->wo, 1.0, w, 1.0));
    return lobe(p->m, h.z) / (4.0 * dv_dot(p->wo, h));
}

double student_pdf_measure(const student_pdf *p) { return p->kind == SPDF_UNIFORM ? 4.0 * PI : 2.0 * PI; }

double student_pdf_lobe_cos(const student_pdf *p, dvec w)
{
    dvec s;
    double len;
    if (p->kind != SPDF_BLINN) return w.z;
    s = dv_lin(p->wo, 1.0, w, 1.0), len = sqrt(dv_dot(s, s));
    return len > 1e-9 ? fabs(s.z) / len : 0.0;   /* the half vector the student drew was h or -h */
}

/* blinn in the half-vector domain: the lobe where the reflection stays above the surface */
static int reflected_above(const student_pdf *p, dvec h) { return dv_reflect(p->wo, h).z > 0.0; }

static double f_binned(const void *ctx, dvec x)
{
    const student_pdf *p = ctx;
    if (p->kind != SPDF_BLINN) return student_pdf_eval(p, x);
    return reflected_above(p, x) ? lobe(p->m, x.z) : 0.0;
}

static double f_lobe(const void *ctx, dvec h) { return lobe(((const student_pdf *)ctx)->m, h.z); }

/* wi.z = cos(theta_o) cos 2theta + sin(theta_o) sin 2theta cos(phi - phi_o) (as brdf_check.c) */
static void clip_reflected_above(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const student_pdf *p = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t)));
    *A = cos(p->theta_o) * (2.0 * c * c - 1.0);
    *B = sin(p->theta_o) * 2.0 * s * c;
    *phi0 = p->phi_o < 0.0 ? p->phi_o + 2.0 * PI : p->phi_o;
}

void student_pdf_domain(const student_pdf *p, sphere_domain *d, double *tmax)
{
    memset(d, 0, sizeof *d);
    d->f = f_binned, d->ctx = p, d->F = dframe_about(dv(0, 0, 1));
    *tmax = p->kind == SPDF_UNIFORM ? 2.0 : 1.0;
    if (p->kind != SPDF_BLINN) return;
    d->clip = clip_reflected_above;
    d->kink[0] = 1.0 - cos(0.25 * PI - 0.5 * p->theta_o), d->kink[1] = 1.0 - cos(0.25 * PI + 0.5 * p->theta_o);
    d->nkinks = 2;
}

double student_pdf_integral(const student_pdf *p)
{
    sphere_domain d;
    double tmax;
    student_pdf_domain(p, &d, &tmax);
    if (p->kind == SPDF_BLINN) d.f = f_lobe, d.clip = NULL, d.nkinks = 0;   /* the half vector's own pdf */
    return sphere_integral(&d, 2.0, 4);
}

double student_pdf_binned_mass(const student_pdf *p)
{
    sphere_domain d;
    double tmax;
    if (p->kind != SPDF_BLINN) return 1.0;
    student_pdf_domain(p, &d, &tmax);
    return sphere_integral(&d, tmax, 16);
}

int student_pdf_bin_coords(const student_pdf *p, dvec w, dvec *x)
{
    if (p->kind == SPDF_UNIFORM) {
        *x = dv_normalize(w);
        return 1;
    }
    if (!(w.z >= 0.0)) return 0;   /* z = 0 (a %f that rounded a small z) is on the surface, in the lowest cells */
    *x = p->kind == SPDF_BLINN ? dv_normalize(dv_lin(p->wo, 1.0, dv_normalize(w), 1.0)) : dv_normalize(w);
    return 1;
}

int student_pdf_draw(void *ctx, pcg32 *rng, dvec *x)
{
    const student_pdf *p = ctx;
    double u1 = pcg32_double(rng), u2 = pcg32_double(rng), c, s, phi = 2.0 * PI * u1;
    if (p->kind == SPDF_UNIFORM) c = 1.0 - 2.0 * u2;
    else c = pow(1.0 - u2, 1.0 / (p->m + 1.0));   /* cos theta = u^(1/(m+1)), u in (0, 1] */
    s = sqrt(fmax(0.0, 1.0 - c * c));
    *x = dv(cos(phi) * s, sin(phi) * s, c);
    return p->kind != SPDF_BLINN || reflected_above(p, *x);
}
