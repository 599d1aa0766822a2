/* integrator.c — the path tracer of the course, vertex by vertex.
 * Notation of the slides: p is the current vertex, wo the direction back toward the eye, s a point
 * on a light chosen with pdf1(s), q the next vertex found in a direction chosen with pdf2; the path
 * throughput `beta` carries f cos / pdf2 of the vertices before p, so that at vertex k the estimate
 * of L_k is beta * f(p) * Le * G / pdf(s) — the slides' L2 estimator with pdf(s, q) = pdf1(s) pdf2(q). */
#include "tracer/integrator.h"
#include "tracer/brdf.h"
#include "tracer/sampling.h"

const char *const DIR_STRATEGY_NAMES[] = {"uniform", "cosine", "brdf", 0};
const char *const DIRECT_STRATEGY_NAMES[] = {"light", "brdf", "mis-balance", "mis-power", 0};

/* A shading point: position, normal facing the incoming ray, local frame, material. */
typedef struct {
    vec3 p, n, wo_local;
    float scale;              /* triangle_scale of its triangle, for offset_ray_origin */
    frame f;
    const material *mat;
} vertex;

static vertex make_vertex(const scene *s, const hit *h, vec3 dir)
{
    vertex v;
    vec3 wo = v3_scale(dir, -1.0f / v3_length(dir));
    v.p = scene_hit_point(s, h);
    v.scale = scene_triangle_scale(s, h->tri);
    v.n = s->Ng[h->tri];
    if (v3_dot(v.n, wo) < 0.0f) v.n = v3_scale(v.n, -1.0f);   /* the BRDF is two-sided */
    v.f = frame_from_normal(v.n);
    v.wo_local = frame_to_local(&v.f, wo);
    v.mat = &s->m.mats[s->m.tri_mat[h->tri]];
    return v;
}

/* Le seen along dir at the hit: emission is one-sided, on the front face only. */
static vec3 emitted(const scene *s, const hit *h, vec3 dir)
{
    vec3 Ke = s->m.mats[s->m.tri_mat[h->tri]].Ke;
    return v3_dot(s->Ng[h->tri], dir) < 0.0f ? Ke : v3(0, 0, 0);
}

static int uses_light_sampling(direct_strategy d) { return d != DIRECT_BRDF; }
static int uses_dir_sampling(direct_strategy d) { return d != DIRECT_LIGHT; }

/* MIS weight of a strategy of density pf against the other of density pg (same measure). */
static float mis_weight(direct_strategy d, float pf, float pg)
{
    switch (d) {
    case DIRECT_MIS_BALANCE: return balance_heuristic(pf, pg);
    case DIRECT_MIS_POWER: return power_heuristic(pf, pg);
    default: return 1.0f;
    }
}

/* pdf2 of the direction strategy, per steradian, for wi in the local frame of v. */
static float pdf_dir(const integrator_opts *o, const vertex *v, vec3 wi)
{
    switch (o->dir) {
    case DIR_UNIFORM: return pdf_uniform_hemisphere(wi);
    case DIR_COSINE: return pdf_cosine_hemisphere(wi);
    default: return brdf_pdf(v->mat, v->wo_local, wi);
    }
}

static vec3 sample_dir(const integrator_opts *o, const vertex *v, pcg32 *rng, float *pdf)
{
    float u0 = pcg32_float(rng), u1 = pcg32_float(rng), u2 = pcg32_float(rng);
    vec3 wi;
    switch (o->dir) {
    case DIR_UNIFORM: wi = sample_uniform_hemisphere(u1, u2); *pdf = pdf_uniform_hemisphere(wi); break;
    case DIR_COSINE: wi = sample_cosine_hemisphere(u1, u2); *pdf = pdf_cosine_hemisphere(wi); break;
    default: wi = brdf_sample(v->mat, v->wo_local, u0, u1, u2, pdf); break;
    }
    return wi;
}

/* L_k by light sampling: Le(s) f(p) cos(theta_p) cos(theta_s) / d^2 / pdf1(s), MIS-weighted. */
static vec3 direct_from_light(const scene *s, const integrator_opts *o, const vertex *v, pcg32 *rng, trace_stats *st)
{
    light_sample ls;
    vec3 d, wi, f;
    float dist2, dist, cos_p, cos_s, pdf_light, w;
    ray shadow;
    double u0 = pcg32_double(rng);
    float u1 = pcg32_float(rng), u2 = pcg32_float(rng);
    light_sample_point(&s->lights, o->light, v->p, u0, u1, u2, &ls);
    d = v3_sub(ls.p, v->p);
    dist2 = v3_dot(d, d);
    dist = sqrtf(dist2);
    wi = v3_scale(d, 1.0f / dist);
    cos_p = v3_dot(v->n, wi);
    cos_s = -v3_dot(ls.n, wi);
    if (cos_p <= 0.0f || cos_s <= 0.0f || !(dist2 > 0.0f)) return v3(0, 0, 0);   /* no shadow ray: no light */
    f = brdf_eval(v->mat, v->wo_local, frame_to_local(&v->f, wi));
    if (v3_is_zero(f)) return v3(0, 0, 0);
    /* from just off p to just off s: no epsilon on t, the offsets keep both surfaces out */
    shadow.o = offset_ray_origin(v->p, v->n, v->scale);
    shadow.d = v3_sub(offset_ray_origin(ls.p, ls.n, scene_triangle_scale(s, s->lights.e[ls.emitter].tri)), shadow.o);
    shadow.tmax = 1.0f;
    st->shadow_rays++;
    if (bvh_occluded(s->accel, &shadow)) return v3(0, 0, 0);
    pdf_light = pdf_area_to_solid_angle(ls.pdf_area, dist2, cos_s);
    w = mis_weight(o->direct, pdf_light, pdf_dir(o, v, frame_to_local(&v->f, wi)));
    return v3_scale(v3_mul(f, ls.Le), cos_p / pdf_light * w);
}

/* L_k by direction sampling: the continuation ray from p (vertex v) hit an emitter at q (hit h). */
static vec3 direct_from_dir(const scene *s, const integrator_opts *o, const vertex *v, const hit *h, const ray *r, float pdf2)
{
    vec3 Le = emitted(s, h, r->d);
    float w = 1.0f;
    if (v3_is_zero(Le)) return Le;
    if (uses_light_sampling(o->direct)) {
        int i = s->lights.emitter_of_tri[h->tri];
        float dist2 = h->t * h->t * v3_dot(r->d, r->d);
        float cos_s = -v3_dot(s->Ng[h->tri], r->d) / v3_length(r->d);
        float pdf_light = pdf_area_to_solid_angle(light_pdf_area(&s->lights, o->light, i, v->p, scene_hit_point(s, h)), dist2, cos_s);
        w = mis_weight(o->direct, pdf2, pdf_light);
    }
    return v3_scale(Le, w);
}

/* L[0] is the total, summed in path order whether or not bounces are split, so that --split
 * leaves the total image bit for bit the same; L[1 + k - bmin] is L_k alone. */
static void add(vec3 *L, const integrator_opts *o, int k, vec3 c)
{
    L[0] = v3_add(L[0], c);
    if (o->split) L[1 + k - o->bmin] = v3_add(L[1 + k - o->bmin], c);
}

void integrate(const scene *s, const integrator_opts *o, const ray *camera, pcg32 *rng, vec3 *L, trace_stats *st)
{
    ray r = *camera;
    hit h;
    vec3 beta = v3(1, 1, 1);
    int k, lights = s->lights.n > 0;

    st->camera_rays++;
    if (!bvh_intersect(s->accel, &r, &h)) return;
    if (o->bmin == 0) add(L, o, 0, emitted(s, &h, r.d));                /* L0 */

    for (k = 1; k <= o->bmax; k++) {
        vertex v = make_vertex(s, &h, r.d);
        vec3 wi, f;
        float pdf2, cos_p;

        /* L_k, light sampling: choose s on a light */
        if (k >= o->bmin && lights && uses_light_sampling(o->direct))
            add(L, o, k, v3_mul(beta, direct_from_light(s, o, &v, rng, st)));

        /* the last bounce needs a continuation ray only to find emitters by direction sampling */
        if (k == o->bmax && !uses_dir_sampling(o->direct)) break;

        /* choose the next vertex q in a direction with pdf2; then beta *= f G(p,q) / pdf2(q),
         * which is f cos(theta_p) / pdf2(w): the cos(theta_q) / d^2 of G and of the area pdf cancel */
        wi = sample_dir(o, &v, rng, &pdf2);
        if (!(pdf2 > 0.0f)) break;
        f = brdf_eval(v.mat, v.wo_local, wi);
        cos_p = wi.z;
        beta = v3_mul(beta, v3_scale(f, cos_p / pdf2));
        if (v3_is_zero(beta)) break;                                    /* no light can follow */
        r.o = offset_ray_origin(v.p, v.n, v.scale);
        r.d = frame_to_world(&v.f, wi);
        r.tmax = INFINITY;
        st->continuation_rays++;
        if (!bvh_intersect(s->accel, &r, &h)) break;

        /* L_k, direction sampling: q is on a light */
        if (k >= o->bmin && lights && uses_dir_sampling(o->direct))
            add(L, o, k, v3_mul(beta, direct_from_dir(s, o, &v, &h, &r, pdf2)));

        /* "et on arrete quand ?": Russian roulette, survival in proportion to the throughput */
        if (o->rr_depth >= 0 && k >= o->rr_depth && k < o->bmax) {
            float q = fminf(1.0f, fmaxf(0.05f, v3_max_comp(beta)));
            if (pcg32_float(rng) >= q) break;
            beta = v3_scale(beta, 1.0f / q);
        }
    }
}
