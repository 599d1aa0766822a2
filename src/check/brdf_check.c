/* brdf_check.c — brdf_sample against brdf_pdf (brdf_check.h), for one material and wo.
 * What "integrates to 1" means for the Blinn lobe: wi = reflect(wo, h) with h of density
 * (Ns+1)/(2 pi) cos^Ns(theta_h) on h.z > 0 has a density over the whole sphere of integral 1, but
 * blinn_pdf is that density only where h faces wo (wo.h > 0), and 0 for the reflections about half
 * vectors facing away from wo, which all land below the surface. So the true statements, checked
 * here, are: blinn_pdf integrates over the sphere to P(wo.h > 0) (1 at normal incidence, 0.51 at
 * 89 degrees with Ns = 1); brdf_pdf (0 below the surface) integrates over wi.z > 0 to
 * (1 - ps) + ps P(wi.z > 0); brdf_sample returns wi.z <= 0 with probability ps (1 - P(wi.z > 0)).
 * Both probabilities come in closed form from the half-vector domain (half_vector_mass).
 * The chi-square bins the reflected direction through its half vector h = (wo+wi)/|wo+wi|, a
 * one-to-one map of the upper hemisphere of wi onto a part of the upper hemisphere of h, where the
 * lobe is round even at grazing wo (in wi it is a sliver 1/cos(theta_o) times narrower than long);
 * the expected density there is brdf_pdf(wi) |dwi/dh| = brdf_pdf(wi) 4 (wo.h). */
#include "check/brdf_check.h"
#include "check/chi2_sphere.h"
#include "stats/quadrature.h"
#include <stdio.h>
#include <string.h>

#define PDF_TOL 1e-4              /* relative: the pdf brdf_sample returns against brdf_pdf */

typedef struct {
    const brdf_routine *b;
    vec3 wo;
    dvec wod;
    double ps;                    /* probability of the glossy lobe */
    sampling_result *r;
} brdf_case;

/* The mixture pdf from the slides' formulas, in double from the same float inputs. */
static double brdf_pdf_formula(const brdf_case *c, dvec wi)
{
    dvec wo = c->wod, h;
    double pdf = 0.0, Ns = c->b->mat.Ns;
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    h = dv_normalize(dv_lin(wo, 1.0, wi, 1.0));
    if (c->ps < 1.0) pdf += (1.0 - c->ps) * wi.z / PI;
    if (c->ps > 0.0) pdf += c->ps * (Ns + 1.0) / (2.0 * PI) * pow(h.z, Ns) / (4.0 * dv_dot(wo, h));
    return pdf;
}

/* P(wi.z > 0) and P(wo.h > 0) for h of density (m+1)/(2 pi) cos^m(theta_h). With wo at polar angle
 * theta_o and h at (theta, phi) about wo's azimuth, wo.h = R cos(theta - g) and
 * wi.z = R cos(2 theta - g), where R sin g = sin(theta_o) cos(phi), R cos g = cos(theta_o). So
 * wo.h > 0 iff theta < g + pi/2, wi.z > 0 iff theta < (g + pi/2)/2, and since the mass of
 * theta < T is 1 - cos^(m+1) T per unit of phi / (2 pi):
 *   P(wo.h > 0) = 1 - 1/(2 pi) int_{cos phi < 0} (sin(theta_o) |cos phi| / R)^(m+1) dphi,
 *   P(wi.z > 0) = 1 - 1/(2 pi) int ((1 - sin(theta_o) cos(phi) / R) / 2)^((m+1)/2) dphi. */
static double half_vector_mass(double theta_o, double m, int reflected_above)
{
    int panels = 400, j, k;
    double a = reflected_above ? 0.0 : 0.5 * PI, b = reflected_above ? 2.0 * PI : 1.5 * PI, h = (b - a) / panels;
    double so = sin(theta_o), co = cos(theta_o), lost = 0.0;
    for (j = 0; j < panels; j++)
        for (k = 0; k < GL_N; k++) {
            double phi = gl_node(a, h, j, k), R = sqrt(so * so * cos(phi) * cos(phi) + co * co);
            double sin_g = so * cos(phi) / R;
            double v = reflected_above ? pow(0.5 * (1.0 - sin_g), 0.5 * (m + 1.0)) : pow(-sin_g, m + 1.0);
            lost += gl_weight(h, k) * v;
        }
    return 1.0 - lost / (2.0 * PI);
}

/* wi-domain: brdf_pdf about the mirror direction, clipped to wi.z > 0 (the clip reads the frame of
 * its own domain: a domain whose ctx is itself) */
typedef struct { sphere_domain d; const brdf_case *c; } wi_domain;

static double f_brdf_wi(const void *ctx, dvec wi)
{
    const brdf_case *c = ((const wi_domain *)ctx)->c;
    return c->b->pdf(&c->b->mat, c->wo, fv_of(wi));
}

static void clip_wi_above(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const sphere_domain *d = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t)));
    *A = c * d->F.n.z;
    *B = s * hypot(d->F.t.z, d->F.b.z);
    *phi0 = atan2(d->F.b.z, d->F.t.z);
}

/* half-vector domain: brdf_pdf(wi(h)) 4 wo.h on wi.z > 0; blinn_pdf(wi(h)) 4 wo.h on wo.h > 0 */
static double f_brdf_h(const void *ctx, dvec h)
{
    const brdf_case *c = ctx;
    double wo_h = dv_dot(c->wod, h);
    dvec wi = dv_reflect(c->wod, h);
    return wi.z > 0.0 && wo_h > 0.0 ? c->b->pdf(&c->b->mat, c->wo, fv_of(wi)) * 4.0 * wo_h : 0.0;
}

static double f_blinn_h(const void *ctx, dvec h)
{
    const brdf_case *c = ctx;
    double wo_h = dv_dot(c->wod, h);
    return blinn_pdf(c->wo, fv_of(dv_reflect(c->wod, h)), c->b->mat.Ns) * 4.0 * fabs(wo_h);
}

/* wi.z = cos(theta_o) cos 2theta + sin(theta_o) sin 2theta cos(phi - phi_o) */
static void clip_h_reflected_above(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const brdf_case *k = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t))), th = k->b->theta_deg * PI / 180.0;
    *A = cos(th) * (2.0 * c * c - 1.0);
    *B = sin(th) * 2.0 * s * c;
    *phi0 = k->b->phi_o;
}

/* wo.h = cos(theta_o) cos theta + sin(theta_o) sin theta cos(phi - phi_o) */
static void clip_h_facing_wo(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const brdf_case *k = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t))), th = k->b->theta_deg * PI / 180.0;
    *A = cos(th) * c;
    *B = sin(th) * s;
    *phi0 = k->b->phi_o;
}

/* A sample, its pdf checked on the way; a sample below the surface is discarded. */
static int draw_brdf(void *ctx, pcg32 *rng, dvec *h)
{
    brdf_case *c = ctx;
    sampling_result *r = c->r;
    float u0 = pcg32_float(rng), u1 = pcg32_float(rng), u2 = pcg32_float(rng), pdf;
    vec3 wi = c->b->sample(&c->b->mat, c->wo, u0, u1, u2, &pdf);
    dvec wid = dv_of(wi);
    double fn = c->b->pdf(&c->b->mat, c->wo, wi), ref = brdf_pdf_formula(c, wid);
    r->pdf_checked++;
    if (!(fabs(pdf - fn) <= PDF_TOL * fn) || (wi.z > 0.0f) != (pdf > 0.0f)) r->pdf_mismatch++;
    if (ref > 0.0) r->formula_gap = fmax(r->formula_gap, fabs(fn - ref) / ref);
    if (!(wi.z > 0.0f)) return 0;
    *h = dv_normalize(dv_lin(c->wod, 1.0, wid, 1.0));
    return 1;
}

static brdf_case brdf_case_of(const brdf_routine *b, sampling_result *r)
{
    double th = b->theta_deg * PI / 180.0;
    brdf_case c;
    c.b = b, c.r = r;
    /* normalized in float: besides, at -O2 GCC 12's SLP vectorizer turned (double)(float)(x) into x
     * here, which made wod differ from wo */
    c.wo = v3_normalize(v3((float)(sin(th) * cos(b->phi_o)), (float)(sin(th) * sin(b->phi_o)), (float)cos(th)));
    c.wod = dv_of(c.wo);
    c.ps = brdf_glossy_prob(&b->mat);
    return c;
}

/* brdf_pdf over wi.z > 0 in the wi domain, about the mirror direction: slower than through the half
 * vector (at grazing wo the lobe is a sliver there), but an independent quadrature */
static double integral_wi(const brdf_case *c)
{
    dvec mirror = dv(-c->wod.x, -c->wod.y, c->wod.z);
    float th = c->b->theta_deg;
    wi_domain dw;
    memset(&dw, 0, sizeof dw);
    dw.c = c;
    dw.d.f = f_brdf_wi, dw.d.ctx = &dw, dw.d.clip = clip_wi_above, dw.d.F = dframe_about(mirror);
    dw.d.kink[0] = 1.0 - hypot(mirror.x, mirror.y), dw.d.kink[1] = 1.0 + hypot(mirror.x, mirror.y), dw.d.nkinks = 2;
    return sphere_integral(&dw.d, 2.0, th > 85.0f ? 512 : th > 70.0f ? 96 : 16);
}

void check_brdf(const brdf_routine *b, long n, uint64_t seed, sampling_result *r)
{
    double th = b->theta_deg * PI / 180.0, p_up = half_vector_mass(th, b->mat.Ns, 1);
    brdf_case c = brdf_case_of(b, r);
    sphere_domain dh;
    sphere_chi2 s;
    memset(&dh, 0, sizeof dh);
    dh.ctx = &c, dh.F = dframe_about(dv(0, 0, 1));

    /* 1a. blinn_pdf over the whole sphere, through dwi = 4 (wo.h) dh: P(wo.h > 0), 1 at normal
     *     incidence; the missing mass is the half vectors facing away from wo */
    if (c.ps == 1.0) {
        dh.f = f_blinn_h, dh.clip = clip_h_facing_wo;
        dh.kink[0] = 1.0 - sin(th), dh.kink[1] = 1.0 + sin(th), dh.nkinks = 2;
        r->integral[1] = sphere_integral(&dh, 2.0, 16), r->integral_want[1] = half_vector_mass(th, b->mat.Ns, 0);
        r->integral_what[1] = "of blinn_pdf over the sphere, want P(wo.h > 0)";
    }

    /* 1b. brdf_pdf over wi.z > 0, in the half-vector domain: the mixture loses the glossy
     *     reflections that go below the surface */
    dh.f = f_brdf_h, dh.clip = clip_h_reflected_above;
    dh.kink[0] = 1.0 - cos(0.25 * PI - 0.5 * th), dh.kink[1] = 1.0 - cos(0.25 * PI + 0.5 * th), dh.nkinks = 2;
    r->nintegrals = c.ps == 1.0 ? 2 : 1;
    r->integral[0] = sphere_integral(&dh, 1.0, 16), r->integral_want[0] = (1.0 - c.ps) + c.ps * p_up;
    r->integral_what[0] = "of brdf_pdf over wi.z > 0 (through h), want (1 - ps) + ps P(wi.z > 0)";
    if (b->wi_integral) {
        r->integral[r->nintegrals] = integral_wi(&c), r->integral_want[r->nintegrals] = r->integral_want[0];
        r->integral_what[r->nintegrals++] = "of brdf_pdf over wi.z > 0 (in wi), want (1 - ps) + ps P(wi.z > 0)";
    }

    /* 2 and 3: sample, check the pdfs on the way, chi-square in the half-vector domain */
    r->has_formula = 1, r->formula_tol = 1e-4 + 8.0 * b->mat.Ns * 5.96e-8;   /* float rounding of cos theta_h, times Ns */
    s = chi2_directions(&dh, draw_brdf, &c, 1.0, c.ps * (1.0 - p_up), n, case_stream(seed, 0), case_stream(seed, 1));
    r->n = n, r->chi2 = s.chi2, r->discarded = s.discarded;
    snprintf(r->cells, sizeof r->cells, "%d x %d cells of the half vector + below the surface", s.rings, SPHERE_SECTORS);
}
