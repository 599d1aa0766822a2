/* light.c — emitters and the choice of a point s on them: first an emitter (a discrete
 * probability: a cdf, or for tree a descent of light_tree.c), then a point on it (uniform per unit
 * area, or per steradian for solid-angle). */
#include "tracer/light.h"
#include "tracer/sampling.h"
#include <assert.h>
#include <stdlib.h>
#include "math/dvec.h"

const char *const LIGHT_STRATEGY_NAMES[] = {"area", "triangle", "power", "solid-angle", "tree", 0};

/* Weight of emitter i in the discrete choice of each strategy (before normalisation). */
static float choice_weight(const emitter *e, light_strategy strategy)
{
    switch (strategy) {
    case LIGHT_AREA: return e->area;
    case LIGHT_TRIANGLE: return 1.0f;
    default: return e->area * fmaxf(luminance(e->Le), 0.0f);
    }
}

/* The tree's view of the emitters: box, normal, power (the power strategy's weight) */
static int build_tree(light_set *ls)
{
    light_bounds *b = malloc(sizeof(light_bounds) * (size_t)ls->n);
    int i, rc;
    if (!b) return 1;
    for (i = 0; i < ls->n; i++) {
        const emitter *e = &ls->e[i];
        vec3 q1 = v3_add(e->a, e->e1), q2 = v3_add(e->a, e->e2);
        b[i].lo = v3_min(e->a, v3_min(q1, q2)), b[i].hi = v3_max(e->a, v3_max(q1, q2));
        b[i].n = e->n, b[i].power = choice_weight(e, LIGHT_POWER);
    }
    rc = light_tree_build(&ls->tree, b, ls->n);
    free(b);
    return rc;
}

static int build_cdf(light_set *ls, light_strategy strategy)
{
    double sum = 0.0, acc = 0.0;
    int i;
    ls->cdf[strategy] = malloc(sizeof(double) * (size_t)ls->n);
    if (!ls->cdf[strategy]) return 1;
    for (i = 0; i < ls->n; i++) sum += choice_weight(&ls->e[i], strategy);
    for (i = 0; i < ls->n; i++) {
        acc += choice_weight(&ls->e[i], strategy);
        ls->cdf[strategy][i] = sum > 0.0 ? acc / sum : (double)(i + 1) / ls->n;
    }
    ls->cdf[strategy][ls->n - 1] = 1.0;
    return 0;
}

/* solid-angle chooses its triangle as power does */
static light_strategy choice_of(light_strategy strategy) { return strategy == LIGHT_SOLID_ANGLE ? LIGHT_POWER : strategy; }

int light_build(light_set *ls, const mesh *m, const vec3 *Ng, const float *area)
{
    double total_area = 0.0;   /* a float sum of 1e5 small areas drifts by 1e-4 or more */
    int i, strategy;
    ls->n = 0;
    ls->total_area = 0.0f;
    ls->e = malloc(sizeof(emitter) * (size_t)(m->ntris > 0 ? m->ntris : 1));
    ls->emitter_of_tri = malloc(sizeof(int) * (size_t)(m->ntris > 0 ? m->ntris : 1));
    for (strategy = 0; strategy < LIGHT_NSTRATEGIES; strategy++) ls->cdf[strategy] = NULL;
    ls->tree.node = NULL, ls->tree.path = NULL, ls->tree.depth = NULL, ls->tree.nnodes = 0;
    if (!ls->e || !ls->emitter_of_tri) return 1;
    for (i = 0; i < m->ntris; i++) {
        vec3 Ke = m->mats[m->tri_mat[i]].Ke;
        const int *t = m->tri + 3 * i;
        emitter *e = &ls->e[ls->n];
        ls->emitter_of_tri[i] = -1;
        if (v3_is_zero(Ke)) continue;
        e->a = m->P[t[0]];
        e->e1 = v3_sub(m->P[t[1]], e->a);
        e->e2 = v3_sub(m->P[t[2]], e->a);
        e->n = Ng[i];
        e->Le = Ke;
        e->area = area[i];
        e->tri = i;
        total_area += area[i];
        ls->emitter_of_tri[i] = ls->n++;
    }
    ls->total_area = (float)total_area;
    if (ls->n == 0) return 0;
    for (strategy = 0; strategy <= LIGHT_POWER; strategy++)
        if (build_cdf(ls, (light_strategy)strategy)) return 1;
    return build_tree(ls);
}

void light_free(light_set *ls)
{
    int strategy;
    free(ls->e);
    free(ls->emitter_of_tri);
    for (strategy = 0; strategy < LIGHT_NSTRATEGIES; strategy++) free(ls->cdf[strategy]);
    light_tree_free(&ls->tree);
}

/* Smallest i with u < cdf[i]: binary search. */
static int pick(const double *cdf, int n, double u)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (u < cdf[mid]) hi = mid; else lo = mid + 1;
    }
    return lo;
}

/* The probability of choosing emitter i from p (before the point on it). */
static float choice_prob(const light_set *ls, light_strategy strategy, int i, vec3 p, vec3 n)
{
    const double *cdf = ls->cdf[choice_of(strategy)];
    assert(0 <= i && i < ls->n);
    if (strategy == LIGHT_TREE) return (float)light_tree_prob(&ls->tree, i, p, n);
    return (float)(cdf[i] - (i > 0 ? cdf[i - 1] : 0.0));
}

/* Spherical trigonometry runs in double: in float, cos(arc AC') rounds to 1 for the thin
 * sub-triangles of a small spherical triangle, which bent the density by several percent below
 * Omega ~ 1e-2 sr (caught by `pathlab check-sampling`, case "Omega = 4e-4 sr"). */
/* v minus its component along the unit vector u, normalised */
static dvec orthogonal_part(dvec v, dvec u) { return dv_normalize(dv_lin(v, 1.0, u, -dv_dot(v, u))); }

/* The spherical triangle an emitter subtends from p: unit directions A, B, C to its corners, its
 * solid angle Omega (Van Oosterom and Strackee 1983: tan(Omega/2) = |A.(B x C)| / (1 + A.B + B.C +
 * C.A)) and the cosine of its angle alpha at A, between the great arcs AB and AC (sampling needs
 * only alpha's cosine and sine, so no acos). */
typedef struct { dvec A, B, C, C_perp; double omega, cos_alpha; } spherical_triangle;   /* C_perp: C's part orthogonal to A */

static spherical_triangle spherical_triangle_from(const emitter *e, vec3 p)
{
    spherical_triangle t;
    dvec a = dv((double)e->a.x - p.x, (double)e->a.y - p.y, (double)e->a.z - p.z);
    t.A = dv_normalize(a);
    t.B = dv_normalize(dv(a.x + e->e1.x, a.y + e->e1.y, a.z + e->e1.z));
    t.C = dv_normalize(dv(a.x + e->e2.x, a.y + e->e2.y, a.z + e->e2.z));
    t.omega = 2.0 * atan2(fabs(dv_dot(t.A, dv_cross(t.B, t.C))),
                          1.0 + dv_dot(t.A, t.B) + dv_dot(t.B, t.C) + dv_dot(t.C, t.A));
    t.C_perp = orthogonal_part(t.C, t.A);
    t.cos_alpha = fmin(1.0, fmax(-1.0, dv_dot(orthogonal_part(t.B, t.A), t.C_perp)));
    return t;
}

/* Arvo sampling only where its trigonometry stays accurate (light.h); elsewhere, by area.
 * (alpha > 0 is cos_alpha < 1: acos is 0 at 1 only.) */
static int solid_angle_usable(const spherical_triangle *t)
{
    return t->omega > LIGHT_SOLID_ANGLE_MIN && t->omega < LIGHT_SOLID_ANGLE_MAX && t->cos_alpha < 1.0;
}

/* Arvo 1995: a direction uniform over the spherical triangle. u1 picks the sub-triangle A B C'
 * of area u1 Omega (C' on the arc AC), u2 a point on the arc from B to C' with the right density.
 * Arvo's s, t, u, v, q are sin_d, cos_d (d = sub - alpha), u, v, cos_ac here: s and q are points
 * in the course. */
static vec3 sample_spherical_triangle(const spherical_triangle *t, float u1, float u2)
{
    /* sin and cos of d = sub - alpha by the difference formulas: one sincos, and no acos for alpha */
    double cos_alpha = t->cos_alpha, sin_alpha = sqrt((1.0 - cos_alpha) * (1.0 + cos_alpha));
    double sub = u1 * t->omega, sin_sub = sin(sub), cos_sub = cos(sub);
    double sin_d = sin_sub * cos_alpha - cos_sub * sin_alpha, cos_d = cos_sub * cos_alpha + sin_sub * sin_alpha;
    double u = cos_d - cos_alpha, v = sin_d + sin_alpha * dv_dot(t->A, t->B), z;
    double cos_ac = ((v * cos_d - u * sin_d) * cos_alpha - v) / ((v * sin_d + u * cos_d) * sin_alpha);   /* of arc AC' */
    dvec C1, w;
    cos_ac = fmin(1.0, fmax(-1.0, cos_ac));
    C1 = dv_lin(t->A, cos_ac, t->C_perp, sqrt(1.0 - cos_ac * cos_ac));
    z = 1.0 - u2 * (1.0 - dv_dot(C1, t->B));                                         /* cos of arc B P */
    w = dv_lin(t->B, z, orthogonal_part(C1, t->B), sqrt(fmax(0.0, 1.0 - z * z)));
    return v3((float)w.x, (float)w.y, (float)w.z);
}

/* solid-angle's pdf1 per unit area at the point s of emitter i, which subtends t from p (usable). */
static float solid_angle_pdf_area(const light_set *ls, int i, const spherical_triangle *t, vec3 p, vec3 n, vec3 s)
{
    vec3 d = v3_sub(s, p);
    float dist2 = v3_dot(d, d), cos_s = fabsf(v3_dot(ls->e[i].n, d)) / sqrtf(dist2);
    float pdf_sa = choice_prob(ls, LIGHT_SOLID_ANGLE, i, p, n) / (float)t->omega;   /* uniform over Omega */
    return pdf_solid_angle_to_area(pdf_sa, dist2, cos_s);
}

float light_pdf_area(const light_set *ls, light_strategy strategy, int i, vec3 p, vec3 n, vec3 s)
{
    const emitter *e = &ls->e[i];
    /* the area strategy is exactly 1/A; computing it from the cdf would add rounding */
    if (strategy == LIGHT_AREA) return 1.0f / ls->total_area;
    if (strategy == LIGHT_SOLID_ANGLE) {
        spherical_triangle t = spherical_triangle_from(e, p);
        if (solid_angle_usable(&t)) return solid_angle_pdf_area(ls, i, &t, p, n, s);
    }
    return choice_prob(ls, strategy, i, p, n) / e->area;
}

/* The point on emitter i (chosen already) from u1, u2; tree_choice: for tree, the probability its
 * descent gave i (light_pdf_area would descend again). */
static void sample_on_emitter(const light_set *ls, light_strategy strategy, int i, float tree_choice, vec3 p, vec3 n, float u1, float u2, light_sample *out)
{
    const emitter *e = &ls->e[i];
    float b1, b2;
    out->n = e->n;
    out->Le = e->Le;
    out->emitter = i;
    if (strategy == LIGHT_SOLID_ANGLE) {
        spherical_triangle t = spherical_triangle_from(e, p);
        if (solid_angle_usable(&t)) {
            /* the point of the triangle's plane in the sampled direction */
            vec3 w = sample_spherical_triangle(&t, u1, u2);
            float dist = v3_dot(v3_sub(e->a, p), e->n) / v3_dot(w, e->n);
            out->pos = v3_madd(p, w, dist);
            out->pdf_area = solid_angle_pdf_area(ls, i, &t, p, n, out->pos);   /* the t just made: no second one */
            return;
        }
    }
    sample_uniform_triangle(u1, u2, &b1, &b2);
    out->pos = v3_add(e->a, v3_add(v3_scale(e->e1, b1), v3_scale(e->e2, b2)));
    out->pdf_area = strategy == LIGHT_TREE ? tree_choice / e->area : light_pdf_area(ls, strategy, i, p, n, out->pos);
}

void light_sample_point(const light_set *ls, light_strategy strategy, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    double prob;
    int i;
    assert(ls->n > 0);   /* callers sample lights only in a scene that has some */
    if (strategy == LIGHT_TREE) {
        i = light_tree_pick(&ls->tree, p, n, &u0, &prob);
        sample_on_emitter(ls, strategy, i, (float)prob, p, n, u1, u2, out);
        return;
    }
    i = pick(ls->cdf[choice_of(strategy)], ls->n, u0);
    sample_on_emitter(ls, strategy, i, 0.0f, p, n, u1, u2, out);
}

void light_sample_point_joint(const light_set *ls, light_strategy strategy, vec3 p, vec3 n, double u0, float u2, light_sample *out)
{
    const double *cdf = ls->cdf[choice_of(strategy)];
    int i;
    double lo, share, r;
    float u1;
    assert(ls->n > 0);
    if (strategy == LIGHT_TREE) {   /* the descent rescales u0 at each node: r is what is left */
        r = u0;
        i = light_tree_pick(&ls->tree, p, n, &r, &share);
    } else {
        i = pick(cdf, ls->n, u0);
        lo = i > 0 ? cdf[i - 1] : 0.0;
        share = cdf[i] - lo;
        r = share > 0.0 ? (u0 - lo) / share : 0.0;
    }
    u1 = (float)r;
    if (!(u1 < 1.0f)) u1 = 0x1.fffffep-1f;   /* r rounded up to 1, or past it by the cdf's rounding */
    if (!(u1 >= 0.0f)) u1 = 0.0f;
    sample_on_emitter(ls, strategy, i, (float)share, p, n, u1, u2, out);
}
