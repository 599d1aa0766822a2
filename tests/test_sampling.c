/* test_sampling.c — the warps of sampling.h, the BRDF of brdf.h and the light choice of light.h,
 * tested against their pdfs:
 *   1. each pdf integrates to what it should (numerical quadrature, to 1e-3);
 *   2. the pdf at a sampled direction matches the pdf function and an independent double-precision
 *      formula (and brdf_eval matches the slides' formula);
 *   3. a chi-square goodness-of-fit test of each sampler (cells with expected count < 5 pooled,
 *      p-value from the regularized incomplete gamma function, alpha = 0.01 for the whole file,
 *      Sidak-corrected over its chi-square cases): directions, points on a triangle, the choice of
 *      an emitter under each light strategy and the point on it.
 * What "integrates to 1" means for the Blinn lobe: wi = reflect(wo, h) with h of density
 * (Ns+1)/(2 pi) cos^Ns(theta_h) on h.z > 0 has a density over the whole sphere of integral 1, but
 * blinn_pdf is that density only where h faces wo (wo.h > 0), and 0 for the reflections about half
 * vectors facing away from wo, which all land below the surface. So the true statements, tested
 * here, are: the integral of blinn_pdf over the sphere is P(wo.h > 0) (1 at normal incidence, 0.51 at
 * 89 degrees with Ns = 1); brdf_pdf (0 below the surface) integrates over wi.z > 0 to
 * (1 - ps) + ps P(wi.z > 0); brdf_sample returns wi.z <= 0 with probability ps (1 - P(wi.z > 0)).
 * Both probabilities come in closed form from the half-vector domain (half_vector_mass).
 * Directions are binned in (t, phi) about an axis, t = 1 - cos(angle to the axis), so that
 * d omega = dt dphi. Radial cell bounds are quantiles of a pilot sample drawn from another stream,
 * so the cells follow the lobe (even Ns = 1e4) yet are independent of the tested sample.
 * The reflected Blinn direction is binned through its half vector h = (wo+wi)/|wo+wi|, a one-to-one
 * map of the upper hemisphere of wi onto a part of the upper hemisphere of h, where the lobe is
 * round even at grazing wo (in wi it is a sliver 1/cos(theta_o) times narrower than long); the
 * expected density there is brdf_pdf(wi) |dwi/dh| = brdf_pdf(wi) 4 (wo.h).
 * PATHLAB_FAST=1 (sanitizer runs) divides the sample counts by 10. */
#include "brdf.h"
#include "check.h"
#include "light.h"
#include "rng.h"
#include "sampling.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define ALPHA 0.01             /* family-wise level of all the chi-square tests of this file */
#define INTEGRAL_TOL 1e-3

static long n_samples = 1000000;   /* per chi-square case, half that for the BRDF's (PATHLAB_FAST: / 10) */
static double alpha_case;          /* Sidak: 1 - (1 - ALPHA)^(1 / number of cases) */
static int n_chi2_done;

/* ---------- double-precision directions ---------- */

typedef struct { double x, y, z; } dvec;
typedef struct { dvec t, b, n; } dframe;

static dvec dv(double x, double y, double z) { dvec r; r.x = x; r.y = y; r.z = z; return r; }
static dvec dv_of(vec3 a) { return dv(a.x, a.y, a.z); }
static vec3 fv_of(dvec a) { return v3((float)a.x, (float)a.y, (float)a.z); }
static double dv_dot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dv_lin(dvec a, double s, dvec b, double r) { return dv(s * a.x + r * b.x, s * a.y + r * b.y, s * a.z + r * b.z); }
static dvec dv_normalize(dvec a) { return dv_lin(a, 1.0 / sqrt(dv_dot(a, a)), a, 0.0); }
static dvec reflect_d(dvec wo, dvec h) { return dv_lin(h, 2.0 * dv_dot(wo, h), wo, -1.0); }

static dframe dframe_about(dvec n)   /* Duff et al. 2017, as frame_from_normal */
{
    dframe f;
    double sign = n.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    f.t = dv(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = dv(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

/* Direction at (t, phi) about F.n. */
static dvec dir_at(const dframe *F, double t, double phi)
{
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t)));
    return dv_lin(F->n, c, dv_lin(F->t, cos(phi), F->b, sin(phi)), s);
}

/* (t, phi) of a unit direction about F.n; t from sin^2 keeps its precision near the axis. */
static void coords_of(const dframe *F, dvec w, double *t, double *phi)
{
    double x = dv_dot(w, F->t), y = dv_dot(w, F->b), z = dv_dot(w, F->n), s2 = x * x + y * y;
    *t = z > 0.0 ? s2 / (1.0 + z) : 1.0 - z;
    *phi = atan2(y, x);
    if (*phi < 0.0) *phi += 2.0 * PI;
}

/* ---------- Gauss-Legendre quadrature ---------- */

#define GL_N 8
static double gl_x[GL_N], gl_w[GL_N];   /* nodes and weights on [-1, 1] */

static void gl_init(void)
{
    int i, j, it;
    for (i = 0; i < GL_N; i++) {
        double x = cos(PI * (i + 0.75) / (GL_N + 0.5)), p0 = 1.0, p1 = x, dp = 1.0;
        for (it = 0; it < 100; it++) {
            double dx;
            p0 = 1.0, p1 = x;
            for (j = 2; j <= GL_N; j++) {
                double p2 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p0) / j;
                p0 = p1, p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1.0);
            dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        gl_x[i] = x;
        gl_w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

/* ---------- the chi-square distribution ---------- */

/* Regularized upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a): power series of P for
 * x < a + 1, Lentz's continued fraction for Q otherwise (Numerical Recipes 6.2). */
static double gamma_q(double a, double x)
{
    double lead, eps = 1e-15;
    int n;
    if (x <= 0.0) return 1.0;
    lead = exp(a * log(x) - x - lgamma(a));
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (n = 1; n < 100000 && fabs(term) > eps * fabs(sum); n++) {
            term *= x / (a + n);
            sum += term;
        }
        return fmax(0.0, 1.0 - lead * sum);
    } else {
        double tiny = 1e-300, b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
        for (n = 1; n < 100000; n++) {
            double an = -n * (n - a), del;
            b += 2.0;
            d = an * d + b;
            if (fabs(d) < tiny) d = tiny;
            c = b + an / c;
            if (fabs(c) < tiny) c = tiny;
            d = 1.0 / d;
            del = d * c;
            h *= del;
            if (fabs(del - 1.0) < eps) break;
        }
        return lead * h;
    }
}

static double chi2_pvalue(double chi2, int dof) { return gamma_q(0.5 * dof, 0.5 * chi2); }

/* Closed forms to check it: Q(1/2, x) = erfc(sqrt x), and for integer a
 * Q(a, x) = e^-x sum_{k<a} x^k / k!. */
static double gamma_q_integer(int a, double x)
{
    double term = 1.0, sum = 1.0;
    int k;
    for (k = 1; k < a; k++) {
        term *= x / k;
        sum += term;
    }
    return exp(-x) * sum;
}

static void test_chi2_pvalue(void)
{
    static const double x[] = {0.01, 0.5, 1.0, 3.0, 10.0, 40.0};
    static const int dofs[] = {2, 6, 20, 200, 1000};
    static const double ratio[] = {0.7, 0.9, 1.0, 1.1, 1.3};
    double err = 0.0;
    int i, j;
    for (i = 0; i < 6; i++) err = fmax(err, fabs(chi2_pvalue(x[i], 1) - erfc(sqrt(0.5 * x[i]))));
    for (i = 0; i < 5; i++)
        for (j = 0; j < 5; j++) {
            double c = ratio[j] * dofs[i];
            err = fmax(err, fabs(chi2_pvalue(c, dofs[i]) - gamma_q_integer(dofs[i] / 2, 0.5 * c)));
        }
    /* and a table value: the 1% critical value of chi-square with 100 degrees of freedom */
    err = fmax(err, fabs(chi2_pvalue(135.8067, 100) - 0.01) * 0.1);
    check(err < 1e-8, "chi2 p-value function", "max error %.2g against erfc, the integer-a sums and tables", err);
}

/* ---------- chi-square test on counts ---------- */

/* Pools the cells with expected count < 5 into one (merged into the largest cell if the pool
 * itself stays below 5), then prints PASS/FAIL with chi2, dof and p. Returns p. */
static double chi2_check(const char *name, const double *obs, const double *expct, int n, const char *extra)
{
    double chi2 = 0.0, pool_o = 0.0, pool_e = 0.0, big_o = 0.0, big_e = -1.0, p, total_e = 0.0;
    int i, cells = 0, big = -1;
    for (i = 0; i < n; i++) {
        total_e += expct[i];
        if (expct[i] < 5.0) {
            pool_o += obs[i];
            pool_e += expct[i];
        } else if (expct[i] > big_e) {
            big = i, big_e = expct[i], big_o = obs[i];
        }
    }
    for (i = 0; i < n; i++) {
        if (expct[i] < 5.0 || i == big) continue;
        chi2 += (obs[i] - expct[i]) * (obs[i] - expct[i]) / expct[i];
        cells++;
    }
    if (pool_e == 0.0 && pool_o > 0.0) chi2 = INFINITY;   /* samples where the pdf says none can be */
    if (pool_e >= 5.0 || big < 0) {
        if (pool_e > 0.0) chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        cells += pool_e > 0.0;
        pool_o = pool_e = 0.0;
    }
    if (big >= 0) {
        big_o += pool_o, big_e += pool_e;
        chi2 += (big_o - big_e) * (big_o - big_e) / big_e;
        cells++;
    }
    p = cells > 1 ? chi2_pvalue(chi2, cells - 1) : 0.0;
    n_chi2_done++;
    check(p >= alpha_case, name, "chi2 %.1f, dof %d, p = %.3g, alpha per case %.2g; sum of expected %.6g%s",
          chi2, cells - 1, p, alpha_case, total_e, extra ? extra : "");
    return p;
}

/* ---------- densities on directions, cells and quadrature ---------- */

/* A density over directions w = dir_at(F, t, phi), integrated in d omega = dt dphi, optionally
 * only where A + B cos(phi - phi0) > 0 (clip gives A, B, phi0 for the ring at t); the t where the
 * clipped arc appears or vanishes are kinks of the integrand and split the quadrature. */
typedef struct {
    double (*f)(const void *ctx, dvec w);
    void (*clip)(const void *ctx, double t, double *A, double *B, double *phi0);
    const void *ctx;
    dframe F;
    double kink[4];
    int nkinks;
} domain;

/* Pieces of [p0, p1] kept by the clip at ring t (at most 3). */
static int ring_arcs(const domain *d, double t, double p0, double p1, double *lo, double *hi)
{
    double A, B, phi0, kappa, delta;
    int k, n = 0;
    if (!d->clip) {
        lo[0] = p0, hi[0] = p1;
        return 1;
    }
    d->clip(d->ctx, t, &A, &B, &phi0);
    if (B <= 1e-14 * fabs(A) || -A / B <= -1.0) {
        if (A <= 0.0) return 0;
        lo[0] = p0, hi[0] = p1;
        return 1;
    }
    kappa = -A / B;
    if (kappa >= 1.0) return 0;
    delta = acos(kappa);
    for (k = -2; k <= 2; k++) {
        double a = fmax(p0, phi0 - delta + 2.0 * PI * k), b = fmin(p1, phi0 + delta + 2.0 * PI * k);
        if (a < b && n < 3) lo[n] = a, hi[n] = b, n++;
    }
    return n;
}

static double ring_integral(const domain *d, double t, double p0, double p1, int ppanels)
{
    double lo[3], hi[3], sum = 0.0;
    int n = ring_arcs(d, t, p0, p1, lo, hi), i, j, k;
    for (i = 0; i < n; i++) {
        double h = (hi[i] - lo[i]) / ppanels;
        for (j = 0; j < ppanels; j++)
            for (k = 0; k < GL_N; k++) {
                double phi = lo[i] + h * (j + 0.5 * (gl_x[k] + 1.0));
                sum += 0.5 * h * gl_w[k] * d->f(d->ctx, dir_at(&d->F, t, phi));
            }
    }
    return sum;
}

static double interval_integral(const domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
{
    double h = (t1 - t0) / tpanels, sum = 0.0;
    int j, k;
    for (j = 0; j < tpanels; j++)
        for (k = 0; k < GL_N; k++)
            sum += 0.5 * h * gl_w[k] * ring_integral(d, t0 + h * (j + 0.5 * (gl_x[k] + 1.0)), p0, p1, ppanels);
    return sum;
}

/* Integral over [t0, t1] x [p0, p1] with no kink inside. */
static double piece_integral(const domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
{
    double cuts[6], sum = 0.0;
    int n = 0, i, j;
    cuts[n++] = t0;
    for (i = 0; i < d->nkinks; i++)
        if (d->kink[i] > t0 && d->kink[i] < t1) cuts[n++] = d->kink[i];
    cuts[n++] = t1;
    for (i = 1; i < n; i++)   /* sort the few cuts */
        for (j = i; j > 0 && cuts[j] < cuts[j - 1]; j--) {
            double c = cuts[j];
            cuts[j] = cuts[j - 1], cuts[j - 1] = c;
        }
    for (i = 0; i + 1 < n; i++) sum += interval_integral(d, cuts[i], cuts[i + 1], p0, p1, tpanels, ppanels);
    return sum;
}

/* Integral over the cell [t0, t1] x [p0, p1]: [t0, t1] is cut into pieces no wider than their
 * distance to the axis (geometrically toward t = 0, down to 1e-12 t1), which resolves lobes of any
 * width about the axis, and the pieces are split at the kinks. */
static double cell_integral(const domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
{
    double sum = 0.0, lo, hi;
    if (t0 > 0.0) {
        for (lo = t0; lo < t1; lo = hi) {
            hi = fmin(2.0 * lo, t1);
            sum += piece_integral(d, lo, hi, p0, p1, tpanels, ppanels);
        }
        return sum;
    }
    for (hi = t1; hi > 1e-12 * t1; hi *= 0.5) sum += piece_integral(d, 0.5 * hi, hi, p0, p1, tpanels, ppanels);
    return sum + piece_integral(d, 0.0, hi, p0, p1, tpanels, ppanels);
}

/* Integral over t in [0, tmax] (with tmax = 2, the whole sphere; t = 1 is a piece boundary). */
static double domain_integral(const domain *d, double tmax, int ppanels)
{
    return cell_integral(d, 0.0, tmax, 0.0, 2.0 * PI, 2, ppanels);
}

/* ---------- chi-square test of a direction sampler ---------- */

/* draw() returns 1 with w set to the sample's direction in d's coordinates, or 0 for a sample
 * that was discarded (a reflection below the surface), all counted in one extra cell. */
typedef int (*draw_fn)(void *ctx, pcg32 *rng, dvec *w);

#define RCELLS 20
#define PCELLS 16

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Radial cell bounds: quantiles of t over a pilot sample (another stream). */
static int radial_bounds(const domain *d, draw_fn draw, void *ctx, double tmax, long N, double *tb)
{
    long n = N / 10 > 20000 ? N / 10 : 20000, m = 0, i;
    double *t = malloc(sizeof(double) * (size_t)n), phi;
    int r, nr = 0;
    pcg32 rng;
    dvec w;
    pcg32_init(&rng, 12345u, 777u);
    for (i = 0; i < n; i++)
        if (draw(ctx, &rng, &w)) coords_of(&d->F, w, &t[m++], &phi);
    qsort(t, (size_t)m, sizeof(double), cmp_double);
    tb[nr++] = 0.0;
    for (r = 1; r < RCELLS && m > 0; r++) {
        double q = t[(long)((double)r / RCELLS * (double)m)];
        if (q > tb[nr - 1] && q < tmax) tb[nr++] = q;
    }
    tb[nr++] = tmax;
    free(t);
    return nr - 1;
}

/* Draws N samples with draw() and compares the counts in (t, phi) cells with the integrals of
 * d->f over them; p_discard is the expected fraction of discarded samples. */
static void chi2_directions(const char *name, const domain *d, draw_fn draw, void *ctx, double tmax,
                            double p_discard, long N, unsigned seed)
{
    double tb[RCELLS + 1], obs[RCELLS * PCELLS + 1], expct[RCELLS * PCELLS + 1];
    int nr = radial_bounds(d, draw, ctx, tmax, N, tb), r, p, ncell;
    long i;
    pcg32 rng;
    ncell = nr * PCELLS;
    memset(obs, 0, sizeof obs);
    for (r = 0; r < nr; r++)
        for (p = 0; p < PCELLS; p++)
            expct[r * PCELLS + p] = (double)N * cell_integral(d, tb[r], tb[r + 1], 2.0 * PI * p / PCELLS,
                                                      2.0 * PI * (p + 1) / PCELLS, 2, 2);
    expct[ncell] = (double)N * p_discard;
    pcg32_init(&rng, seed, 1u);
    for (i = 0; i < N; i++) {
        dvec w;
        double t, phi;
        int ri, pi;
        if (!draw(ctx, &rng, &w)) {
            obs[ncell] += 1.0;
            continue;
        }
        coords_of(&d->F, w, &t, &phi);
        for (ri = 0; ri < nr - 1 && t >= tb[ri + 1]; ri++) {}
        pi = (int)(phi / (2.0 * PI) * PCELLS);
        if (pi >= PCELLS) pi = PCELLS - 1;
        obs[ri * PCELLS + pi] += 1.0;
    }
    {
        char extra[96];
        snprintf(extra, sizeof extra, "; N = %ld, %d x %d cells + discarded (%g observed)", N, nr, PCELLS,
                 obs[ncell]);
        chi2_check(name, obs, expct, ncell + 1, extra);
    }
}

/* ---------- warps: uniform, cosine, cosine power ---------- */

typedef struct { int kind; float m; } warp;   /* kind 0 uniform, 1 cosine, 2 cos^m */

static float warp_pdf(const warp *W, vec3 w)
{
    return W->kind == 0 ? pdf_uniform_hemisphere(w) : W->kind == 1 ? pdf_cosine_hemisphere(w) : pdf_cos_power(w, W->m);
}

static vec3 warp_sample(const warp *W, float u1, float u2)
{
    return W->kind == 0 ? sample_uniform_hemisphere(u1, u2) : W->kind == 1 ? sample_cosine_hemisphere(u1, u2)
                                                                           : sample_cos_power(u1, u2, W->m);
}

/* The pdfs from their definitions, in double: 1/(2 pi), cos/pi, (m+1)/(2 pi) cos^m. */
static double warp_pdf_ref(const warp *W, dvec w)
{
    if (w.z <= 0.0) return 0.0;
    return W->kind == 0 ? 0.5 / PI : W->kind == 1 ? w.z / PI : (W->m + 1.0) / (2.0 * PI) * pow(w.z, W->m);
}

static double f_warp(const void *ctx, dvec w) { return warp_pdf((const warp *)ctx, fv_of(w)); }

static int draw_warp(void *ctx, pcg32 *rng, dvec *w)
{
    float u1 = pcg32_float(rng), u2 = pcg32_float(rng);
    *w = dv_of(warp_sample((const warp *)ctx, u1, u2));
    return 1;
}

static void warp_name(const warp *W, char *buf, size_t n)
{
    if (W->kind == 0) snprintf(buf, n, "uniform_hemisphere");
    else if (W->kind == 1) snprintf(buf, n, "cosine_hemisphere");
    else snprintf(buf, n, "cos_power m=%g", W->m);
}

static void test_warp(const warp *W, unsigned seed)
{
    char name[64], line[160];
    domain d;
    double integral, max_rel = 0.0, max_len = 0.0;
    int below = 0, zero = 0, i;
    pcg32 rng;
    warp_name(W, name, sizeof name);
    memset(&d, 0, sizeof d);
    d.f = f_warp, d.ctx = W, d.F = dframe_about(dv(0, 0, 1));

    /* 1. integral over the sphere (the pdf must vanish below the horizon) */
    integral = domain_integral(&d, 2.0, 4);
    snprintf(line, sizeof line, "integral over the sphere: %s", name);
    check(fabs(integral - 1.0) < INTEGRAL_TOL, line, "%.7f", integral);

    /* 2. the pdf at the samples: positive, as the formula says; the samples are unit and above.
     *    The first 9 use the corners and middles of [0, 1)^2 (1 - 2^-24 is the largest pcg32_float). */
    pcg32_init(&rng, seed, 99u);
    for (i = 0; i < 200000; i++) {
        static const float edge[3] = {0.0f, 0.5f, 1.0f - 0x1p-24f};
        float u1 = i < 9 ? edge[i % 3] : pcg32_float(&rng), u2 = i < 9 ? edge[i / 3] : pcg32_float(&rng);
        vec3 w = warp_sample(W, u1, u2);
        double ref = warp_pdf_ref(W, dv_of(w)), pdf = warp_pdf(W, w);
        max_len = fmax(max_len, fabs(v3_length(w) - 1.0));
        below += w.z < 0.0f;
        zero += !(pdf > 0.0f);
        if (ref > 0.0) max_rel = fmax(max_rel, fabs(pdf - ref) / ref);
    }
    snprintf(line, sizeof line, "pdf at the samples: %s", name);
    check(max_rel < 1e-4 && below == 0 && zero == 0 && max_len < 1e-5, line,
          "200000 samples incl. the corners of [0,1)^2: max relative error %.2g against the double formula, "
          "|w| - 1 up to %.1g, %d below the surface, %d with pdf 0", max_rel, max_len, below, zero);

    /* 3. chi-square over (cos theta, phi) cells of the hemisphere */
    snprintf(line, sizeof line, "chi2 %s", name);
    chi2_directions(line, &d, draw_warp, (void *)W, 1.0, 0.0, n_samples, seed);
}

/* ---------- the BRDF sampler ---------- */

typedef struct {
    const char *name;
    material m;
    float theta_deg, phi_o;      /* wo = (sin cos phi_o, sin sin phi_o, cos) */
    vec3 wo;
    dvec wod;
    double ps;                   /* probability of the glossy lobe */
    double max_rel_ref;          /* largest relative gap brdf_pdf / double formula seen */
    long pdf_mismatch;           /* samples whose returned pdf differs from brdf_pdf */
    long n_drawn;
} brdf_case;

static material make_material(float kd, float ks, float Ns)
{
    material m;
    memset(&m, 0, sizeof m);
    m.Kd = v3(kd, 0.8f * kd, 0.6f * kd);
    m.Ks = v3(ks, ks, ks);
    m.Ns = Ns;
    return m;
}

/* The mixture pdf from the slides' formulas, in double from the same float inputs. */
static double brdf_pdf_ref(const brdf_case *c, dvec wo, dvec wi)
{
    dvec h;
    double pdf = 0.0, Ns = c->m.Ns;
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    h = dv_normalize(dv_lin(wo, 1.0, wi, 1.0));
    if (c->ps < 1.0) pdf += (1.0 - c->ps) * wi.z / PI;
    if (c->ps > 0.0) pdf += c->ps * (Ns + 1.0) / (2.0 * PI) * pow(h.z, Ns) / (4.0 * dv_dot(wo, h));
    return pdf;
}

/* P(wi.z > 0) and P(wo.h > 0) for h of density (m+1)/(2 pi) cos^m(theta_h), computed in the half-vector
 * domain. With wo at polar angle theta_o and h at (theta, phi) about wo's azimuth, wo.h = R cos(theta - g)
 * and wi.z = R cos(2 theta - g), where R sin g = sin(theta_o) cos(phi), R cos g = cos(theta_o). So
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
            double phi = a + h * (j + 0.5 * (gl_x[k] + 1.0)), R = sqrt(so * so * cos(phi) * cos(phi) + co * co);
            double sin_g = so * cos(phi) / R;
            double v = reflected_above ? pow(0.5 * (1.0 - sin_g), 0.5 * (m + 1.0)) : pow(-sin_g, m + 1.0);
            lost += 0.5 * h * gl_w[k] * v;
        }
    return 1.0 - lost / (2.0 * PI);
}

/* wi-domain density about the mirror direction, and its clip to wi.z > 0 */
static double f_brdf_wi(const void *ctx, dvec wi)
{
    const brdf_case *c = ctx;
    return brdf_pdf(&c->m, c->wo, fv_of(wi));
}

static void clip_wi_above(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const domain *d = ctx;   /* the clip of a wi-domain looks at its own frame */
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t)));
    *A = c * d->F.n.z;
    *B = s * hypot(d->F.t.z, d->F.b.z);
    *phi0 = atan2(d->F.b.z, d->F.t.z);
}

/* half-vector-domain densities: brdf_pdf(wi(h)) 4 wo.h on wi.z > 0, blinn_pdf(wi(h)) 4 wo.h on wo.h > 0 */
static double f_brdf_h(const void *ctx, dvec h)
{
    const brdf_case *c = ctx;
    double wo_h = dv_dot(c->wod, h);
    dvec wi = reflect_d(c->wod, h);
    return wi.z > 0.0 && wo_h > 0.0 ? brdf_pdf(&c->m, c->wo, fv_of(wi)) * 4.0 * wo_h : 0.0;
}

static double f_blinn_h(const void *ctx, dvec h)
{
    const brdf_case *c = ctx;
    double wo_h = dv_dot(c->wod, h);
    return blinn_pdf(c->wo, fv_of(reflect_d(c->wod, h)), c->m.Ns) * 4.0 * fabs(wo_h);
}

static void clip_h_reflected_above(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const brdf_case *k = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t))), th = k->theta_deg * PI / 180.0;
    *A = cos(th) * (2.0 * c * c - 1.0);   /* wi.z = cos(theta_o) cos 2theta + sin(theta_o) sin 2theta cos(phi - phi_o) */
    *B = sin(th) * 2.0 * s * c;
    *phi0 = k->phi_o;
}

static void clip_h_facing_wo(const void *ctx, double t, double *A, double *B, double *phi0)
{
    const brdf_case *k = ctx;
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t))), th = k->theta_deg * PI / 180.0;
    *A = cos(th) * c;                     /* wo.h = cos(theta_o) cos theta + sin(theta_o) sin theta cos(phi - phi_o) */
    *B = sin(th) * s;
    *phi0 = k->phi_o;
}

/* the wi-domain needs its own frame in the clip: a domain whose ctx is itself */
typedef struct { domain d; const brdf_case *c; } wi_domain;
static double f_brdf_wi_dom(const void *ctx, dvec wi) { return f_brdf_wi(((const wi_domain *)ctx)->c, wi); }

static int draw_brdf(void *ctx, pcg32 *rng, dvec *h)
{
    brdf_case *c = ctx;
    float u0 = pcg32_float(rng), u1 = pcg32_float(rng), u2 = pcg32_float(rng), pdf;
    vec3 wi = brdf_sample(&c->m, c->wo, u0, u1, u2, &pdf);
    dvec wid = dv_of(wi);
    double fn = brdf_pdf(&c->m, c->wo, wi), ref = brdf_pdf_ref(c, c->wod, wid);
    c->n_drawn++;
    if (!(fabs(pdf - fn) <= 1e-4 * fn) || (wi.z > 0.0f) != (pdf > 0.0f)) c->pdf_mismatch++;
    if (ref > 0.0) c->max_rel_ref = fmax(c->max_rel_ref, fabs(fn - ref) / ref);
    if (!(wi.z > 0.0f)) return 0;
    *h = dv_normalize(dv_lin(c->wod, 1.0, wid, 1.0));
    return 1;
}

static void test_brdf_case(brdf_case *c, unsigned seed)
{
    double th = c->theta_deg * PI / 180.0, p_up = half_vector_mass(th, c->m.Ns, 1), expect, integral;
    char line[192];
    domain dh;
    wi_domain dw;
    dvec mirror;

    /* normalized in float: besides, at -O2 GCC 12's SLP vectorizer turned (double)(float)(x) into x
     * here, which made wod differ from wo */
    c->wo = v3_normalize(v3((float)(sin(th) * cos(c->phi_o)), (float)(sin(th) * sin(c->phi_o)), (float)cos(th)));
    c->wod = dv_of(c->wo);
    c->ps = brdf_glossy_prob(&c->m);
    mirror = dv(-c->wod.x, -c->wod.y, c->wod.z);

    /* 1a. over the upper hemisphere of wi, in a frame about the mirror direction: the mixture
     *     loses the glossy reflections that go below the surface, P(wi.z <= 0) of them. */
    memset(&dw, 0, sizeof dw);
    dw.c = c;
    dw.d.f = f_brdf_wi_dom, dw.d.ctx = &dw, dw.d.clip = clip_wi_above, dw.d.F = dframe_about(mirror);
    dw.d.kink[0] = 1.0 - hypot(mirror.x, mirror.y), dw.d.kink[1] = 1.0 + hypot(mirror.x, mirror.y), dw.d.nkinks = 2;
    integral = domain_integral(&dw.d, 2.0, c->theta_deg > 85.0f ? 512 : c->theta_deg > 70.0f ? 96 : 16);
    expect = (1.0 - c->ps) + c->ps * p_up;
    snprintf(line, sizeof line, "integral of brdf_pdf over wi.z > 0: %s, wo at %g deg", c->name, c->theta_deg);
    check(fabs(integral - expect) < INTEGRAL_TOL, line,
          "%.7f, expected (1 - ps) + ps P(wi.z > 0) = %.7f with ps = %.3f, P(wi.z > 0) = %.7f",
          integral, expect, c->ps, p_up);

    /* 1b. the reflected-direction density blinn_pdf over the whole sphere, through dwi = 4 (wo.h) dh:
     *     it is P(wo.h > 0), 1 at normal incidence; the missing mass is the half vectors facing away
     *     from wo, whose reflections all go below the surface (blinn_pdf rightly ignores them). */
    memset(&dh, 0, sizeof dh);
    dh.ctx = c, dh.F = dframe_about(dv(0, 0, 1));
    if (c->ps == 1.0) {
        double p_face = half_vector_mass(th, c->m.Ns, 0);
        dh.f = f_blinn_h, dh.clip = clip_h_facing_wo;
        dh.kink[0] = 1.0 - sin(th), dh.kink[1] = 1.0 + sin(th), dh.nkinks = 2;
        integral = domain_integral(&dh, 2.0, 16);
        snprintf(line, sizeof line, "integral of blinn_pdf over the sphere: Ns=%g, wo at %g deg", c->m.Ns, c->theta_deg);
        check(fabs(integral - p_face) < INTEGRAL_TOL, line, "%.7f, expected P(wo.h > 0) = %.7f", integral, p_face);
    }

    /* 2 and 3: sample, check the pdfs on the way, chi-square in the half-vector domain */
    dh.f = f_brdf_h, dh.clip = clip_h_reflected_above;
    dh.kink[0] = 1.0 - cos(0.25 * PI - 0.5 * th), dh.kink[1] = 1.0 - cos(0.25 * PI + 0.5 * th), dh.nkinks = 2;
    snprintf(line, sizeof line, "chi2 brdf_sample %s, wo at %g deg", c->name, c->theta_deg);
    chi2_directions(line, &dh, draw_brdf, c, 1.0, c->ps * (1.0 - p_up), n_samples / 2, seed);
}

/* ---------- triangles and lights ---------- */

/* Cell of barycentrics (b1, b2) among the n^2 equal sub-triangles of the barycentric triangle:
 * square (a, b) of the n x n grid holds the sub-triangle nearer the origin (index a n + b) and, when
 * a + b < n - 1, the far one (index (n-1-a) n + (n-1-b), unused by the near ones). */
static int subtriangle(double b1, double b2, int n)
{
    double x = b1 * n, y = b2 * n;
    int a = x < 0.0 ? 0 : (int)x, b = y < 0.0 ? 0 : (int)y;
    if (a > n - 1) a = n - 1;
    if (b > n - 1 - a) b = n - 1 - a;
    return (x - a) + (y - b) < 1.0 || a + b == n - 1 ? a * n + b : (n - 1 - a) * n + (n - 1 - b);
}

/* Uniform over the triangle: the barycentric triangle cut into n^2 equal sub-triangles. */
static void test_triangle(void)
{
    enum { n = 16 };
    double obs[n * n], expct[n * n];
    long i, outside = 0;
    pcg32 rng;
    pcg32_init(&rng, 4242u, 3u);
    memset(obs, 0, sizeof obs);
    for (i = 0; i < n * n; i++) expct[i] = (double)n_samples / (n * n);
    for (i = 0; i < n_samples; i++) {
        float b1, b2;
        sample_uniform_triangle(pcg32_float(&rng), pcg32_float(&rng), &b1, &b2);
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f + 1e-6f) {
            outside++;
            continue;
        }
        obs[subtriangle(b1, b2, n)] += 1.0;
    }
    check(outside == 0, "sample_uniform_triangle stays in the triangle", "%ld of %ld outside", outside, n_samples);
    chi2_check("chi2 sample_uniform_triangle", obs, expct, n * n, "; 16 x 16 grid of sub-triangles");
}

#define NTRI 6

static float luminance_709(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* Five emitters of different areas, colours and orientations, and a wall that does not emit. */
static void test_lights(void)
{
    static const float P[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},     {2, 0, 0}, {4, 0, 0},   {2, 1, 0},
                                 {0, 2, 0}, {0.3f, 2, 0}, {0, 2.2f, 0}, {0, 0, 1}, {0, 1, 1},  {3, 0, 1},
                                 {5, 5, 5}, {7, 5, 5}, {5, 7, 5},     {0, 0, 3}, {0, 0.01f, 3}, {0.02f, 0, 3}};
    static const float Ke[NTRI][3] = {{1, 1, 1}, {5, 0, 0}, {0, 0, 20}, {0.2f, 0.5f, 0.1f}, {0, 0, 0}, {100, 100, 100}};
    vec3 Pv[18], Ng[NTRI];
    float area[NTRI];
    int tri[3 * NTRI], tri_mat[NTRI], i, st, e;
    material mats[NTRI];
    mesh m;
    light_set ls;
    memset(&m, 0, sizeof m);
    for (i = 0; i < 18; i++) Pv[i] = v3(P[i][0], P[i][1], P[i][2]);
    for (i = 0; i < NTRI; i++) {   /* the fourth emitter faces -z, the others +z */
        vec3 c;
        tri[3 * i] = 3 * i, tri[3 * i + 1] = 3 * i + 1, tri[3 * i + 2] = 3 * i + 2;
        c = v3_cross(v3_sub(Pv[tri[3 * i + 1]], Pv[tri[3 * i]]), v3_sub(Pv[tri[3 * i + 2]], Pv[tri[3 * i]]));
        area[i] = 0.5f * v3_length(c);
        Ng[i] = v3_normalize(c);
        memset(&mats[i], 0, sizeof mats[i]);
        mats[i].Kd = v3(0.5f, 0.5f, 0.5f);
        mats[i].Ke = v3(Ke[i][0], Ke[i][1], Ke[i][2]);
        tri_mat[i] = i;
    }
    m.P = Pv, m.nverts = 18, m.tri = tri, m.tri_mat = tri_mat, m.ntris = NTRI, m.mats = mats, m.nmats = NTRI;
    i = light_build(&ls, &m, Ng, area);
    if (!check(i == 0 && ls.n == NTRI - 1, "light_build on six triangles", "%d emitters (expected 5)", ls.n))
        return;
    {
        int ok = ls.emitter_of_tri[4] == -1;
        double A = 0.0;
        for (i = 0; i < NTRI; i++) A += i == 4 ? 0.0 : area[i];
        for (e = 0; e < ls.n; e++) ok &= ls.emitter_of_tri[ls.e[e].tri] == e && ls.e[e].area == area[ls.e[e].tri];
        check(ok && fabs(ls.total_area - A) < 1e-6 * A, "light_build emitters and areas",
              "total area %.6f (expected %.6f)", ls.total_area, A);
    }
    for (st = 0; st <= LIGHT_POWER; st++) {   /* the strategies whose pdf is choice / area */
        double w[NTRI], sum = 0.0, obs[NTRI], expct[NTRI], pdf_err = 0.0, geo_err = 0.0, cell[64], cell_e[64];
        char name[96];
        long k;
        pcg32 rng;
        for (e = 0; e < ls.n; e++) {
            const emitter *em = &ls.e[e];
            w[e] = st == LIGHT_AREA ? em->area : st == LIGHT_TRIANGLE ? 1.0 : em->area * luminance_709(em->Le);
            sum += w[e];
        }
        for (e = 0; e < ls.n; e++) {   /* pdf1(s) = (choice probability) / area */
            double want = w[e] / sum / ls.e[e].area;
            pdf_err = fmax(pdf_err, fabs(light_pdf_area(&ls, (light_strategy)st, e, v3(0, 0, 0), v3(0, 0, 0)) - want) / want);
            obs[e] = 0.0, expct[e] = w[e] / sum * (double)n_samples;
        }
        for (k = 0; k < 64; k++) cell[k] = 0.0, cell_e[k] = (double)n_samples / 64.0;
        pcg32_init(&rng, 555u + (unsigned)st, 5u);
        for (k = 0; k < n_samples; k++) {
            light_sample s;
            const emitter *em;
            vec3 d;
            double b1, b2, nn;
            light_sample_point(&ls, (light_strategy)st, v3(0, 0, 0), pcg32_double(&rng), pcg32_float(&rng), pcg32_float(&rng), &s);
            if (s.emitter < 0 || s.emitter >= ls.n) {
                geo_err = INFINITY;
                break;
            }
            em = &ls.e[s.emitter];
            obs[s.emitter] += 1.0;
            /* s on its triangle: barycentrics from the normal equations of p - a = b1 e1 + b2 e2 */
            d = v3_sub(s.p, em->a);
            {
                double e11 = v3_dot(em->e1, em->e1), e12 = v3_dot(em->e1, em->e2), e22 = v3_dot(em->e2, em->e2);
                double d1 = v3_dot(d, em->e1), d2 = v3_dot(d, em->e2), det = e11 * e22 - e12 * e12;
                b1 = (d1 * e22 - d2 * e12) / det, b2 = (d2 * e11 - d1 * e12) / det;
            }
            nn = fabs(v3_dot(d, em->n));
            cell[subtriangle(b1, b2, 8)] += 1.0;
            geo_err = fmax(geo_err, fmax(fmax(-b1, -b2), fmax(b1 + b2 - 1.0, nn)));
            if (fabs(s.pdf_area - light_pdf_area(&ls, (light_strategy)st, s.emitter, v3(0, 0, 0), s.p)) > 1e-6f * s.pdf_area ||
                !v3_is_zero(v3_sub(s.n, Ng[em->tri])) || !v3_is_zero(v3_sub(s.Le, mats[em->tri].Ke)))
                geo_err = INFINITY;
        }
        snprintf(name, sizeof name, "light_pdf_area %s = choice probability / area", light_strategy_name((light_strategy)st));
        check(pdf_err < 1e-5, name, "max relative error %.2g", pdf_err);
        snprintf(name, sizeof name, "light_sample_point %s: s on its emitter, with its n, Le and pdf", light_strategy_name((light_strategy)st));
        check(geo_err < 1e-5, name, "max distance outside the triangle %.2g", geo_err);
        snprintf(name, sizeof name, "chi2 light choice %s", light_strategy_name((light_strategy)st));
        chi2_check(name, obs, expct, ls.n, "; 5 emitters, power = area x Rec. 709 luminance");
        if (st == LIGHT_TRIANGLE)
            chi2_check("chi2 light_sample_point uniform on its triangle", cell, cell_e, 64,
                       "; triangle strategy, barycentrics of s on its emitter, 8 x 8 sub-triangles");
    }
    light_free(&ls);
}

/* Many small emitters (a big emissive mesh): the area pdf must be 1 / (sum of the areas) to float
 * precision, and each strategy's pdf must match the probability with which light_sample_point really
 * picks each emitter: exactly the share of the 2^32 values of u0 = pcg32_double() in
 * [cdf[i-1], cdf[i]), up to that 2^-32 granularity. */
static void test_many_emitters(void)
{
    enum { n = 300000 };
    vec3 *P = malloc(sizeof(vec3) * 3 * n), *Ng = malloc(sizeof(vec3) * n);
    float *area = malloc(sizeof(float) * n);
    int *tri = malloc(sizeof(int) * 3 * n), *tri_mat = calloc(n, sizeof(int)), i, st;
    material mats[3];
    mesh m;
    light_set ls;
    double A = 0.0;
    if (!P || !Ng || !area || !tri || !tri_mat) {
        check(0, "many emitters", "out of memory");
        return;
    }
    memset(mats, 0, sizeof mats);
    for (i = 0; i < 3; i++) mats[i].Ke = v3(1.0f + i, 1.0f, 0.5f * i);
    for (i = 0; i < n; i++) {   /* right triangles of legs 0.01 x (1 + (i mod 7)/10), in a row */
        float x = 0.02f * (float)(i % 1000), y = 0.02f * (float)(i / 1000), l = 0.01f * (1.0f + 0.1f * (float)(i % 7));
        P[3 * i] = v3(x, y, 0), P[3 * i + 1] = v3(x + l, y, 0), P[3 * i + 2] = v3(x, y + 0.01f, 0);
        tri[3 * i] = 3 * i, tri[3 * i + 1] = 3 * i + 1, tri[3 * i + 2] = 3 * i + 2;
        tri_mat[i] = i % 3;
        area[i] = 0.5f * l * 0.01f;
        Ng[i] = v3(0, 0, 1);
        A += area[i];
    }
    memset(&m, 0, sizeof m);
    m.P = P, m.nverts = 3 * n, m.tri = tri, m.tri_mat = tri_mat, m.ntris = n, m.mats = mats, m.nmats = 3;
    i = light_build(&ls, &m, Ng, area);
    if (check(i == 0 && ls.n == n, "light_build on 300000 emitters", "%d emitters", ls.n)) {
        check(fabs(light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0)) * A - 1.0) < 1e-5, "area pdf of 300000 emitters = 1 / total area",
              "1/pdf = %.7g, sum of the areas %.7g (relative gap %.2g)", 1.0 / light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0)), A,
              light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0)) * A - 1.0);
        for (st = 0; st <= LIGHT_POWER; st++) {   /* the strategies whose pdf is choice / area */
            double worst = 0.0, worst_allowed = 0.0, prev = 0.0, sum_p = 0.0;
            char name[96];
            for (i = 0; i < n; i++) {
                double next = ceil((double)ls.cdf[st][i] * 4294967296.0), picked = (next - prev) / 4294967296.0;
                double claimed = (double)light_pdf_area(&ls, (light_strategy)st, i, v3(0, 0, 0), v3(0, 0, 0)) * ls.e[i].area;
                double gap = fabs(picked - claimed) / claimed, allowed = 1.0 / 4294967296.0 / claimed + 1e-5;
                if (gap / allowed > worst) worst = gap / allowed, worst_allowed = allowed;
                sum_p += claimed;
                prev = next;
            }
            snprintf(name, sizeof name, "300000 emitters, %s: pick probabilities = pdf x area", light_strategy_name((light_strategy)st));
            check(worst <= 1.0 && fabs(sum_p - 1.0) < 1e-4, name,
                  "worst gap %.2g of the allowed 2^-32/p + 1e-5 (= %.2g there); sum of pdf x area %.7f", worst,
                  worst_allowed, sum_p);
        }
        light_free(&ls);
    }
    free(P), free(Ng), free(area), free(tri), free(tri_mat);
}

/* ---------- spot checks of the pdfs off their support ---------- */

static void test_supports(void)
{
    material g = make_material(0.3f, 0.5f, 20.0f);
    vec3 up = v3(0.3f, 0.1f, 0.9486833f), down = v3(0.3f, 0.1f, -0.9486833f);
    float pdf;
    int ok = pdf_uniform_hemisphere(down) == 0.0f && pdf_cosine_hemisphere(down) == 0.0f &&
             pdf_cos_power(down, 10.0f) == 0.0f && brdf_pdf(&g, up, down) == 0.0f && brdf_pdf(&g, down, up) == 0.0f &&
             v3_is_zero(brdf_eval(&g, up, down)) && v3_is_zero(brdf_eval(&g, down, up));
    brdf_sample(&g, down, 0.9f, 0.3f, 0.6f, &pdf);
    check(ok && pdf == 0.0f, "pdfs and BRDF vanish below the surface", "wo or wi with z < 0");
}

/* brdf_eval against the slides' formula in double, and its symmetry in (wo, wi). */
static void test_brdf_eval(void)
{
    static const float Ns[] = {1.0f, 10.0f, 100.0f, 1e4f};
    double worst = 0.0, max_sym = 0.0;
    int i, k;
    pcg32 rng;
    pcg32_init(&rng, 31u, 4u);
    for (k = 0; k < 4; k++) {
        material m = make_material(0.5f, 0.4f, Ns[k]);
        double tol = 1e-4 + 8.0 * Ns[k] * 5.96e-8;   /* float rounding of cos theta_h, times Ns */
        for (i = 0; i < 20000; i++) {
            vec3 wo = sample_uniform_hemisphere(pcg32_float(&rng), pcg32_float(&rng));
            vec3 wi = sample_uniform_hemisphere(pcg32_float(&rng), pcg32_float(&rng)), f, g;
            dvec h, r = reflect_d(dv_of(wo), dv_of(sample_cos_power(pcg32_float(&rng), pcg32_float(&rng), Ns[k])));
            double lobe;
            int c;
            if (i % 2 && r.z > 0.0) wi = v3_normalize(fv_of(r));   /* half of them in the glossy lobe */
            f = brdf_eval(&m, wo, wi), g = brdf_eval(&m, wi, wo);
            h = dv_normalize(dv_lin(dv_of(wo), 1.0, dv_of(wi), 1.0));
            lobe = (Ns[k] + 8.0) / (8.0 * PI) * pow(h.z, Ns[k]);
            for (c = 0; c < 3; c++) {
                double ref = v3_comp(m.Kd, c) / PI + v3_comp(m.Ks, c) * lobe;
                worst = fmax(worst, fabs(v3_comp(f, c) - ref) / ref / tol);
                max_sym = fmax(max_sym, fabs(v3_comp(f, c) - v3_comp(g, c)) / ref);
            }
        }
    }
    check(worst < 1.0 && max_sym == 0.0, "brdf_eval = Kd/pi + Ks (Ns+8)/(8 pi) cos^Ns(theta_h), symmetric",
          "Ns = 1, 10, 100, 1e4, 80000 pairs, half in the lobe: worst relative error %.2g of the allowed "
          "1e-4 + 8 Ns 2^-24; f(wo, wi) - f(wi, wo) up to %.2g", worst, max_sym);
}

int main(void)
{
    static const warp warps[] = {{0, 0}, {1, 0}, {2, 1}, {2, 10}, {2, 100}, {2, 1e4f}};
    static const float thetas[] = {0.0f, 30.0f, 60.0f, 80.0f, 89.0f};
    static struct { const char *name; float kd, ks, Ns; } mats[] = {
        {"diffuse", 0.8f, 0.0f, 10.0f},           {"glossy Ns=1", 0.0f, 0.5f, 1.0f},
        {"glossy Ns=10", 0.0f, 0.5f, 10.0f},      {"glossy Ns=100", 0.0f, 0.5f, 100.0f},
        {"glossy Ns=1e4", 0.0f, 0.9f, 1e4f},      {"mixed Kd .5 Ks .3 Ns=10", 0.5f, 0.3f, 10.0f},
        {"mixed Kd .2 Ks .6 Ns=1e4", 0.2f, 0.6f, 1e4f}};
    const int nwarps = 6, nthetas = 5, nmats = 7, ncases = nwarps + nthetas * nmats + 1 + (LIGHT_POWER + 1) + 1;
    const char *fast = getenv("PATHLAB_FAST");
    int i, j;
    unsigned seed = 1;

    if (fast && *fast && strcmp(fast, "0")) n_samples /= 10;
    alpha_case = 1.0 - pow(1.0 - ALPHA, 1.0 / ncases);
    printf("# %d chi-square cases, family-wise alpha %g, per case %.3g; %ld samples each\n", ncases, ALPHA,
           alpha_case, n_samples);
    gl_init();
    test_chi2_pvalue();
    test_supports();
    test_brdf_eval();
    for (i = 0; i < nwarps; i++) test_warp(&warps[i], seed++);
    for (i = 0; i < nmats; i++) {
        double max_rel = 0.0, tol = 1e-4 + 8.0 * mats[i].Ns * 5.96e-8;
        long mismatch = 0, drawn = 0;
        char line[160];
        for (j = 0; j < nthetas; j++) {
            brdf_case c;
            memset(&c, 0, sizeof c);
            c.name = mats[i].name;
            c.m = make_material(mats[i].kd, mats[i].ks, mats[i].Ns);
            c.theta_deg = thetas[j];
            c.phi_o = 0.7f + (float)j;
            test_brdf_case(&c, seed++);
            max_rel = fmax(max_rel, c.max_rel_ref);
            mismatch += c.pdf_mismatch;
            drawn += c.n_drawn;
        }
        snprintf(line, sizeof line, "brdf_sample pdf = brdf_pdf = the formula: %s", mats[i].name);
        check(mismatch == 0 && max_rel < tol, line,
              "%ld samples over %d wo: %ld returned pdfs differ from brdf_pdf (or are 0 above / > 0 below "
              "the surface); brdf_pdf vs the double formula: max relative error %.2g (float rounding of "
              "cos theta_h, allowed 1e-4 + 8 Ns 2^-24 = %.2g)", drawn, nthetas, mismatch, max_rel, tol);
    }
    test_triangle();
    test_lights();
    test_many_emitters();
    check(n_chi2_done == ncases, "every chi-square case counted in the Sidak correction", "%d run, %d counted",
          n_chi2_done, ncases);
    return check_summary();
}
