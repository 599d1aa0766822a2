/* test_chi2_power.c — the checks of check-sampling have power: fed deliberately wrong samples, their
 * chi-square verdict must be FAIL. Each broken routine is one of pathlab's cases (src/check/cases.c)
 * with a sampler or a pdf swapped for a wrong one, run through the same cells, quadrature and pooling,
 * at the same per-case level as `pathlab check-sampling` (Sidak over its cases). Each comes with its
 * control, the unbroken case with the same sample count, which must pass: the FAIL is the breakage's. */
#include "check.h"
#include "check/cases.h"
#include "check/run.h"
#include "check/verdict.h"
#include "stats/significance.h"
#include "tracer/brdf.h"
#include "tracer/sampling.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define N_SAMPLES 100000
#define SEED 7
#define MAX_BROKEN 16

static sampling_case all[CHECK_MAX_CASES];
static int nall;

static sampling_case find(const char *name)
{
    int i;
    for (i = 0; i < nall; i++)
        if (!strcmp(all[i].name, name)) return all[i];
    fprintf(stderr, "test_chi2_power: no case '%s'\n", name);
    exit(1);
}

/* ---------- broken routines ---------- */

static vec3 cosine_warp(float u1, float u2, float m) { (void)m; return sample_cosine_hemisphere(u1, u2); }
static vec3 cos_power_one_more(float u1, float u2, float m) { return sample_cos_power(u1, u2, m + 1.0f); }

/* Malley without the sqrt: r = u1 is not uniform on the disk */
static vec3 cosine_no_sqrt(float u1, float u2, float m)
{
    float phi = 2.0f * PI_F * u2;
    (void)m;
    return v3(u1 * cosf(phi), u1 * sinf(phi), sqrtf(fmaxf(0.0f, 1.0f - u1 * u1)));
}

/* barycentrics without the sqrt: crowds the corner a */
static void triangle_no_sqrt(float u1, float u2, float *b1, float *b2) { *b1 = u1 * (1.0f - u2), *b2 = u1 * u2; }

static vec3 reflect(vec3 wo, vec3 h) { return v3_sub(v3_scale(h, 2.0f * v3_dot(wo, h)), wo); }

/* brdf_sample with the glossy lobe chosen with probability ps and of exponent Ns */
static vec3 mixture(const material *m, vec3 wo, float ps, float Ns, float u_lobe, float u1, float u2, float *pdf)
{
    vec3 wi = u_lobe < ps ? reflect(wo, sample_cos_power(u1, u2, Ns)) : sample_cosine_hemisphere(u1, u2);
    *pdf = brdf_pdf(m, wo, wi);
    return wi;
}

/* the glossy lobe chosen with probability 1 - ps instead of ps */
static vec3 brdf_lobes_swapped(const material *m, vec3 wo, float u_lobe, float u1, float u2, float *pdf)
{
    return mixture(m, wo, 1.0f - brdf_glossy_prob(m), m->Ns, u_lobe, u1, u2, pdf);
}

/* the half vector with exponent Ns + 1 */
static vec3 blinn_one_more(const material *m, vec3 wo, float u_lobe, float u1, float u2, float *pdf)
{
    return mixture(m, wo, brdf_glossy_prob(m), m->Ns + 1.0f, u_lobe, u1, u2, pdf);
}

/* the pdf of the half vector taken for the pdf of wi: the Jacobian 1/(4 wo.h) forgotten */
static float brdf_pdf_no_jacobian(const material *m, vec3 wo, vec3 wi)
{
    float ps = brdf_glossy_prob(m);
    vec3 h = v3_normalize(v3_add(wo, wi));
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    return (1.0f - ps) * pdf_cosine_hemisphere(wi) + ps * pdf_cos_power(h, m->Ns);
}

/* asked for one strategy, samples another */
static void light_by_power(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    (void)st;
    light_sample_point(ls, LIGHT_POWER, p, n, u0, u1, u2, out);
}

/* Arvo's map fed sqrt(u1): the sub-triangle areas are no longer uniform */
static void arvo_sqrt_u1(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    light_sample_point(ls, st, p, n, u0, sqrtf(u1), u2, out);
}

/* The tree's descent from p with the first child's probability q(k) of node k, seen from p of
 * normal q_n; a uniform point on the leaf's triangle, and the pdf the tree's own light_pdf_area gives
 * it from p of normal n. rescale = 0: u0 is not rescaled at each node (every level compares the
 * same u0 with its q). */
static void tree_descent(const light_set *ls, vec3 p, vec3 n, vec3 q_n, double u0, float u1, float u2, light_sample *out,
                         double (*q_of)(const light_tree *t, int k, vec3 p, vec3 n), int rescale)
{
    const light_tree *t = &ls->tree;
    const emitter *e;
    int k = 0;
    float b1, b2;
    while (t->node[k].right >= 0) {
        double q = q_of(t, k, p, q_n);
        if (u0 < q) u0 = rescale ? u0 / q : u0, k = k + 1;
        else u0 = rescale ? (u0 - q) / (1.0 - q) : u0, k = t->node[k].right;
    }
    out->emitter = t->node[k].emitter, e = &ls->e[out->emitter];
    sample_uniform_triangle(u1, u2, &b1, &b2);
    out->pos = v3_add(e->a, v3_add(v3_scale(e->e1, b1), v3_scale(e->e2, b2)));
    out->n = e->n, out->Le = e->Le;
    out->pdf_area = light_pdf_area(ls, LIGHT_TREE, out->emitter, p, n, out->pos);
}

/* the importance without the normal cones: power / d^2, d^2 clamped at the bounding sphere */
static double no_cone_importance(const light_node *nd, vec3 p)
{
    vec3 v = v3_sub(p, nd->c);
    return nd->power / fmax(v3_dot(v, v), nd->r * nd->r);
}

static double q_no_cone(const light_tree *t, int k, vec3 p, vec3 n)
{
    double i1 = no_cone_importance(&t->node[k + 1], p), i2 = no_cone_importance(&t->node[t->node[k].right], p);
    (void)n;
    return i1 + i2 > 0.0 ? i1 / (i1 + i2) : 0.5;
}

/* the tree's descent with u0 never rescaled */
static void tree_no_rescale(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    (void)st;
    tree_descent(ls, p, n, n, u0, u1, u2, out, light_tree_first_prob, 0);
}

/* the tree's descent blind to the normal at p, checked against the tree's pdf, which sees it */
static void tree_no_normal(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    (void)st;
    tree_descent(ls, p, n, v3(0, 0, 0), u0, u1, u2, out, light_tree_first_prob, 1);
}

/* the tree's descent weighing nodes by power / d^2 only, checked against the tree's pdf */
static void tree_no_cone(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    (void)st;
    tree_descent(ls, p, n, n, u0, u1, u2, out, q_no_cone, 1);
}

/* the tree's pdf with the first child's probability at every step, whichever child the path takes */
static float tree_pdf_first_always(const light_set *ls, light_strategy st, int i, vec3 p, vec3 n, vec3 s)
{
    const light_tree *t = &ls->tree;
    double pr = 1.0;
    int k = 0, level;
    (void)st, (void)s;
    for (level = 0; level < t->depth[i]; level++) {
        pr *= light_tree_first_prob(t, k, p, n);
        k = t->path[i] >> level & 1u ? t->node[k].right : k + 1;
    }
    return (float)pr / ls->e[i].area;
}

/* the sky's direction uniform in theta inside its row, not in cos theta (solid angle) */
static vec3 sky_theta_uniform(const sky *s, double u1, float u2, float *pdf_sa, vec3 *L)
{
    vec3 w = sky_sample(s, u1, u2, pdf_sa, L);
    int j = (int)(acos(fmin(1.0, fmax(-1.0, w.y))) / PI * s->h);
    double r, c, sin_old, sin_new;
    if (j >= s->h) j = s->h - 1;
    r = (s->cos_edge[j] - w.y) / (s->cos_edge[j] - s->cos_edge[j + 1]);
    c = cos(PI * (j + r) / s->h), sin_old = sqrt(fmax(1e-30, 1.0 - (double)w.y * w.y)), sin_new = sqrt(fmax(0.0, 1.0 - c * c));
    return v3((float)(w.x * sin_new / sin_old), (float)c, (float)(w.z * sin_new / sin_old));
}

/* the constant sky sampled over the upper hemisphere only */
static vec3 sky_upper_only(const sky *s, double u1, float u2, float *pdf_sa, vec3 *L)
{
    vec3 w = sky_sample(s, u1, u2, pdf_sa, L);
    return v3(w.x, fabsf(w.y), w.z);
}

/* ---------- the list ---------- */

typedef struct { const char *what; sampling_case broken, control; } breakage;

static int breakages(breakage *b)
{
    int n = 0;
    b[n].what = "cosine samples checked against the uniform pdf", b[n].control = find("uniform_hemisphere");
    b[n].broken = b[n].control, b[n++].broken.warp.sample = cosine_warp;
    b[n].what = "cosine hemisphere without the sqrt (r = u1)", b[n].control = find("cosine_hemisphere");
    b[n].broken = b[n].control, b[n++].broken.warp.sample = cosine_no_sqrt;
    b[n].what = "Blinn half vector of exponent Ns+1 checked against the Ns pdf (Ns = 10)", b[n].control = find("cos_power m=10");
    b[n].broken = b[n].control, b[n++].broken.warp.sample = cos_power_one_more;
    b[n].what = "triangle samples without the sqrt", b[n].control = find("sample_uniform_triangle");
    b[n].broken = b[n].control, b[n++].broken.triangle.sample = triangle_no_sqrt;
    b[n].what = "reflected direction with the half vector of exponent Ns+1 (Ns = 10, wo 60 deg)";
    b[n].control = find("brdf_sample glossy Ns=10, wo 60 deg");
    b[n].broken = b[n].control, b[n++].broken.brdf.sample = blinn_one_more;
    b[n].what = "mixture choosing the glossy lobe with probability 1 - ps (Kd .5, Ks .3)";
    b[n].control = find("brdf_sample mixed Kd .5 Ks .3 Ns=10, wo 30 deg");
    b[n].broken = b[n].control, b[n++].broken.brdf.sample = brdf_lobes_swapped;
    b[n].what = "pdf of the reflected direction without the Jacobian 1/(4 wo.h) (Ns = 100)";
    b[n].control = find("brdf_sample glossy Ns=100, wo 30 deg");
    b[n].broken = b[n].control, b[n++].broken.brdf.pdf = brdf_pdf_no_jacobian;
    b[n].what = "emitters chosen by power, checked against the area pdf", b[n].control = find("light choice area");
    b[n].broken = b[n].control, b[n++].broken.light.sample = light_by_power;
    b[n].what = "points uniform in area, checked against the solid-angle pdf (Omega = 0.5 sr)";
    b[n].control = find("solid-angle, Omega = 0.5 sr");
    b[n].broken = b[n].control, b[n++].broken.light.sample = light_by_power;
    b[n].what = "Arvo's map fed sqrt(u1) (Omega = 0.5 sr)", b[n].control = find("solid-angle, Omega = 0.5 sr");
    b[n].broken = b[n].control, b[n++].broken.light.sample = arvo_sqrt_u1;
    b[n].what = "tree: the descent without rescaling u0 at each node", b[n].control = find("tree, 40 emitters, near (0.3, -0.2, 0.1)");
    b[n].broken = b[n].control, b[n++].broken.light.sample = tree_no_rescale;
    b[n].what = "tree: nodes weighed by power / d^2 (no normal cone), checked against the tree's pdf";
    b[n].control = find("tree, 40 emitters, corner (2.5, 2.5, 2.5)");
    b[n].broken = b[n].control, b[n++].broken.light.sample = tree_no_cone;
    b[n].what = "tree: the descent blind to the normal at p, checked against the tree's pdf";
    b[n].control = find("tree, 40 emitters, (0.3, -0.2, 0.1) normal +y");
    b[n].broken = b[n].control, b[n++].broken.light.sample = tree_no_normal;
    b[n].what = "tree: pdf with the first child's probability at every step", b[n].control = find("tree points, 40 emitters, (0.5, 0.5, 0.5)");
    b[n].broken = b[n].control, b[n++].broken.light.pdf = tree_pdf_first_always;
    b[n].what = "sky directions uniform in theta inside their row (16 x 8 image)", b[n].control = find("sky_sample, 16 x 8 image");
    b[n].broken = b[n].control, b[n++].broken.sky.sample = sky_theta_uniform;
    b[n].what = "constant sky sampled over the upper hemisphere only", b[n].control = find("sky_sample, constant sky");
    b[n].broken = b[n].control, b[n++].broken.sky.sample = sky_upper_only;
    return n;
}

int main(void)
{
    static breakage b[MAX_BROKEN];
    static sampling_case cases[2 * MAX_BROKEN];
    static sampling_result r[2 * MAX_BROKEN];
    double alpha_case;
    int n, i, threads = (int)sysconf(_SC_NPROCESSORS_ONLN);
    nall = check_sampling_cases(all, CHECK_MAX_CASES);
    alpha_case = sidak_level(CHECK_ALPHA, nall);   /* the level of each case of check-sampling */
    n = breakages(b);
    for (i = 0; i < n; i++) cases[2 * i] = b[i].broken, cases[2 * i + 1] = b[i].control;
    check_sampling_run_all(cases, 2 * n, N_SAMPLES, SEED, threads, r);
    printf("# %d broken routines, %d samples each (BRDF: half), FAIL below p = %.3g as in check-sampling\n", n,
           N_SAMPLES, alpha_case);
    for (i = 0; i < n; i++) {
        char name[160];
        const sampling_result *x = &r[2 * i], *c = &r[2 * i + 1];
        snprintf(name, sizeof name, "caught: %s", b[i].what);
        check(!sampling_chi2_pass(x, alpha_case), name, "chi2 %.1f, dof %d, p = %.3g", x->chi2.chi2, x->chi2.dof, x->chi2.p);
        snprintf(name, sizeof name, "control passes: %s", c->routine);
        check(sampling_chi2_pass(c, alpha_case), name, "chi2 %.1f, dof %d, p = %.3g", c->chi2.chi2, c->chi2.dof, c->chi2.p);
    }
    return check_summary();
}
