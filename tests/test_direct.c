/* test_direct.c — known-answer test of the direct light L1 computed by integrate().
 * Scene (built in memory): a diffuse plane z = 0 with Kd = 0.5; a unit square light at height 1
 * facing down, cut into four triangles of different areas and colours (so that the area, triangle
 * and power strategies differ); a diffuse ceiling at z = 2 above the light.
 * The exact radiance leaving a plane point x is
 *     L1(x) = Kd/pi sum_j Le_j E_j(x),   E_j(x) = int_{triangle j} cos(theta_x) cos(theta_s) / d^2 dA,
 * and Lambert's formula gives E_j in closed form (derived in lambert_triangle, checked against a
 * brute-force quadrature). Each estimate averages N camera samples with N chosen from a pilot run
 * for a relative standard error of about 1e-3 (capped), and must lie within 4 standard errors of the
 * exact value in each channel (two-sided alpha = 6.3e-5 per check). At one point, four strategies
 * are run again at a relative standard error of 2.5e-4, so that their 4-sigma tolerance is 1e-3 of
 * the exact value: the check fails if that precision is not reached. Each estimate runs on NTHREADS
 * threads, each with its own stream, so the figures do not depend on the machine. */
#include "check.h"
#include "tracer/integrator.h"
#include "tracer/scene.h"
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define KD 0.5
#define Z_MAX 4.0
#define REL_SE 1e-3
#define NTHREADS 4
#define MIN_NONZERO 1000

static long n_max = 600000;    /* cap on samples per estimate, 0.4 of it for BRDF sampling alone */
static long n_pilot = 20000;   /* PATHLAB_FAST=1 (sanitizer runs): both / 20 */

typedef struct { double x, y, z; } dvec;
static dvec dv(double x, double y, double z) { dvec r; r.x = x; r.y = y; r.z = z; return r; }
static dvec dv_of(vec3 a) { return dv(a.x, a.y, a.z); }
static dvec dv_sub(dvec a, dvec b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static double dv_dot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dv_cross(dvec a, dvec b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static double dv_len(dvec a) { return sqrt(dv_dot(a, a)); }

/* ---------- the scene ---------- */

#define NLIGHT 4
static const float light_Le[NLIGHT][3] = {{4, 2, 1}, {1, 1, 1}, {0.5f, 2, 3}, {2, 0.2f, 0.5f}};

static int build_scene(scene *s)
{
    /* plane corners 0-3, light corners 4-7 and centre 8 (off-centre: triangles of different
     * areas), ceiling corners 9-12 */
    static const float P[13][3] = {{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0},
                                   {-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {0.5f, 0.5f, 1}, {-0.5f, 0.5f, 1}, {0.1f, -0.15f, 1},
                                   {-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
    /* light triangles wound clockwise seen from above, so that (b-a) x (c-a) points down */
    static const int T[8][3] = {{0, 1, 2}, {0, 2, 3}, {5, 4, 8}, {6, 5, 8}, {7, 6, 8}, {4, 7, 8}, {9, 11, 10}, {9, 12, 11}};
    static const int M[8] = {0, 0, 1, 2, 3, 4, 0, 0};
    mesh *m = &s->m;
    int i;
    memset(s, 0, sizeof *s);
    s->emitter_prob = 1.0f;   /* no sky: light sampling always picks an emitter (scene_load sets it so) */
    m->nverts = 13, m->ntris = 8, m->nmats = 1 + NLIGHT;
    m->P = malloc(sizeof(vec3) * 13);
    m->tri = malloc(sizeof(int) * 24);
    m->tri_mat = malloc(sizeof(int) * 8);
    m->mats = calloc((size_t)m->nmats, sizeof(material));
    s->Ng = malloc(sizeof(vec3) * 8);
    s->area = malloc(sizeof(float) * 8);
    s->scale = malloc(sizeof(float) * 8);
    if (!m->P || !m->tri || !m->tri_mat || !m->mats || !s->Ng || !s->area || !s->scale) return 1;
    for (i = 0; i < 13; i++) m->P[i] = v3(P[i][0], P[i][1], P[i][2]);
    for (i = 0; i < 8; i++) {
        vec3 c;
        memcpy(m->tri + 3 * i, T[i], sizeof T[i]);
        m->tri_mat[i] = M[i];
        c = v3_cross(v3_sub(m->P[T[i][1]], m->P[T[i][0]]), v3_sub(m->P[T[i][2]], m->P[T[i][0]]));
        s->area[i] = 0.5f * v3_length(c);
        s->Ng[i] = v3_normalize(c);
        s->scale[i] = triangle_scale(m->P[T[i][0]], m->P[T[i][1]], m->P[T[i][2]]);
    }
    strcpy(m->mats[0].name, "diffuse");
    m->mats[0].Kd = v3(KD, KD, KD);
    for (i = 0; i < NLIGHT; i++) {   /* the lights reflect nothing */
        sprintf(m->mats[1 + i].name, "light%d", i);
        m->mats[1 + i].Ke = v3(light_Le[i][0], light_Le[i][1], light_Le[i][2]);
    }
    if (light_build(&s->lights, m, s->Ng, s->area)) return 1;
    s->accel = bvh_build(m->P, m->tri, m->ntris, 1);
    return s->accel == NULL;
}

/* ---------- the exact answer ---------- */

/* Irradiance per unit radiance at x (normal nx) from a triangle p0 p1 p2 that emits toward its front
 * nL = (p1-p0) x (p2-p0), by Lambert's formula. With v_i = p_i - x, the solid angle A of the triangle
 * seen from x satisfies int_A w dw = 1/2 sum_i gamma_i u_i (Stokes on the sphere), u_i the unit
 * normal of the great circle through v_i, v_{i+1}, gamma_i the angle between them, provided the
 * boundary turns counterclockwise seen from outside the sphere, i.e. clockwise seen from x. From
 * the front the mesh winding is counterclockwise about nL (x is on the side nL points to), so
 *     E = nx . int_A w dw = -1/2 sum_i gamma_i nx . (v_i x v_{i+1}) / |v_i x v_{i+1}|.
 * From the back the same sum is negative: one-sided emission, E = 0. (x must see the whole
 * triangle above its horizon, true for every point used here.) */
static double lambert_triangle(dvec x, dvec nx, const dvec p[3])
{
    double sum = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        dvec a = dv_sub(p[i], x), b = dv_sub(p[(i + 1) % 3], x), c = dv_cross(a, b);
        double gamma = atan2(dv_len(c), dv_dot(a, b));
        sum += gamma * dv_dot(nx, c) / dv_len(c);
    }
    return fmax(0.0, -0.5 * sum);
}

/* The same integral by brute force: composite Gauss-Legendre on the triangle mapped from the unit
 * square by (b1, b2) = (u (1 - v), u v), dA = 2 area u du dv. */
static double brute_force_triangle(dvec x, dvec nx, const dvec p[3])
{
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    dvec e1 = dv_sub(p[1], p[0]), e2 = dv_sub(p[2], p[0]), nL = dv_cross(e1, e2);
    double two_area = dv_len(nL), sum = 0.0, h = 1.0 / 32;
    int i, j, a, b;
    nL = dv(nL.x / two_area, nL.y / two_area, nL.z / two_area);
    for (i = 0; i < 32; i++)
        for (j = 0; j < 32; j++)
            for (a = 0; a < 4; a++)
                for (b = 0; b < 4; b++) {
                    double u = h * (i + 0.5 * (gx[a] + 1.0)), v = h * (j + 0.5 * (gx[b] + 1.0));
                    double b1 = u * (1.0 - v), b2 = u * v, d2, cx, cs;
                    dvec s = dv(p[0].x + b1 * e1.x + b2 * e2.x, p[0].y + b1 * e1.y + b2 * e2.y, p[0].z + b1 * e1.z + b2 * e2.z);
                    dvec d = dv_sub(s, x);
                    d2 = dv_dot(d, d);
                    cx = fmax(0.0, dv_dot(nx, d)) / sqrt(d2);
                    cs = fmax(0.0, -dv_dot(nL, d)) / sqrt(d2);
                    sum += 0.25 * h * h * gw[a] * gw[b] * cx * cs / d2 * two_area * u;
                }
    return sum;
}

/* Exact L1 at x on a diffuse surface with normal nx (three channels), and the check of Lambert's
 * formula against brute force for each light triangle; returns the worst relative gap. */
static double exact_L1(const scene *s, dvec x, dvec nx, double L[3])
{
    double worst = 0.0;
    int i, e;
    L[0] = L[1] = L[2] = 0.0;
    for (e = 0; e < s->lights.n; e++) {
        const emitter *em = &s->lights.e[e];
        dvec p[3];
        double E, Eb;
        p[0] = dv_of(em->a);
        p[1] = dv(em->a.x + em->e1.x, em->a.y + em->e1.y, em->a.z + em->e1.z);
        p[2] = dv(em->a.x + em->e2.x, em->a.y + em->e2.y, em->a.z + em->e2.z);
        E = lambert_triangle(x, nx, p);
        Eb = brute_force_triangle(x, nx, p);
        worst = fmax(worst, fabs(E - Eb) / (Eb > 0.0 ? Eb : 1.0));
        for (i = 0; i < 3; i++) L[i] += KD / PI * v3_comp(em->Le, i) * E;
    }
    return worst;
}

/* ---------- the estimates ---------- */

typedef struct { double sum[3], sum2[3]; long n, nonzero; } accum;

typedef struct {
    const scene *s;
    const integrator_opts *o;
    const ray *r;
    pcg32 rng;
    accum a;
} job;

static void *run_job(void *arg)
{
    job *j = arg;
    trace_stats st;
    sampler smp;
    long k;
    int i;
    memset(&st, 0, sizeof st);
    sampler_from_stream(&smp, &j->rng);   /* independent samples, one stream read in turn */
    for (k = 0; k < j->a.n; k++) {
        vec3 L = integrate(j->s, j->o, j->r, &smp, NULL, &st);
        j->a.nonzero += !v3_is_zero(L);
        for (i = 0; i < 3; i++) {
            double c = v3_comp(L, i);
            j->a.sum[i] += c;
            j->a.sum2[i] += c * c;
        }
    }
    return NULL;
}

/* n samples of L along r, on NTHREADS threads with streams (seed, stream + t). */
static void estimate(const scene *s, const integrator_opts *o, const ray *r, unsigned seed, unsigned stream, long n, accum *a)
{
    job jobs[NTHREADS];
    pthread_t th[NTHREADS];
    int t, i, started[NTHREADS];
    memset(a, 0, sizeof *a);
    for (t = 0; t < NTHREADS; t++) {
        memset(&jobs[t], 0, sizeof jobs[t]);
        jobs[t].s = s, jobs[t].o = o, jobs[t].r = r;
        pcg32_init(&jobs[t].rng, seed, stream + (unsigned)t);
        jobs[t].a.n = n / NTHREADS + (t < n % NTHREADS);
        started[t] = pthread_create(&th[t], NULL, run_job, &jobs[t]) == 0;
        if (!started[t]) run_job(&jobs[t]);
    }
    for (t = 0; t < NTHREADS; t++) {
        if (started[t]) pthread_join(th[t], NULL);
        for (i = 0; i < 3; i++) a->sum[i] += jobs[t].a.sum[i], a->sum2[i] += jobs[t].a.sum2[i];
        a->n += jobs[t].a.n;
        a->nonzero += jobs[t].a.nonzero;
    }
}

static void mean_se(const accum *a, int i, double *mean, double *se)
{
    double n = (double)a->n, m = a->sum[i] / n, var = fmax(0.0, a->sum2[i] / n - m * m) * n / (n - 1.0);
    *mean = m;
    *se = sqrt(var / n);
}

typedef struct {
    const char *name;
    light_strategy light;
    dir_strategy dir;
    direct_strategy direct;
} strategy;

/* Camera ray from eye to the point x; checks integrate()'s L1 against the exact value. */
/* target_rel_se: the pilot run picks N for it (up to the cap); precision > 0: also require the
 * tolerance Z_MAX x standard error to be at most that fraction of the exact value. */
static void check_point_at(const scene *s, const char *where, dvec eye, dvec x, const double exact[3],
                           const strategy *S, unsigned seed, double target_rel_se, long n_cap, double precision)
{
    integrator_opts o;
    ray r;
    accum pilot, a;
    double zmax = 0.0, rel_se = 0.0, m, se;
    long n = n_pilot, cap = S->direct == DIRECT_BRDF ? n_cap / 5 * 2 : n_cap;
    int i;
    char name[160];
    memset(&o, 0, sizeof o);
    o.light = S->light, o.dir = S->dir, o.direct = S->direct;
    o.bmin = o.bmax = 1, o.rr_depth = -1;
    r.o = v3((float)eye.x, (float)eye.y, (float)eye.z);
    r.d = v3((float)(x.x - eye.x), (float)(x.y - eye.y), (float)(x.z - eye.z));
    r.tmax = INFINITY;

    /* pilot run (its own stream) to choose N for the target relative standard error */
    estimate(s, &o, &r, seed, 1000u, n, &pilot);
    for (i = 0; i < 3; i++) {
        double need;
        mean_se(&pilot, i, &m, &se);
        need = m > 0.0 ? (double)pilot.n * (se / (target_rel_se * m)) * (se / (target_rel_se * m)) : 0.0;
        if (need > (double)n) n = need < (double)cap ? (long)need : cap;
    }
    /* the z-test needs a mean of many nonzero terms: BRDF sampling alone of a small far light finds
     * it too rarely to be tested within the cap (its rare hits make the sample variance unreliable) */
    if (exact[0] > 0.0 && (double)pilot.nonzero / (double)pilot.n * (double)n < MIN_NONZERO) {
        printf("# skipped: L1 %s, %s: only %.0f of the %ld samples would be nonzero (need %d)\n", where, S->name,
               (double)pilot.nonzero / (double)pilot.n * (double)n, n, MIN_NONZERO);
        return;
    }
    estimate(s, &o, &r, seed, 2000u, n, &a);
    for (i = 0; i < 3; i++) {
        mean_se(&a, i, &m, &se);
        if (se > 0.0) zmax = fmax(zmax, fabs(m - exact[i]) / se);
        else if (m != exact[i]) zmax = INFINITY;
        if (exact[i] > 0.0) rel_se = fmax(rel_se, se / exact[i]);
    }
    mean_se(&a, 0, &m, &se);
    snprintf(name, sizeof name, "L1 %s, %s", where, S->name);
    if (exact[0] > 0.0 && precision > 0.0)
        check(zmax < Z_MAX && Z_MAX * rel_se <= precision, name,
              "red %.6f vs exact %.6f; max |z| over RGB %.2f < %g; N = %ld; relative standard error %.2g, "
              "so the %g-sigma tolerance is %.2g of the exact value (need <= %g)", m, exact[0], zmax, Z_MAX, n,
              rel_se, Z_MAX, Z_MAX * rel_se, precision);
    else if (exact[0] > 0.0)
        check(zmax < Z_MAX, name,
              "red %.6f vs exact %.6f; max |z| over RGB %.2f < %g (two-sided alpha 6.3e-5); N = %ld (%ld "
              "nonzero), relative standard error %.2g", m, exact[0], zmax, Z_MAX, n, a.nonzero, rel_se);
    else   /* the back of the light: nothing at all, in any sample */
        check(a.sum[0] == 0.0 && a.sum[1] == 0.0 && a.sum[2] == 0.0 && exact[1] == 0.0, name,
              "every one of %ld samples is 0 (exact 0)", n);
}

static void check_point(const scene *s, const char *where, dvec eye, dvec x, const double exact[3],
                        const strategy *S, unsigned seed)
{
    check_point_at(s, where, eye, x, exact, S, seed, REL_SE, n_max, 0.0);
}

/* L0 of the light seen from below (its front: Le) and from above (its back: 0). */
static void check_emission(const scene *s)
{
    integrator_opts o;
    ray up, down;
    pcg32 rng;
    sampler smp;
    trace_stats st;
    vec3 Lu, Ld;
    int e = s->lights.emitter_of_tri[2];   /* triangle 2 contains (-0.3, -0.45, 1)... */
    memset(&o, 0, sizeof o);
    memset(&st, 0, sizeof st);
    o.bmin = o.bmax = 0, o.rr_depth = -1, o.direct = DIRECT_MIS_POWER, o.dir = DIR_COSINE;
    pcg32_init(&rng, 1, 1);
    up.o = v3(0.0f, -0.45f, 0.3f), up.d = v3(0.0f, 0.0f, 1.0f), up.tmax = INFINITY;
    down.o = v3(0.0f, -0.45f, 1.5f), down.d = v3(0.0f, 0.0f, -1.0f), down.tmax = INFINITY;
    sampler_from_stream(&smp, &rng);
    Lu = integrate(s, &o, &up, &smp, NULL, &st);
    Ld = integrate(s, &o, &down, &smp, NULL, &st);
    check(e >= 0 && v3_is_zero(v3_sub(Lu, s->lights.e[e].Le)) && v3_is_zero(Ld), "L0 of the light: Le from the front, 0 from the back",
          "front %g %g %g (Le %g %g %g), back %g %g %g", Lu.x, Lu.y, Lu.z, s->lights.e[e].Le.x, s->lights.e[e].Le.y,
          s->lights.e[e].Le.z, Ld.x, Ld.y, Ld.z);
}

int main(void)
{
    static const strategy S[] = {
        {"light sampling (area)", LIGHT_AREA, DIR_COSINE, DIRECT_LIGHT},
        {"light sampling (triangle)", LIGHT_TRIANGLE, DIR_COSINE, DIRECT_LIGHT},
        {"light sampling (power)", LIGHT_POWER, DIR_COSINE, DIRECT_LIGHT},
        {"light sampling (solid angle)", LIGHT_SOLID_ANGLE, DIR_COSINE, DIRECT_LIGHT},
        {"BRDF sampling (cosine)", LIGHT_AREA, DIR_COSINE, DIRECT_BRDF},
        {"BRDF sampling (brdf)", LIGHT_AREA, DIR_BRDF, DIRECT_BRDF},
        {"BRDF sampling (uniform)", LIGHT_AREA, DIR_UNIFORM, DIRECT_BRDF},
        {"MIS balance (power + uniform)", LIGHT_POWER, DIR_UNIFORM, DIRECT_MIS_BALANCE},
        {"MIS balance (area + cosine)", LIGHT_AREA, DIR_COSINE, DIRECT_MIS_BALANCE},
        {"MIS balance (triangle + brdf)", LIGHT_TRIANGLE, DIR_BRDF, DIRECT_MIS_BALANCE},
        {"MIS power (power + cosine)", LIGHT_POWER, DIR_COSINE, DIRECT_MIS_POWER},
        {"MIS power (area + brdf)", LIGHT_AREA, DIR_BRDF, DIRECT_MIS_POWER},
        {"MIS power (solid angle + brdf)", LIGHT_SOLID_ANGLE, DIR_BRDF, DIRECT_MIS_POWER},
    };
    static const struct { const char *where; double eye[3], x[3]; } P[] = {
        {"under the light centre", {0, -3, 0.5}, {0, 0, 0}},
        {"under a corner of the light", {2, 2, 0.8}, {0.35, -0.3, 0}},
        {"beside the light", {2.5, -2, 3}, {2.5, 1, 0}},
        {"far from the light (light at 83 deg)", {12, 3, 2}, {8, 0, 0}},
        {"under the light, grazing view (1 deg)", {20, 0.1, 0.35}, {0.2, 0.1, 0}},
        {"beside the light, grazing view (0.6 deg)", {-34, 3, 0.3}, {-4, 3, 0}},
        {"ceiling above the light (its back)", {0.3, 0.2, 1.5}, {0.1, -0.1, 2}},
    };
    const char *fast = getenv("PATHLAB_FAST");
    scene s;
    unsigned seed = 7;
    size_t i, j;
    int built;
    if (fast && *fast && strcmp(fast, "0")) n_max /= 20, n_pilot /= 20;
    built = build_scene(&s) == 0;
    if (!check(built && s.lights.n == NLIGHT, "build the scene in memory", "%d emitters", s.lights.n)) return check_summary();
    check_emission(&s);
    for (i = 0; i < sizeof P / sizeof P[0]; i++) {
        dvec x = dv(P[i].x[0], P[i].x[1], P[i].x[2]);
        double exact[3], gap = exact_L1(&s, x, dv(0, 0, x.z > 1.5 ? -1 : 1), exact);
        char name[160];
        snprintf(name, sizeof name, "Lambert's formula = brute-force quadrature, %s", P[i].where);
        check(gap < 1e-7, name, "worst relative gap over the 4 triangles %.1g; exact L1 = %.6f %.6f %.6f", gap,
              exact[0], exact[1], exact[2]);
        for (j = 0; j < sizeof S / sizeof S[0]; j++)
            check_point(&s, P[i].where, dv(P[i].eye[0], P[i].eye[1], P[i].eye[2]), x, exact, &S[j], seed++);
    }
    /* precision: 4 sigma <= 1e-3 of the exact value (skipped in sanitizer runs, too slow there) */
    if (!(fast && *fast && strcmp(fast, "0"))) {
        static const int PS[] = {0, 3, 10, 12};   /* area, solid angle, MIS power (power + cosine), (solid angle + brdf) */
        dvec x = dv(P[1].x[0], P[1].x[1], P[1].x[2]);
        double exact[3];
        char where[160];
        exact_L1(&s, x, dv(0, 0, 1), exact);
        snprintf(where, sizeof where, "%s, to 1e-3", P[1].where);
        for (j = 0; j < sizeof PS / sizeof PS[0]; j++)
            check_point_at(&s, where, dv(P[1].eye[0], P[1].eye[1], P[1].eye[2]), x, exact, &S[PS[j]], seed++,
                           2.4e-4, 40000000, 1e-3);
    }
    scene_free(&s);
    return check_summary();
}
