/* warp_check.c — the warps of sampling.c against their pdfs: directions about +z (uniform, cosine,
 * cos^m: the Blinn half vector) and points on a triangle (warp_check.h). */
#include "check/warp_check.h"
#include "check/chi2_sphere.h"
#include "check/chi2_triangle.h"
#include <stdio.h>
#include <string.h>

#define SPOT_CHECKS 200000        /* samples whose pdf is compared with the formula */
#define FORMULA_TOL 1e-4          /* relative, float pdf against the double formula */
#define UNIT_TOL 1e-5             /* | |w| - 1 | */
#define TRIANGLE_GRID 16

static double f_warp(const void *ctx, dvec w)
{
    const warp_routine *W = ctx;
    return W->pdf(fv_of(w), W->m);
}

static int draw_warp(void *ctx, pcg32 *rng, dvec *w)
{
    const warp_routine *W = ctx;
    float u1 = pcg32_float(rng), u2 = pcg32_float(rng);
    *w = dv_of(W->sample(u1, u2, W->m));
    return 1;
}

/* The pdf at samples, the first 9 at the corners and middles of [0, 1)^2 (1 - 2^-24 is the largest
 * pcg32_float): positive, the formula's value, at unit directions above the surface. */
static void spot_check_warp(const warp_routine *W, pcg32 rng, sampling_result *r)
{
    static const float edge[3] = {0.0f, 0.5f, 1.0f - 0x1p-24f};
    int i;
    r->has_formula = r->has_geom = 1;
    r->formula_tol = FORMULA_TOL, r->geom_tol = UNIT_TOL;
    r->pdf_checked = SPOT_CHECKS;
    for (i = 0; i < SPOT_CHECKS; i++) {
        float u1 = i < 9 ? edge[i % 3] : pcg32_float(&rng), u2 = i < 9 ? edge[i / 3] : pcg32_float(&rng);
        vec3 w = W->sample(u1, u2, W->m);
        double ref = w.z > 0.0f ? W->formula(w.z, W->m) : 0.0, pdf = W->pdf(w, W->m);
        r->geom_gap = fmax(r->geom_gap, fabs(v3_length(w) - 1.0));
        r->outside += w.z < 0.0f;
        r->pdf_mismatch += !(pdf > 0.0f);
        if (ref > 0.0) r->formula_gap = fmax(r->formula_gap, fabs(pdf - ref) / ref);
        else r->formula_gap = fmax(r->formula_gap, pdf > 0.0 ? INFINITY : 0.0);
    }
}

void check_warp(const warp_routine *W, long n, uint64_t seed, sampling_result *r)
{
    warp_routine w = *W;
    sphere_domain d;
    sphere_chi2 s;
    memset(&d, 0, sizeof d);
    d.f = f_warp, d.ctx = &w, d.F = dframe_about(dv(0, 0, 1));

    /* the integral over the whole sphere: the pdf must vanish below the horizon */
    r->nintegrals = 1;
    r->integral[0] = sphere_integral(&d, 2.0, 4), r->integral_want[0] = 1.0, r->integral_what[0] = "over the sphere";
    spot_check_warp(&w, case_stream(seed, 2), r);
    s = chi2_directions(&d, draw_warp, &w, 1.0, 0.0, n, case_stream(seed, 0), case_stream(seed, 1));
    r->n = n, r->chi2 = s.chi2, r->discarded = s.discarded;
    snprintf(r->cells, sizeof r->cells, "%d x %d cells in (1 - cos theta, phi)", s.rings, SPHERE_SECTORS);
}

static double twice(const void *ctx, double b1, double b2) { (void)ctx, (void)b1, (void)b2; return 2.0; }

/* Uniform in area is uniform in (b1, b2): density 2 on the barycentric triangle of area 1/2. */
void check_triangle(const triangle_routine *T, long n, uint64_t seed, sampling_result *r)
{
    enum { cells = TRIANGLE_GRID * TRIANGLE_GRID };
    double obs[cells], expct[cells];
    pcg32 rng = case_stream(seed, 0);
    long i;
    int k;
    memset(obs, 0, sizeof obs);
    for (k = 0; k < cells; k++) expct[k] = (double)n * tri_cell_integral(twice, NULL, k, TRIANGLE_GRID);
    r->has_geom = 1, r->geom_tol = 1e-6;
    for (i = 0; i < n; i++) {
        float b1, b2;
        T->sample(pcg32_float(&rng), pcg32_float(&rng), &b1, &b2);
        r->geom_gap = fmax(r->geom_gap, fmax(fmax(-b1, -b2), b1 + b2 - 1.0f));
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f + 1e-6f) {
            r->outside++;
            continue;
        }
        obs[tri_cell(b1, b2, TRIANGLE_GRID)] += 1.0;
    }
    r->n = n, r->chi2 = chi2_test(obs, expct, cells);
    snprintf(r->cells, sizeof r->cells, "%d x %d sub-triangles", TRIANGLE_GRID, TRIANGLE_GRID);
}
