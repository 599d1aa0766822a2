/* chi2_sphere.c — cells in (t, phi) on the sphere, the quadrature of a density over them, and the
 * chi-square test of a direction sampler (chi2_sphere.h). */
#include "check/chi2_sphere.h"
#include "stats/quadrature.h"
#include <stdlib.h>
#include <string.h>

#define PILOT_MIN 20000     /* the pilot sample: n/10 directions, at least this many */

/* Pieces of [p0, p1] kept by the clip at ring t (at most 3). */
static int ring_arcs(const sphere_domain *d, double t, double p0, double p1, double *lo, double *hi)
{
    double A, B, phi0, kappa, delta;
    int k, n = 0;
    if (!d->clip) {
        lo[0] = p0, hi[0] = p1;
        return 1;
    }
    d->clip(d->ctx, t, &A, &B, &phi0);
    if (B <= 1e-14 * fabs(A) || -A / B <= -1.0) {   /* the whole ring is in, or out */
        if (A <= 0.0) return 0;
        lo[0] = p0, hi[0] = p1;
        return 1;
    }
    kappa = -A / B;
    if (kappa >= 1.0) return 0;
    delta = acos(kappa);                            /* kept: |phi - phi0| < delta */
    for (k = -2; k <= 2; k++) {
        double a = fmax(p0, phi0 - delta + 2.0 * PI * k), b = fmin(p1, phi0 + delta + 2.0 * PI * k);
        if (a < b && n < 3) lo[n] = a, hi[n] = b, n++;
    }
    return n;
}

static double ring_integral(const sphere_domain *d, double t, double p0, double p1, int ppanels)
{
    double lo[3], hi[3], sum = 0.0;
    int n = ring_arcs(d, t, p0, p1, lo, hi), i, j, k;
    for (i = 0; i < n; i++) {
        double h = (hi[i] - lo[i]) / ppanels;
        for (j = 0; j < ppanels; j++)
            for (k = 0; k < GL_N; k++) sum += gl_weight(h, k) * d->f(d->ctx, dframe_dir(&d->F, t, gl_node(lo[i], h, j, k)));
    }
    return sum;
}

static double interval_integral(const sphere_domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
{
    double h = (t1 - t0) / tpanels, sum = 0.0;
    int j, k;
    for (j = 0; j < tpanels; j++)
        for (k = 0; k < GL_N; k++) sum += gl_weight(h, k) * ring_integral(d, gl_node(t0, h, j, k), p0, p1, ppanels);
    return sum;
}

/* Integral over [t0, t1] x [p0, p1], split at the kinks inside. */
static double piece_integral(const sphere_domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
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

/* Integral over the cell [t0, t1] x [p0, p1], in panels (tpanels per piece of t, ppanels in phi).
 * [t0, t1] is cut into pieces no wider than their distance to the axis (geometrically toward t = 0,
 * down to 1e-12 t1), which resolves lobes of any width about the axis. */
static double sphere_cell_integral(const sphere_domain *d, double t0, double t1, double p0, double p1, int tpanels, int ppanels)
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

double sphere_integral(const sphere_domain *d, double tmax, int ppanels)
{
    return sphere_cell_integral(d, 0.0, tmax, 0.0, 2.0 * PI, 2, ppanels);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Ring bounds tb[0..rings]: quantiles of t over the pilot sample; returns the number of rings. */
static int ring_bounds(const sphere_domain *d, sphere_draw_fn draw, void *ctx, double tmax, long n, pcg32 *pilot, double *tb)
{
    long np = n / 10 > PILOT_MIN ? n / 10 : PILOT_MIN, m = 0, i;
    double *t = malloc(sizeof(double) * (size_t)np), phi;
    int r, nr = 0;
    dvec w;
    tb[nr++] = 0.0;
    if (t) {
        for (i = 0; i < np; i++)
            if (draw(ctx, pilot, &w)) dframe_coords(&d->F, w, &t[m++], &phi);
        qsort(t, (size_t)m, sizeof(double), cmp_double);
        for (r = 1; r < SPHERE_RINGS && m > 0; r++) {
            double q = t[(long)((double)r / SPHERE_RINGS * (double)m)];
            if (q > tb[nr - 1] && q < tmax) tb[nr++] = q;
        }
        free(t);
    }
    tb[nr++] = tmax;
    return nr - 1;
}

sphere_chi2 chi2_directions(const sphere_domain *d, sphere_draw_fn draw, void *ctx, double tmax,
                            double p_discard, long n, pcg32 rng, pcg32 pilot)
{
    return chi2_directions_piloted(d, draw, ctx, draw, ctx, tmax, p_discard, n, rng, pilot);
}

sphere_chi2 chi2_directions_piloted(const sphere_domain *d, sphere_draw_fn draw, void *ctx, sphere_draw_fn pilot_draw,
                                    void *pilot_ctx, double tmax, double p_discard, long n, pcg32 rng, pcg32 pilot)
{
    enum { MAXCELLS = SPHERE_RINGS * SPHERE_SECTORS + 1 };
    double tb[SPHERE_RINGS + 1], obs[MAXCELLS], expct[MAXCELLS];
    int nr = ring_bounds(d, pilot_draw, pilot_ctx, tmax, n, &pilot, tb), r, s, ncell = nr * SPHERE_SECTORS;
    sphere_chi2 out;
    long i;
    memset(obs, 0, sizeof obs);
    for (r = 0; r < nr; r++)
        for (s = 0; s < SPHERE_SECTORS; s++)
            expct[r * SPHERE_SECTORS + s] = (double)n * sphere_cell_integral(d, tb[r], tb[r + 1], 2.0 * PI * s / SPHERE_SECTORS,
                                                                     2.0 * PI * (s + 1) / SPHERE_SECTORS, 2, 2);
    expct[ncell] = (double)n * p_discard;
    for (i = 0; i < n; i++) {
        dvec w;
        double t, phi;
        int ri, si;
        if (!draw(ctx, &rng, &w)) {
            obs[ncell] += 1.0;
            continue;
        }
        dframe_coords(&d->F, w, &t, &phi);
        for (ri = 0; ri < nr - 1 && t >= tb[ri + 1]; ri++) {}
        si = (int)(phi / (2.0 * PI) * SPHERE_SECTORS);
        if (si >= SPHERE_SECTORS) si = SPHERE_SECTORS - 1;
        obs[ri * SPHERE_SECTORS + si] += 1.0;
    }
    out.chi2 = chi2_test(obs, expct, ncell + 1);
    out.rings = nr;
    out.discarded = obs[ncell];
    return out;
}
