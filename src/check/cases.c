/* cases.c — the cases of check-sampling with pathlab's routines (cases.h). */
#include "check/cases.h"
#include "tracer/sampling.h"
#include <stdio.h>
#include <string.h>

/* ---------- pathlab's routines, in the form of the checks ---------- */

static vec3 uniform_warp(float u1, float u2, float m) { (void)m; return sample_uniform_hemisphere(u1, u2); }
static float uniform_pdf(vec3 w, float m) { (void)m; return pdf_uniform_hemisphere(w); }
static double uniform_formula(double z, double m) { (void)z, (void)m; return 0.5 / PI; }
static vec3 cosine_warp(float u1, float u2, float m) { (void)m; return sample_cosine_hemisphere(u1, u2); }
static float cosine_pdf(vec3 w, float m) { (void)m; return pdf_cosine_hemisphere(w); }
static double cosine_formula(double z, double m) { (void)m; return z / PI; }
static double cos_power_formula(double z, double m) { return (m + 1.0) / (2.0 * PI) * pow(z, m); }

material check_sampling_material(float kd, float ks, float Ns)
{
    material m;
    memset(&m, 0, sizeof m);
    m.Kd = v3(kd, 0.8f * kd, 0.6f * kd);
    m.Ks = v3(ks, ks, ks);
    m.Ns = Ns;
    return m;
}

static sampling_case *add(sampling_case *c, int *n, int max, sampling_case_kind kind, const char *name)
{
    if (*n >= max) return NULL;
    c += (*n)++;
    memset(c, 0, sizeof *c);
    c->kind = kind, c->share = 1.0;
    snprintf(c->name, sizeof c->name, "%s", name);
    c->brdf.sample = brdf_sample, c->brdf.pdf = brdf_pdf;
    c->light.sample = light_sample_point, c->light.pdf = light_pdf_area;
    c->sky.sample = sky_sample, c->sky.pdf = sky_pdf_sa;
    return c;
}

static void add_warps(sampling_case *cases, int *n, int max)
{
    static const float m[] = {1.0f, 10.0f, 100.0f, 1e4f};
    sampling_case *c;
    char name[80];
    int i;
    if ((c = add(cases, n, max, CASE_WARP, "uniform_hemisphere")))
        c->warp.sample = uniform_warp, c->warp.pdf = uniform_pdf, c->warp.formula = uniform_formula;
    if ((c = add(cases, n, max, CASE_WARP, "cosine_hemisphere")))
        c->warp.sample = cosine_warp, c->warp.pdf = cosine_pdf, c->warp.formula = cosine_formula;
    for (i = 0; i < 4; i++) {   /* the Blinn half vector */
        snprintf(name, sizeof name, "cos_power m=%g", m[i]);
        if ((c = add(cases, n, max, CASE_WARP, name)))
            c->warp.sample = sample_cos_power, c->warp.pdf = pdf_cos_power, c->warp.formula = cos_power_formula, c->warp.m = m[i];
    }
}

/* glossy (ps = 1): the reflected direction alone; mixed: the mixture of both lobes */
static void add_brdfs(sampling_case *cases, int *n, int max)
{
    static const float thetas[] = {0.0f, 30.0f, 60.0f, 80.0f, 89.0f};
    static const struct { const char *name; float kd, ks, Ns; } mats[] = {
        {"diffuse", 0.8f, 0.0f, 10.0f},           {"glossy Ns=1", 0.0f, 0.5f, 1.0f},
        {"glossy Ns=10", 0.0f, 0.5f, 10.0f},      {"glossy Ns=100", 0.0f, 0.5f, 100.0f},
        {"glossy Ns=1e4", 0.0f, 0.9f, 1e4f},      {"mixed Kd .5 Ks .3 Ns=10", 0.5f, 0.3f, 10.0f},
        {"mixed Kd .2 Ks .6 Ns=1e4", 0.2f, 0.6f, 1e4f}};
    sampling_case *c;
    char name[80];
    int i, j;
    for (i = 0; i < 7; i++)
        for (j = 0; j < 5; j++) {
            snprintf(name, sizeof name, "brdf_sample %s, wo %g deg", mats[i].name, thetas[j]);
            if (!(c = add(cases, n, max, CASE_BRDF, name))) continue;
            c->share = 0.5;
            c->brdf.mat = check_sampling_material(mats[i].kd, mats[i].ks, mats[i].Ns);
            c->brdf.theta_deg = thetas[j], c->brdf.phi_o = 0.7f + (float)j;
        }
}

/* light_sample_point_joint in the form of the checks: u1 unused, the point's first coordinate is
 * what the choice left of u0 (for tree: u0 rescaled at every node of the descent) */
static void joint_sample(const light_set *ls, light_strategy st, vec3 p, vec3 n, double u0, float u1, float u2, light_sample *out)
{
    (void)u1;
    light_sample_point_joint(ls, st, p, n, u0, u2, out);
}

/* tree: the choice among the 40 emitters of LIGHT_SCENE_MANY (some face p, some do not) from inside
 * the cluster, from its corner and from far away, and from a surface inside it (a normal: the
 * emitters under it get 0); the point, from plain and joint sampling */
static void add_tree(sampling_case *cases, int *n, int max)
{
    static const struct { const char *name; float p[3]; } from[] = {
        {"tree, 40 emitters, near (0.3, -0.2, 0.1)", {0.3f, -0.2f, 0.1f}},
        {"tree, 40 emitters, corner (2.5, 2.5, 2.5)", {2.5f, 2.5f, 2.5f}},
        {"tree, 40 emitters, far (30, 20, -40)", {30.0f, 20.0f, -40.0f}}};
    sampling_case *c;
    int i;
    for (i = 0; i < 3; i++)
        if ((c = add(cases, n, max, CASE_LIGHT_CHOICE, from[i].name)))
            c->light.st = LIGHT_TREE, c->light.scene = LIGHT_SCENE_MANY, c->light.p = v3(from[i].p[0], from[i].p[1], from[i].p[2]);
    if ((c = add(cases, n, max, CASE_LIGHT_CHOICE, "tree, 5 emitters seen from (1, 1, 2)")))
        c->light.st = LIGHT_TREE, c->light.p = v3(1, 1, 2);
    if ((c = add(cases, n, max, CASE_LIGHT_POINT, "tree points, 40 emitters, (0.5, 0.5, 0.5)")))
        c->light.st = LIGHT_TREE, c->light.scene = LIGHT_SCENE_MANY, c->light.grid = 4, c->light.p = v3(0.5f, 0.5f, 0.5f);
    if ((c = add(cases, n, max, CASE_LIGHT_POINT, "tree joint, 40 emitters, (0.3, -0.2, 0.1)"))) {
        c->light.st = LIGHT_TREE, c->light.scene = LIGHT_SCENE_MANY, c->light.grid = 4, c->light.p = v3(0.3f, -0.2f, 0.1f);
        c->light.sample = joint_sample;
    }
    if ((c = add(cases, n, max, CASE_LIGHT_CHOICE, "tree, 40 emitters, (0.3, -0.2, 0.1) normal +y")))
        c->light.st = LIGHT_TREE, c->light.scene = LIGHT_SCENE_MANY, c->light.p = v3(0.3f, -0.2f, 0.1f), c->light.n = v3(0, 1, 0);
    if ((c = add(cases, n, max, CASE_LIGHT_POINT, "tree joint, 40 emitters, (0.5, 0.5, 0.5) normal -x"))) {
        c->light.st = LIGHT_TREE, c->light.scene = LIGHT_SCENE_MANY, c->light.grid = 4;
        c->light.p = v3(0.5f, 0.5f, 0.5f), c->light.n = v3(-1, 0, 0), c->light.sample = joint_sample;
    }
}

static void add_lights(sampling_case *cases, int *n, int max)
{
    /* points p from which the triangle of LIGHT_SCENE_ONE subtends the solid angle named */
    static const struct { const char *name; float p[3]; } one[] = {
        {"solid-angle, Omega = 0.5 sr", {1.0f, 0.4f, 0.376f}},
        {"solid-angle, Omega = 4e-4 sr (floor 3e-4)", {3.0f, 2.0f, 31.4f}},
        {"solid-angle, Omega = 5.9 sr (ceiling 6)", {0.42f, 0.3f, 0.0202f}},
        {"solid-angle, Omega = 2e-4 sr: by area", {3.0f, 2.0f, 44.6f}},
        {"solid-angle, Omega = 6.1 sr: by area", {0.42f, 0.3f, 0.00963f}}};
    sampling_case *c;
    char name[80];
    int st, i;
    for (st = 0; st <= LIGHT_POWER; st++) {
        snprintf(name, sizeof name, "light choice %s", LIGHT_STRATEGY_NAMES[st]);
        if ((c = add(cases, n, max, CASE_LIGHT_CHOICE, name))) c->light.st = (light_strategy)st;
    }
    if ((c = add(cases, n, max, CASE_LIGHT_POINT, "light_sample_point uniform on its triangle")))
        c->light.st = LIGHT_TRIANGLE, c->light.grid = 8;
    if ((c = add(cases, n, max, CASE_LIGHT_POINT, "solid-angle, 5 emitters seen from (1, 1, 2)")))
        c->light.st = LIGHT_SOLID_ANGLE, c->light.grid = 8, c->light.p = v3(1, 1, 2);
    for (i = 0; i < 5; i++)
        if ((c = add(cases, n, max, CASE_LIGHT_POINT, one[i].name))) {
            c->light.st = LIGHT_SOLID_ANGLE, c->light.grid = 16, c->light.scene = LIGHT_SCENE_ONE;
            c->light.p = v3(one[i].p[0], one[i].p[1], one[i].p[2]);
        }
    add_tree(cases, n, max);
}

int check_sampling_cases(sampling_case *cases, int max)
{
    sampling_case *c;
    int n = 0;
    add_warps(cases, &n, max);
    add_brdfs(cases, &n, max);
    if (add(cases, &n, max, CASE_TRIANGLE, "sample_uniform_triangle")) cases[n - 1].triangle.sample = sample_uniform_triangle;
    add_lights(cases, &n, max);
    if ((c = add(cases, &n, max, CASE_SKY, "sky_sample, constant sky"))) c->sky.w = c->sky.h = 1;
    if ((c = add(cases, &n, max, CASE_SKY, "sky_sample, 16 x 8 image"))) c->sky.w = 16, c->sky.h = 8;
    if ((c = add(cases, &n, max, CASE_SKY, "sky_sample, 5 x 3 image"))) c->sky.w = 5, c->sky.h = 3;
    return n;
}
