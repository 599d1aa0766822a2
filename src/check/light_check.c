/* light_check.c — light_sample_point against light_pdf_area (light_check.h): the choice of an
 * emitter, and the point s on it. Cells: one per emitter for the choice. For the point,
 * cells that follow the documented strategy, so that each expects about as many samples:
 *  - a point uniform in area: the sub-triangles of the emitter; a cell expects N times the integral
 *    of pdf_A over it;
 *  - Arvo's map (solid-angle, Omega within the bounds of docs/estimators.md): cells in Arvo's own
 *    coordinates (u1, u2) of the direction from p to s, recovered by the inverse map in double
 *    (arvo.h, independent of light.c's float code). The map is uniform, d omega = Omega du1 du2, so a
 *    cell expects N times the integral over it of pdf_w Omega du1 du2, with
 *    pdf_w = pdf_A d^2 / cos(theta_s) from light_pdf_area. This checks the spherical sampling, the
 *    ray-plane intersection and the pdf together, and the integral over all cells checks light.c's
 *    Omega (Van Oosterom and Strackee, in float) against Girard's theorem in double.
 * Either layout is right for any sampler, as long as the counts expected are: the layout only
 * decides where the test looks closest. */
#include "check/light_check.h"
#include "check/arvo.h"
#include "check/chi2_triangle.h"
#include "stats/quadrature.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PDF_TOL 1e-6              /* relative: the pdf light_sample_point returns vs light_pdf_area */

/* ---------- the course's pdf, in double ---------- */

/* Rec. 709 in double: the reference for light.c, which uses math/vec.h's luminance() in float */
static double luminance_709(vec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

static double choice_weight(const light_scene *s, light_strategy st, int i)
{
    int t = s->ls.e[i].tri;
    return st == LIGHT_AREA ? s->area[t] : st == LIGHT_TRIANGLE ? 1.0 : s->area[t] * luminance_709(s->mats[t].Ke);
}

static dvec corner(const light_scene *s, int i, int k) { return dv_of(s->P[s->tri[3 * s->ls.e[i].tri + k]]); }

/* The tree's choice of every emitter from p, by walking the whole tree (not light.c's walk down one
 * emitter's path): each node passes its probability to its children in proportion to their
 * importances, half each when both are 0. */
static void tree_choices(const light_tree *t, int k, vec3 p, vec3 n, double prob, double *choice)
{
    const light_node *nd = &t->node[k];
    double i1, i2, q;
    if (nd->right < 0) {
        choice[nd->emitter] = prob;
        return;
    }
    i1 = light_node_importance(nd + 1, p, n), i2 = light_node_importance(&t->node[nd->right], p, n);
    q = i1 + i2 > 0.0 ? i1 / (i1 + i2) : 0.5;
    tree_choices(t, k + 1, p, n, prob * q, choice);
    tree_choices(t, nd->right, p, n, prob * (1.0 - q), choice);
}

/* What the checks know of emitter i seen from p, computed once. */
typedef struct {
    const light_scene *s;
    const light_routine *l;
    int i;
    double choice;       /* the course's probability of choosing it */
    int arvo;            /* sampled by Arvo's map (solid-angle, Omega within the bounds): cells in (u1, u2) */
    arvo_triangle t;     /* the spherical triangle it subtends from p */
} emitter_ctx;

static void emitters_seen(const light_scene *s, const light_routine *l, emitter_ctx *e)
{
    double sum = 0.0, tree[LIGHT_SCENE_MAX];
    int i, k;
    for (i = 0; i < s->ls.n; i++) sum += choice_weight(s, l->st, i);
    if (l->st == LIGHT_TREE) tree_choices(&s->ls.tree, 0, l->p, l->n, 1.0, tree);
    for (i = 0; i < s->ls.n; i++) {
        memset(&e[i], 0, sizeof e[i]);
        e[i].s = s, e[i].l = l, e[i].i = i;
        e[i].choice = l->st == LIGHT_TREE ? tree[i] : choice_weight(s, l->st, i) / sum;
        if (l->st != LIGHT_SOLID_ANGLE) continue;
        {
            dvec c[3];
            for (k = 0; k < 3; k++) c[k] = dv_normalize(dv_lin(corner(s, i, k), 1.0, dv_of(l->p), -1.0));
            e[i].t = arvo_triangle_from(c[0], c[1], c[2]);
            e[i].arvo = e[i].t.omega > LIGHT_SOLID_ANGLE_MIN && e[i].t.omega < LIGHT_SOLID_ANGLE_MAX;
        }
    }
}

/* pdf1(s) per unit area: (choice probability) / A_i, or for Arvo's map (choice) cos_s / (Omega d^2) */
static double pdf_formula(const emitter_ctx *e, dvec sp)
{
    dvec d = dv_lin(sp, 1.0, dv_of(e->l->p), -1.0), n = dv_of(e->s->Ng[e->s->ls.e[e->i].tri]);
    double d2 = dv_dot(d, d);
    if (e->arvo) return e->choice * fabs(dv_dot(n, d)) / sqrt(d2) / (e->t.omega * d2);
    return e->choice / e->s->area[e->s->ls.e[e->i].tri];
}

/* ---------- one sample: which emitter, where on it, and its checks ---------- */

/* The barycentrics of s on emitter i from the normal equations of s - a = b1 e1 + b2 e2; returns the
 * distance from the triangle (out of its plane, or past an edge in barycentric units). */
static double barycentrics(const light_scene *s, int i, dvec sp, double *b1, double *b2)
{
    dvec a = corner(s, i, 0), e1 = dv_lin(corner(s, i, 1), 1.0, a, -1.0), e2 = dv_lin(corner(s, i, 2), 1.0, a, -1.0);
    dvec d = dv_lin(sp, 1.0, a, -1.0), n = dv_of(s->Ng[s->ls.e[i].tri]);
    double e11 = dv_dot(e1, e1), e12 = dv_dot(e1, e2), e22 = dv_dot(e2, e2), d1 = dv_dot(d, e1), d2 = dv_dot(d, e2);
    double det = e11 * e22 - e12 * e12;
    *b1 = (d1 * e22 - d2 * e12) / det, *b2 = (d2 * e11 - d1 * e12) / det;
    return fmax(fmax(fmax(-*b1, -*b2), *b1 + *b2 - 1.0), fabs(dv_dot(d, n)));
}

/* Draws one sample; returns its emitter (-1 if none), with its checks recorded in r. */
static int draw_light(const emitter_ctx *e, pcg32 *rng, sampling_result *r, light_sample *out)
{
    const light_scene *s = e->s;
    const light_routine *l = e->l;
    double u0 = pcg32_double53(rng), b1, b2, want, fn;
    float u1 = pcg32_float(rng), u2 = pcg32_float(rng);
    int i, t;
    l->sample(&s->ls, l->st, l->p, l->n, u0, u1, u2, out);
    i = out->emitter;
    if (i < 0 || i >= s->ls.n) {
        r->outside++;
        return -1;
    }
    t = s->ls.e[i].tri;
    r->geom_gap = fmax(r->geom_gap, barycentrics(s, i, dv_of(out->pos), &b1, &b2));
    fn = l->pdf(&s->ls, l->st, i, l->p, l->n, out->pos);
    want = pdf_formula(&e[i], dv_of(out->pos));
    r->formula_gap = fmax(r->formula_gap, fabs(fn - want) / want);
    r->pdf_checked++;
    if (!(fabs(out->pdf_area - fn) <= PDF_TOL * out->pdf_area) || !v3_is_zero(v3_sub(out->n, s->Ng[t])) ||
        !v3_is_zero(v3_sub(out->Le, s->mats[t].Ke)))
        r->pdf_mismatch++;
    return i;
}

/* ---------- the integral of the pdf over the cells of an emitter ---------- */

/* pdf_A at barycentrics (b1, b2) of emitter i, times 2 A_i: a density in db1 db2 */
static double pdf_in_barycentrics(const void *ctx, double b1, double b2)
{
    const emitter_ctx *e = ctx;
    dvec a = corner(e->s, e->i, 0), b = corner(e->s, e->i, 1), c = corner(e->s, e->i, 2);
    dvec sp = dv_lin(dv_lin(a, 1.0 - b1 - b2, b, b1), 1.0, c, b2);
    return e->l->pdf(&e->s->ls, e->l->st, e->i, e->l->p, e->l->n, fv_of(sp)) * 2.0 * e->s->area[e->s->ls.e[e->i].tri];
}

/* pdf_w Omega at Arvo's coordinates (u1, u2) of emitter i: a density in du1 du2 */
static double pdf_in_arvo(const emitter_ctx *e, double u1, double u2)
{
    dvec w = arvo_direction(&e->t, u1, u2), p = dv_of(e->l->p), n = dv_of(e->s->Ng[e->s->ls.e[e->i].tri]);
    double dist = dv_dot(dv_lin(corner(e->s, e->i, 0), 1.0, p, -1.0), n) / dv_dot(w, n);
    float pdf_area = e->l->pdf(&e->s->ls, e->l->st, e->i, e->l->p, e->l->n, fv_of(dv_lin(p, 1.0, w, dist)));
    return pdf_area * dist * dist / fabs(dv_dot(w, n)) * e->t.omega;
}

static double cell_integral(const emitter_ctx *e, int k, int grid)
{
    double h = 1.0 / grid, u1 = (k / grid) * h, u2 = (k % grid) * h, sum = 0.0;
    int i, j;
    if (!e->arvo) return tri_cell_integral(pdf_in_barycentrics, e, k, grid);
    for (i = 0; i < GL_N; i++)
        for (j = 0; j < GL_N; j++) sum += gl_weight(h, i) * gl_weight(h, j) * pdf_in_arvo(e, gl_node(u1, h, 0, i), gl_node(u2, h, 0, j));
    return sum;
}

/* The cell of a sample s of emitter e. */
static int cell_of(const emitter_ctx *e, vec3 s, int grid)
{
    double b1, b2, u1, u2;
    int a, b;
    if (!e->arvo) {
        barycentrics(e->s, e->i, dv_of(s), &b1, &b2);
        return tri_cell(b1, b2, grid);
    }
    arvo_coords(&e->t, dv_normalize(dv_lin(dv_of(s), 1.0, dv_of(e->l->p), -1.0)), &u1, &u2);
    a = (int)(u1 * grid), b = (int)(u2 * grid);
    return (a < grid ? a : grid - 1) * grid + (b < grid ? b : grid - 1);
}

/* ---------- the cases ---------- */

static int begin(light_scene *s, const light_routine *l, emitter_ctx *e, sampling_result *r)
{
    int i;
    if (light_scene_build(s, l->scene) || s->ls.n == 0) {
        snprintf(r->cells, sizeof r->cells, "could not build the light scene");
        r->outside = 1;
        return 1;
    }
    emitters_seen(s, l, e);
    r->has_formula = 1, r->formula_tol = l->st == LIGHT_SOLID_ANGLE ? 1e-4 : 1e-5;
    r->has_geom = 1, r->geom_tol = 1e-5;
    for (i = 0; i < s->ls.n; i++) {   /* the pdf at each centroid, in case an emitter is never drawn */
        dvec g = dv_lin(dv_lin(corner(s, i, 0), 1.0, corner(s, i, 1), 1.0), 1.0 / 3.0, corner(s, i, 2), 1.0 / 3.0);
        double fn = l->pdf(&s->ls, l->st, i, l->p, l->n, fv_of(g)), want = pdf_formula(&e[i], dv_of(fv_of(g)));
        double facing = dv_dot(dv_of(s->Ng[s->ls.e[i].tri]), dv_lin(dv_of(l->p), 1.0, g, -1.0));
        int k, above = !(v3_dot(l->n, l->n) > 0.0f);   /* a corner above p's surface (any, with no normal) */
        for (k = 0; k < 3; k++) above |= dv_dot(dv_of(l->n), dv_lin(corner(s, i, k), 1.0, dv_of(l->p), -1.0)) > 0.0;
        r->formula_gap = fmax(r->formula_gap, fn == want ? 0.0 : fabs(fn - want) / want);
        if (facing > 0.0 && above && !(fn > 0.0)) r->outside++;   /* it lights p: a pdf of 0 there is a bias */
    }
    return 0;
}

static void end(double *expct, int ncells, long n, sampling_result *r)
{
    int k;
    r->nintegrals = 1, r->integral[0] = 0.0, r->integral_want[0] = 1.0, r->integral_what[0] = "over the emitters";
    for (k = 0; k < ncells; k++) r->integral[0] += expct[k] / (double)n;
}

void check_light_choice(const light_routine *l, long n, uint64_t seed, sampling_result *r)
{
    double obs[LIGHT_SCENE_MAX], expct[LIGHT_SCENE_MAX];
    emitter_ctx e[LIGHT_SCENE_MAX];
    pcg32 rng = case_stream(seed, 0);
    light_scene s;
    long j;
    int i;
    if (begin(&s, l, e, r)) return;
    for (i = 0; i < s.ls.n; i++) obs[i] = 0.0, expct[i] = (double)n * tri_cell_integral(pdf_in_barycentrics, &e[i], 0, 1);
    for (j = 0; j < n; j++) {   /* P(emitter i) = the integral of pdf_A over it */
        light_sample ps;
        if ((i = draw_light(e, &rng, r, &ps)) >= 0) obs[i] += 1.0;
    }
    r->n = n, r->chi2 = chi2_test(obs, expct, s.ls.n);
    end(expct, s.ls.n, n, r);
    snprintf(r->cells, sizeof r->cells, "one cell per emitter (%d)", s.ls.n);
    light_scene_free(&s);
}

void check_light_point(const light_routine *l, long n, uint64_t seed, sampling_result *r)
{
    int g2 = l->grid * l->grid, i, k, narvo = 0;
    double *obs = calloc((size_t)(LIGHT_SCENE_MAX * g2), sizeof(double)), *expct = calloc((size_t)(LIGHT_SCENE_MAX * g2), sizeof(double));
    emitter_ctx e[LIGHT_SCENE_MAX];
    pcg32 rng = case_stream(seed, 0);
    light_scene s;
    long j;
    if (!obs || !expct || begin(&s, l, e, r)) {
        if (!obs || !expct) snprintf(r->cells, sizeof r->cells, "out of memory"), r->outside = 1;
        free(obs), free(expct);
        return;
    }
    for (i = 0; i < s.ls.n; i++) {
        narvo += e[i].arvo;
        for (k = 0; k < g2; k++) expct[i * g2 + k] = (double)n * cell_integral(&e[i], k, l->grid);
    }
    for (j = 0; j < n; j++) {
        light_sample ps;
        if ((i = draw_light(e, &rng, r, &ps)) >= 0) obs[i * g2 + cell_of(&e[i], ps.pos, l->grid)] += 1.0;
    }
    r->n = n, r->chi2 = chi2_test(obs, expct, s.ls.n * g2);
    end(expct, s.ls.n * g2, n, r);
    snprintf(r->cells, sizeof r->cells, "%d emitter(s) x %d x %d cells: %d in Arvo's (u1, u2), %d sub-triangles", s.ls.n,
             l->grid, l->grid, narvo, s.ls.n - narvo);
    light_scene_free(&s);
    free(obs), free(expct);
}
