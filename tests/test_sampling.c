/* test_sampling.c — the warps of sampling.h, the BRDF of brdf.h and the light sampling of light.h,
 * tested against their pdfs. The cases are those of `pathlab check-sampling` (src/check/cases.c: each
 * pdf beside its sampler, the cells, the quadrature), here with 1000000 samples each (the BRDF's
 * 500000; PATHLAB_FAST=1, for sanitizer runs, a tenth) and each check on a line of its own:
 *   1. each pdf integrates to what it should (numerical quadrature, to 1e-3; the BRDF's both through
 *      the half vector and, a second quadrature, in the wi domain);
 *   2. the pdf a sampler returns equals the pdf function there, which equals the course's formula in
 *      double (up to float rounding); the samples are unit, above the surface, on their triangle;
 *   3. a chi-square goodness-of-fit test of each sampler (cells with expected count < 5 pooled,
 *      alpha = 0.01 for the whole file, Sidak-corrected over its chi-square cases).
 * And what check-sampling does not show: the chi-square p-value against closed forms, the pdfs off
 * their support, brdf_eval against the slides' formula, light_build, 300000 emitters, and the
 * reference Arvo map (arvo.h) that bins the solid-angle samples: round trip, and uniformity
 * (directions drawn by rejection). */
#include "check.h"
#include "check/arvo.h"
#include "check/cases.h"
#include "check/chi2_sphere.h"
#include "check/light_scene.h"
#include "check/run.h"
#include "check/verdict.h"
#include "math/rng.h"
#include "stats/significance.h"
#include "tracer/brdf.h"
#include "tracer/light.h"
#include "tracer/sampling.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define SEED 1

static double alpha_case;   /* Sidak: 1 - (1 - CHECK_ALPHA)^(1 / number of chi-square cases) */
static int n_chi2_done;

/* ---------- the chi-square distribution ---------- */

/* Closed forms: Q(1/2, x) = erfc(sqrt x), and for integer a Q(a, x) = e^-x sum_{k<a} x^k / k!. */
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
    static const double obs[] = {10, 20, 30, 3, 1, 0}, expct[] = {12, 18, 30, 2, 1, 1};
    chi2_result r;
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
    /* pooling: the last three cells expect 4 < 5 together, so they join the largest cell: 34 for 34 */
    r = chi2_test(obs, expct, 6);
    check(r.dof == 2 && fabs(r.chi2 - (4.0 / 12 + 4.0 / 18)) < 1e-12 && r.expected_total == 64.0,
          "chi2 statistic with pooling", "chi2 %.6f, dof %d", r.chi2, r.dof);
    {   /* a sample where the pdf says none can be: chi2 infinite, p = 0 */
        static const double o2[] = {50, 60, 1}, e2[] = {51, 60, 0};
        r = chi2_test(o2, e2, 3);
        check(isinf(r.chi2) && r.p == 0.0, "chi2 of a sample where nothing is expected", "chi2 %g, p %g", r.chi2, r.p);
    }
}

/* ---------- spot checks of the pdfs off their support, and of the BRDF ---------- */

static void test_supports(void)
{
    material g = check_sampling_material(0.3f, 0.5f, 20.0f);
    vec3 up = v3(0.3f, 0.1f, 0.9486833f), down = v3(0.3f, 0.1f, -0.9486833f);
    float pdf;
    int ok = pdf_uniform_hemisphere(down) == 0.0f && pdf_cosine_hemisphere(down) == 0.0f &&
             pdf_cos_power(down, 10.0f) == 0.0f && brdf_pdf(&g, up, down) == 0.0f && brdf_pdf(&g, down, up) == 0.0f &&
             v3_is_zero(brdf_eval(&g, up, down)) && v3_is_zero(brdf_eval(&g, down, up));
    brdf_sample(&g, down, 0.9f, 0.3f, 0.6f, &pdf);
    check(ok && pdf == 0.0f, "pdfs and BRDF vanish below the surface", "wo or wi with z < 0");
}
static void test_brdf_eval(void)
{
    static const float Ns[] = {1.0f, 10.0f, 100.0f, 1e4f};
    double worst = 0.0, max_sym = 0.0;
    int i, k;
    pcg32 rng;
    pcg32_init(&rng, 31u, 4u);
    for (k = 0; k < 4; k++) {
        material m = check_sampling_material(0.5f, 0.4f, Ns[k]);
        double tol = 1e-4 + 8.0 * Ns[k] * 5.96e-8;   /* float rounding of cos theta_h, times Ns */
        for (i = 0; i < 20000; i++) {
            vec3 wo = sample_uniform_hemisphere(pcg32_float(&rng), pcg32_float(&rng));
            vec3 wi = sample_uniform_hemisphere(pcg32_float(&rng), pcg32_float(&rng)), f, g;
            dvec h, r = dv_reflect(dv_of(wo), dv_of(sample_cos_power(pcg32_float(&rng), pcg32_float(&rng), Ns[k])));
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

/* ---------- the reference Arvo map ---------- */

/* Spherical triangles seen from points: the corners, then the point. */
static const double ARVO_TRIS[3][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0.3, 0.8, 0}}, {{-2, -1, -1}, {3, -1, -1.2}, {0.1, 4, -0.8}},
                                          {{0, 0, 5}, {0.01, 0, 5}, {0, 0.03, 5.001}}};
static const double ARVO_P[3][3] = {{1.0, 0.4, 0.376}, {0.2, 0.1, 0.3}, {0.2, 0.1, 0.3}};

/* The unit corners of spherical triangle t. */
static void arvo_corners(int t, dvec c[3])
{
    int k;
    for (k = 0; k < 3; k++)
        c[k] = dv_normalize(dv(ARVO_TRIS[t][k][0] - ARVO_P[t][0], ARVO_TRIS[t][k][1] - ARVO_P[t][1], ARVO_TRIS[t][k][2] - ARVO_P[t][2]));
}

/* Round trip (u1, u2) -> w -> (u1, u2), and Girard's area against Van Oosterom and Strackee's. */
static void test_arvo_round_trip(pcg32 *rng)
{
    double worst = 0.0, area_gap = 0.0;
    int t, i;
    for (t = 0; t < 3; t++) {
        dvec c[3];
        arvo_triangle T;
        double vo;
        arvo_corners(t, c);
        T = arvo_triangle_from(c[0], c[1], c[2]);
        vo = 2.0 * atan2(fabs(dv_dot(c[0], dv_cross(c[1], c[2]))), 1.0 + dv_dot(c[0], c[1]) + dv_dot(c[1], c[2]) + dv_dot(c[2], c[0]));
        area_gap = fmax(area_gap, fabs(T.omega - vo));   /* Girard: about 1e-16 / (side^2) */
        for (i = 0; i < 10000; i++) {
            double u1 = pcg32_double(rng), u2 = pcg32_double(rng), v1, v2;
            arvo_coords(&T, arvo_direction(&T, u1, u2), &v1, &v2);
            worst = fmax(worst, fmax(fabs(v1 - u1), fabs(v2 - u2) * (u1 > 1e-6)));
        }
    }
    check(worst < 1e-7 && area_gap < 1e-10, "arvo_coords inverts arvo_direction",
          "3 triangles (Omega from 5e-6 to 3 sr), 30000 points: max |u - u'| %.2g; Girard vs Van Oosterom %.2g sr",
          worst, area_gap);
}

/* A direction uniform over the spherical triangle c, by rejection from the cone of F.n down to cos
 * cmin: inside is on the side of each edge's plane where the third corner is. */
static dvec uniform_in_triangle(const dvec c[3], const dframe *F, double cmin, pcg32 *rng)
{
    dvec w;
    int k;
    for (;;) {
        w = dframe_dir(F, (1.0 - cmin) * pcg32_double(rng), 2.0 * PI * pcg32_double(rng));
        for (k = 0; k < 3; k++) {
            dvec e = dv_cross(c[k], c[(k + 1) % 3]);
            if (dv_dot(w, e) * dv_dot(c[(k + 2) % 3], e) <= 0.0) break;
        }
        if (k == 3) return w;
    }
}

/* Directions uniform over the Omega = 0.5 sr triangle, binned by arvo_coords: uniform in (u1, u2). */
static void test_arvo_uniform(pcg32 *rng)
{
    enum { G = 8, N = 200000 };
    double obs[G * G], expct[G * G], cmin = 1.0, u1, u2;
    dvec c[3], axis;
    dframe F;
    arvo_triangle T;
    chi2_result r;
    int i, k;
    arvo_corners(0, c);
    T = arvo_triangle_from(c[0], c[1], c[2]);
    axis = dv_normalize(dv_lin(dv_lin(c[0], 1.0, c[1], 1.0), 1.0, c[2], 1.0));
    for (k = 0; k < 3; k++) cmin = fmin(cmin, dv_dot(axis, c[k]));
    F = dframe_about(axis);
    memset(obs, 0, sizeof obs);
    for (k = 0; k < G * G; k++) expct[k] = (double)N / (G * G);
    for (i = 0; i < N; i++) {
        arvo_coords(&T, uniform_in_triangle(c, &F, cmin, rng), &u1, &u2);
        obs[(int)fmin(u1 * G, G - 1) * G + (int)fmin(u2 * G, G - 1)] += 1.0;
    }
    r = chi2_test(obs, expct, G * G);
    n_chi2_done++;
    check(r.p >= alpha_case, "chi2 arvo_coords of uniform directions (rejection sampling)",
          "chi2 %.1f, dof %d, p = %.3g, alpha per case %.2g; %d x %d cells, N = %d", r.chi2, r.dof, r.p, alpha_case,
          G, G, N);
}

/* The reference Arvo map that bins the solid-angle samples (one stream for both tests). */
static void test_arvo(void)
{
    pcg32 rng;
    pcg32_init(&rng, 77u, 5u);
    test_arvo_round_trip(&rng);
    test_arvo_uniform(&rng);
}

/* ---------- the cases of check-sampling ---------- */

static void report(const sampling_result *r)
{
    char name[200];
    int k;
    for (k = 0; k < r->nintegrals; k++) {
        snprintf(name, sizeof name, "integral %.72s: %.80s", r->integral_what[k], r->routine);
        check(sampling_integral_pass(r, k), name, "%.7f, want %.7f", r->integral[k], r->integral_want[k]);
    }
    snprintf(name, sizeof name, "pdf and samples: %.80s", r->routine);
    check(sampling_pdf_pass(r) && sampling_samples_pass(r), name,
          "%ld pdfs: %ld differ from the pdf function (or are 0 where it is not); pdf function vs the formula "
          "in double: %s %.2g (allowed %.2g); samples: worst %.2g out (allowed %.2g), %ld out of their domain",
          r->pdf_checked, r->pdf_mismatch, r->has_formula ? "max relative gap" : "not checked", r->formula_gap,
          r->formula_tol, r->geom_gap, r->geom_tol, r->outside);
    snprintf(name, sizeof name, "chi2 %.80s", r->routine);
    n_chi2_done++;
    check(sampling_chi2_pass(r, alpha_case), name,
          "chi2 %.1f, dof %d, p = %.3g, alpha per case %.2g; sum of expected %.6g; N = %ld, %s (%g discarded)",
          r->chi2.chi2, r->chi2.dof, r->chi2.p, alpha_case, r->chi2.expected_total, r->n, r->cells, r->discarded);
}

/* light_build on the five-emitter scene of the light cases */
static void test_light_build(void)
{
    light_scene s;
    int i, e, ok;
    double A = 0.0;
    i = light_scene_build(&s, LIGHT_SCENE_FIVE);
    if (!check(i == 0 && s.ls.n == 5, "light_build on six triangles", "%d emitters (expected 5)", s.ls.n)) return;
    ok = s.ls.emitter_of_tri[4] == -1;
    for (i = 0; i < 6; i++) A += i == 4 ? 0.0 : s.area[i];
    for (e = 0; e < s.ls.n; e++) ok &= s.ls.emitter_of_tri[s.ls.e[e].tri] == e && s.ls.e[e].area == s.area[s.ls.e[e].tri];
    check(ok && fabs(s.ls.total_area - A) < 1e-6 * A, "light_build emitters and areas", "total area %.6f (expected %.6f)",
          s.ls.total_area, A);
    light_scene_free(&s);
}

/* From p = (3, 2, 0.5) on a surface of normal +x, over the emitters of test_tree_many: those with a
 * corner at x > 3 light p and must have a probability > 0; those wholly at x < 2.9 are under p's
 * surface: the normal's bound must take a good part of their probability away (measured: 0.154
 * of the choices, 0.311 without the normal; what is left falls in nodes whose loose bounding sphere
 * holds p, and which then split it evenly among children that both have importance 0). */
static void test_tree_normal(const light_set *ls)
{
    vec3 p = v3(3, 2, 0.5f), n = v3(1, 0, 0);
    double sum = 0.0, under_p = 0.0, under_p_bare = 0.0;
    long lit = 0, lit_zero = 0;
    int i;
    for (i = 0; i < ls->n; i++) {
        const emitter *e = &ls->e[i];
        double pr = (double)light_pdf_area(ls, LIGHT_TREE, i, p, n, p) * e->area;
        float xmax = fmaxf(e->a.x, fmaxf(e->a.x + e->e1.x, e->a.x + e->e2.x));
        sum += pr;
        if (xmax > 3.0f) lit++, lit_zero += !(pr > 0.0);
        else if (xmax < 2.9f) under_p += pr, under_p_bare += (double)light_pdf_area(ls, LIGHT_TREE, i, p, v3(0, 0, 0), p) * e->area;
    }
    check(fabs(sum - 1.0) < 1e-4 && lit_zero == 0 && under_p < 0.6 * under_p_bare,
          "tree, 300000 emitters from (3, 2, 0.5) of normal +x: probabilities sum to 1, none 0 right of p, those under its surface under 0.6 of their share without the normal",
          "sum %.7f; %ld of %ld right of p at 0; under p's surface %.3g of the choices, %.3g without the normal", sum, lit_zero, lit, under_p, under_p_bare);
}

/* The tree over many emitters (all in z = 0, facing +z): its depth, and from points above (every
 * emitter faces them: each must have a probability > 0) and below (none does), the probabilities of
 * light_pdf_area x area sum to 1 */
static void test_tree_many(const light_set *ls)
{
    static const float from[4][3] = {{3, 2, 0.5f}, {10, 3, 0.01f}, {-50, 80, 40}, {5, 5, -1}};
    int i, k, depth = 0;
    for (i = 0; i < ls->n; i++) depth = ls->tree.depth[i] > depth ? ls->tree.depth[i] : depth;
    check(depth == (int)ceil(log2((double)ls->n)), "tree over 300000 emitters: depth ceil(log2 n)", "depth %d", depth);
    for (k = 0; k < 4; k++) {
        vec3 p = v3(from[k][0], from[k][1], from[k][2]);
        double sum = 0.0;
        long zero = 0;
        char name[160];
        for (i = 0; i < ls->n; i++) {
            double pr = (double)light_pdf_area(ls, LIGHT_TREE, i, p, v3(0, 0, 0), p) * ls->e[i].area;
            sum += pr, zero += !(pr > 0.0);
        }
        snprintf(name, sizeof name, "tree, 300000 emitters from (%g, %g, %g): probabilities sum to 1, %s", p.x, p.y, p.z,
                 p.z > 0 ? "none 0" : "below them");
        check(fabs(sum - 1.0) < 1e-4 && (p.z < 0 || zero == 0), name, "sum %.7f, %ld emitters of probability 0", sum, zero);
    }
    test_tree_normal(ls);
}

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
        check(fabs(light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)) * A - 1.0) < 1e-5, "area pdf of 300000 emitters = 1 / total area",
              "1/pdf = %.7g, sum of the areas %.7g (relative gap %.2g)", 1.0 / light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)), A,
              light_pdf_area(&ls, LIGHT_AREA, 0, v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)) * A - 1.0);
        for (st = 0; st <= LIGHT_POWER; st++) {   /* the strategies whose pdf is choice / area */
            double worst = 0.0, worst_allowed = 0.0, prev = 0.0, sum_p = 0.0;
            char name[96];
            for (i = 0; i < n; i++) {
                double next = ceil((double)ls.cdf[st][i] * 9007199254740992.0), picked = (next - prev) / 9007199254740992.0;
                double claimed = (double)light_pdf_area(&ls, (light_strategy)st, i, v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)) * ls.e[i].area;
                double gap = fabs(picked - claimed) / claimed, allowed = 1.0 / 9007199254740992.0 / claimed + 1e-5;
                if (gap / allowed > worst) worst = gap / allowed, worst_allowed = allowed;
                sum_p += claimed;
                prev = next;
            }
            snprintf(name, sizeof name, "300000 emitters, %s: pick probabilities = pdf x area", LIGHT_STRATEGY_NAMES[st]);
            check(worst <= 1.0 && fabs(sum_p - 1.0) < 1e-4, name,
                  "worst gap %.2g of the allowed 2^-53/p + 1e-5 (= %.2g there); sum of pdf x area %.7f", worst,
                  worst_allowed, sum_p);
        }
        test_tree_many(&ls);
        light_free(&ls);
    }
    free(P), free(Ng), free(area), free(tri), free(tri_mat);
}

int main(void)
{
    static sampling_case cases[CHECK_MAX_CASES];
    static sampling_result results[CHECK_MAX_CASES];
    const char *fast = getenv("PATHLAB_FAST");
    long n_samples = 1000000;
    int n = check_sampling_cases(cases, CHECK_MAX_CASES), ncases = n + 1, i;

    if (fast && *fast && strcmp(fast, "0")) n_samples /= 10;
    for (i = 0; i < n; i++) cases[i].brdf.wi_integral = 1;
    alpha_case = sidak_level(CHECK_ALPHA, ncases);
    printf("# %d chi-square cases, family-wise alpha %g, per case %.3g; %ld samples each (BRDF: half)\n", ncases,
           CHECK_ALPHA, alpha_case, n_samples);
    test_chi2_pvalue();
    test_supports();
    test_brdf_eval();
    test_arvo();
    check_sampling_run_all(cases, n, n_samples, SEED, (int)sysconf(_SC_NPROCESSORS_ONLN), results);
    for (i = 0; i < n; i++) report(&results[i]);
    test_light_build();
    test_many_emitters();
    check(n_chi2_done == ncases, "every chi-square case counted in the Sidak correction", "%d run, %d counted",
          n_chi2_done, ncases);
    return check_summary();
}
