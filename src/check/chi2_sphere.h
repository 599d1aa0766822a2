/* chi2_sphere.h — the chi-square test of a direction sampler. Directions are binned in (t, phi)
 * about an axis, t = 1 - cos(angle to the axis), so that d omega = dt dphi: 16 equal sectors in phi
 * times up to 20 rings in t whose bounds are quantiles of a pilot sample (another stream), so that
 * the cells follow a lobe of any width yet do not depend on the tested sample. The expected count
 * of a cell is N times the integral of the pdf over it, by Gauss-Legendre quadrature in double.
 * Also: the integral of a density over the sphere. */
#ifndef PATHLAB_CHI2_SPHERE_H
#define PATHLAB_CHI2_SPHERE_H
#include "stats/chi2.h"
#include "math/rng.h"
#include "math/dvec.h"
#include "math/vec.h"

#define SPHERE_RINGS 20
#define SPHERE_SECTORS 16

/* A density f over directions, integrated in d omega = dt dphi about F.n; if clip is set, only where
 * A + B cos(phi - phi0) > 0 (clip gives A, B, phi0 for the ring at t). The t where the clipped arc
 * appears or vanishes are kinks of the integrand: list them, the quadrature splits there. */
typedef struct {
    double (*f)(const void *ctx, dvec w);
    void (*clip)(const void *ctx, double t, double *A, double *B, double *phi0);
    const void *ctx;
    dframe F;
    double kink[4];
    int nkinks;
} sphere_domain;

/* Integral over t in [0, tmax] (tmax = 2: the whole sphere). */
double sphere_integral(const sphere_domain *d, double tmax, int ppanels);

/* One sample: 1 with w set (a unit direction in the same coordinates as the domain), or 0 for a
 * sample that was discarded (a reflection below the surface); discarded samples have a cell of
 * their own, expected p_discard N. */
typedef int (*sphere_draw_fn)(void *ctx, pcg32 *rng, dvec *w);

typedef struct {
    chi2_result chi2;
    int rings;           /* rings in t (times SPHERE_SECTORS sectors, plus the discarded cell) */
    double discarded;    /* samples observed in the discarded cell */
} sphere_chi2;

/* Draws n samples from the stream rng (and the ring bounds from the stream pilot) over t in
 * [0, tmax], and compares their counts with the pdf d->f. */
sphere_chi2 chi2_directions(const sphere_domain *d, sphere_draw_fn draw, void *ctx, double tmax,
                            double p_discard, long n, pcg32 rng, pcg32 pilot);
/* The same with the ring bounds from another sampler (pilot_draw): a sample read from a file cannot
 * give its own cells without making them depend on it, so the pilot is a reference sampler of the
 * pdf (check/student_check.c). */
sphere_chi2 chi2_directions_piloted(const sphere_domain *d, sphere_draw_fn draw, void *ctx, sphere_draw_fn pilot_draw,
                                    void *pilot_ctx, double tmax, double p_discard, long n, pcg32 rng, pcg32 pilot);
#endif
