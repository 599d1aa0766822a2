/* integrator.c — the path tracer of the course, vertex by vertex, in the slides' notation:
 *   p          the current vertex (a `vertex`); wo the direction back toward the eye;
 *   s          a point on a light, chosen with pdf1(s) (a `light_sample`);
 *   q          the next vertex: where the ray from p, in a direction wi chosen with pdf2, hits;
 *   wi_world   a direction in world coordinates; wi_local the same in p's frame (cos theta = z);
 *   _area _sa  a density per unit area, per steradian (solid angle): pdf1_area (the light
 *              sample's pdf_area), pdf1_sa, pdf2_sa; sc the scene, opt the estimator's options.
 * The slides' L2 estimator, with pdf(s, q) = pdf1(s) x pdf2(q) and both pdfs per unit area,
 *   Le(s) f(s, q, p) G(q, s) f(q, p, o) G(p, q) / (pdf1(s) pdf2(q))     (o: the eye),
 * is computed one vertex at a time, walking from the eye: the first vertex plays p and finds q
 * with pdf2; then q becomes the current vertex, named p in turn, and samples s with pdf1. So the
 * slides' "s seen from q" is the code's "s seen from p" one step later. The path throughput `beta`
 * carries f G / pdf2(q) of the vertices walked so far, and at each vertex light sampling adds
 * beta x Le f G / pdf1(s). Directions are sampled per steradian; per unit area at q the density is
 * pdf2_area(q) = pdf2_sa cos(theta_q) / d^2, so in f G(p, q) / pdf2_area(q) the cos(theta_q) / d^2
 * cancels: beta *= f cos(theta_p) / pdf2_sa. Likewise pdf1_sa = pdf1_area d^2 / cos(theta_s):
 * Le f G(p, s) / pdf1_area = Le f cos(theta_p) / pdf1_sa.
 * MIS weighs the two ways of finding a light with both pdfs per steradian. */
#include "tracer/integrator.h"
#include "tracer/brdf.h"
#include "tracer/sampling.h"
#include "tracer/surface.h"
#include <assert.h>

const char *const DIR_STRATEGY_NAMES[] = {"uniform", "cosine", "brdf", 0};
const char *const DIRECT_STRATEGY_NAMES[] = {"light", "brdf", "mis-balance", "mis-power", 0};

/* A shading point: position, normals facing the incoming ray, local frame, material. With a shading
 * normal n (from the vn) the BRDF and its cosine live in n's frame, while the geometric normal ng
 * keeps deciding what is below the surface (no light comes through it, no path goes into it) and
 * where rays leave from. */
typedef struct {
    vec3 pos, n, ng, wo_local;
    int tri;                  /* its triangle */
    float scale;              /* triangle_scale of its triangle, for offset_ray_origin */
    frame frame;              /* n is its z axis */
    int shaded;               /* n is not ng */
    const material *mat;      /* the scene's material, or `own` when textures or --material change it here */
    material own;             /* (its name is not copied) */
} vertex;

/* *v = the vertex at hit h of a ray of direction dir. Written in place: a returned struct was
 * copied through the stack with wide loads that waited on the narrow stores before them (7% of
 * integrate's samples under perf record). */
static void make_vertex(vertex *v, const scene *sc, const integrator_opts *opt, const hit *h, vec3 dir)
{
    vec3 wo = v3_scale(dir, -1.0f / v3_length(dir));
    v->pos = scene_hit_point(sc, h);
    v->tri = h->tri;
    v->scale = scene_triangle_scale(sc, h->tri);
    v->ng = sc->Ng[h->tri];
    if (v3_dot(v->ng, wo) < 0.0f) v->ng = v3_scale(v->ng, -1.0f);   /* the BRDF is two-sided */
    v->n = opt->normals == NORMALS_SHADING ? surface_normal(sc, h, v->ng, wo) : v->ng;
    v->shaded = v->n.x != v->ng.x || v->n.y != v->ng.y || v->n.z != v->ng.z;
    v->frame = frame_from_normal(v->n);
    v->wo_local = frame_to_local(&v->frame, wo);
    v->mat = surface_material(&v->own, sc, opt->material, opt->filter, h);
}

static int uses_light_sampling(direct_strategy strategy) { return strategy != DIRECT_BRDF; }
static int uses_dir_sampling(direct_strategy strategy) { return strategy != DIRECT_LIGHT; }

/* MIS weight of a strategy of density pdf_this against the other of density pdf_other (both per
 * steradian); 1 without MIS. */
static float mis_weight(direct_strategy strategy, float pdf_this, float pdf_other)
{
    switch (strategy) {
    case DIRECT_MIS_BALANCE: return balance_heuristic(pdf_this, pdf_other);
    case DIRECT_MIS_POWER: return power_heuristic(pdf_this, pdf_other);
    default: return 1.0f;
    }
}

/* pdf2 per steradian of the --dir strategy at p, for the direction wi_local. */
static float dir_pdf2_sa(const integrator_opts *opt, const vertex *p, vec3 wi_local)
{
    switch (opt->dir) {
    case DIR_UNIFORM: return pdf_uniform_hemisphere(wi_local);
    case DIR_COSINE: return pdf_cosine_hemisphere(wi_local);
    default: return brdf_pdf(p->mat, p->wo_local, wi_local);
    }
}

/* The uniform numbers of a vertex for the light and the direction, drawn together as the path
 * reaches it. A Sobol number is a long chain of dependent hashes (sampler.c): drawn before the
 * shadow ray is traced, the direction's is ready when the continuation ray needs it instead of
 * stalling the path (--sampler sobol1: 5% less time on the Cornell boxes). The roulette's number
 * is drawn where it is used: a path that ends before never pays for it. */
typedef struct {
    double light_choice;        /* which emitter; where it fell in that emitter's share is the point's u1 */
    float light_u2;             /* the point s on it: its second coordinate */
    float lobe, dir1, dir2;     /* which BRDF lobe, the direction wi */
} vertex_numbers;

/* 1 if the --dir strategy at p chooses between two BRDF lobes. */
static int chooses_lobe(const integrator_opts *opt, const vertex *p)
{
    float ps = opt->dir == DIR_BRDF ? brdf_glossy_prob(p->mat) : 0.0f;
    return ps > 0.0f && ps < 1.0f;
}

/* The numbers *u of vertex p for light sampling (if light) and direction sampling (if dir). The
 * lobe's number is drawn only when there is a choice: with one lobe, 0 picks it. */
static void draw_numbers(const integrator_opts *opt, const vertex *p, sampler *smp, int light, int dir, vertex_numbers *u)
{
    if (light) u->light_choice = sampler_light(smp, &u->light_u2);
    if (dir) {
        u->lobe = chooses_lobe(opt, p) ? sampler_lobe(smp) : 0.0f;
        sampler_direction(smp, &u->dir1, &u->dir2);
    }
}

/* A direction wi_local at p chosen by the --dir strategy, its pdf2 per steradian in *pdf2_sa (0: the
 * BRDF lobe sent it below the surface). */
static vec3 sample_dir(const integrator_opts *opt, const vertex *p, const vertex_numbers *u, float *pdf2_sa)
{
    vec3 wi_local;
    switch (opt->dir) {
    case DIR_UNIFORM: wi_local = sample_uniform_hemisphere(u->dir1, u->dir2); *pdf2_sa = pdf_uniform_hemisphere(wi_local); break;
    case DIR_COSINE: wi_local = sample_cosine_hemisphere(u->dir1, u->dir2); *pdf2_sa = pdf_cosine_hemisphere(wi_local); break;
    default: return brdf_sample(p->mat, p->wo_local, u->lobe, u->dir1, u->dir2, pdf2_sa);
    }
    assert(*pdf2_sa > 0.0f);   /* the hemisphere warps never return z = 0, since u1 < 1 */
    return wi_local;
}

/* The shadow ray from just off p to just off s (no epsilon on t: the offsets keep both surfaces out),
 * or, when a triangle stands within that offset in front of s's emitter (a plate 0.5 mm under a lamp
 * at coordinates near 1000, where the offset is 1 mm), to s itself, blind to s's own triangle: the
 * plate then blocks, as it does for BRDF sampling. Found at load (scene.h, near_blocker): ending off
 * s spares the leaf of the emitter (5 % of CornellBox-Original's time). None is needed when
 * nothing can come between p's triangle and s's (a wall and the light of an empty box: visibility.h). */
static int visible(const scene *sc, const vertex *p, const light_sample *s, trace_stats *st)
{
    ray shadow;
    int tri = sc->lights.e[s->emitter].tri;
    if (sees_wholly(&sc->wholly_seen, p->tri, s->emitter)) {
        st->shadow_rays_spared++;
        return 1;
    }
    shadow.o = offset_ray_origin(p->pos, p->ng, p->scale);
    shadow.tmax = 1.0f;
    st->shadow_rays++;
    if (!sc->near_blocker || sc->near_blocker[s->emitter]) {
        shadow.d = v3_sub(s->pos, shadow.o);
        return !bvh_occluded_except(sc->accel, &shadow, tri);
    }
    shadow.d = v3_sub(offset_ray_origin(s->pos, s->n, scene_triangle_scale(sc, tri)), shadow.o);
    return !bvh_occluded(sc->accel, &shadow);
}

/* The shadow ray from just off p toward the sky in the direction wi_world: nothing in the way, to infinity. */
static int sky_visible(const scene *sc, const vertex *p, vec3 wi_world, trace_stats *st)
{
    ray shadow;
    shadow.o = offset_ray_origin(p->pos, p->ng, p->scale);
    shadow.d = wi_world;
    shadow.tmax = INFINITY;
    st->shadow_rays++;
    return !bvh_occluded(sc->accel, &shadow);
}

/* L_k by light sampling the sky at p: a direction s with pdf1_sa = P(sky) x the sky's pdf, then
 * L(s) f cos(theta_p) / pdf1_sa, MIS-weighted against direction sampling. u1 is what is left of the
 * light's choice number once the sky was chosen. */
static vec3 direct_from_sky(const scene *sc, const integrator_opts *opt, const vertex *p, double u1, float u2, trace_stats *st)
{
    vec3 L, wi_local, f, wi_world;
    float pdf_sky, pdf1_sa, cos_p, w_mis;
    wi_world = sky_sample(&sc->sky, u1, u2, &pdf_sky, &L);
    cos_p = v3_dot(p->n, wi_world);
    if (cos_p <= 0.0f || !(pdf_sky > 0.0f)) return v3(0, 0, 0);
    if (p->shaded && !(v3_dot(p->ng, wi_world) > 0.0f)) return v3(0, 0, 0);      /* below the surface */
    wi_local = frame_to_local(&p->frame, wi_world);
    f = brdf_eval(p->mat, p->wo_local, wi_local);
    if (v3_is_zero(f) || !sky_visible(sc, p, wi_world, st)) return v3(0, 0, 0);
    pdf1_sa = (float)sc->sky_prob * pdf_sky;
    w_mis = mis_weight(opt->direct, pdf1_sa, dir_pdf2_sa(opt, p, wi_local));
    return v3_scale(v3_mul(f, L), cos_p / pdf1_sa * w_mis);
}

/* L_k by light sampling at p: Le(s) f cos(theta_p) cos(theta_s) / d^2 / pdf1_area(s), which is
 * Le(s) f cos(theta_p) / pdf1_sa(s), MIS-weighted against direction sampling. The light's choice
 * number picks the sky below sky_prob, an emitter above (its pdf1 times emitter_prob). */
static vec3 direct_from_light(const scene *sc, const integrator_opts *opt, const vertex *p, const vertex_numbers *u, trace_stats *st)
{
    light_sample s;
    vec3 to_s, wi_world, wi_local, f;
    float dist2, dist, cos_p, cos_s, pdf1_sa, w_mis;
    double u0 = u->light_choice;
    if (sc->sky_prob > 0.0) {
        if (u0 < sc->sky_prob) return direct_from_sky(sc, opt, p, u0 / sc->sky_prob, u->light_u2, st);
        u0 = fmin((u0 - sc->sky_prob) / (1.0 - sc->sky_prob), 0x1.fffffffffffffp-1);
    }
    light_sample_point_joint(&sc->lights, opt->light, p->pos, p->n, u0, u->light_u2, &s);
    to_s = v3_sub(s.pos, p->pos);
    dist2 = v3_dot(to_s, to_s);
    dist = sqrtf(dist2);
    wi_world = v3_scale(to_s, 1.0f / dist);
    cos_p = v3_dot(p->n, wi_world);
    cos_s = -v3_dot(s.n, wi_world);
    if (cos_p <= 0.0f || cos_s <= 0.0f || !(dist2 > 0.0f)) return v3(0, 0, 0);   /* no shadow ray: no light */
    if (p->shaded && !(v3_dot(p->ng, wi_world) > 0.0f)) return v3(0, 0, 0);      /* s is below the surface */
    wi_local = frame_to_local(&p->frame, wi_world);
    f = brdf_eval(p->mat, p->wo_local, wi_local);
    if (v3_is_zero(f) || !visible(sc, p, &s, st)) return v3(0, 0, 0);
    pdf1_sa = pdf_area_to_solid_angle(s.pdf_area, dist2, cos_s) * sc->emitter_prob;
    w_mis = mis_weight(opt->direct, pdf1_sa, dir_pdf2_sa(opt, p, wi_local));
    return v3_scale(v3_mul(f, surface_Le_at(sc, opt->filter, &s)), cos_p / pdf1_sa * w_mis);
}

/* pdf1 per steradian with which light sampling at p would have chosen the point hit at q. */
static float light_pdf1_sa(const scene *sc, const integrator_opts *opt, const vertex *p, const hit *q, const ray *ray_pq)
{
    int i = sc->lights.emitter_of_tri[q->tri];
    float dist2 = q->t * q->t * v3_dot(ray_pq->d, ray_pq->d);
    float cos_s = -v3_dot(sc->Ng[q->tri], ray_pq->d) / v3_length(ray_pq->d);
    assert(i >= 0);   /* q emits light, so its triangle is one of the emitters */
    return pdf_area_to_solid_angle(light_pdf_area(&sc->lights, opt->light, i, p->pos, p->n, scene_hit_point(sc, q)), dist2, cos_s) * sc->emitter_prob;
}

/* L_k by direction sampling: the ray from p, of density pdf2_sa, hit q; Le(q) if q emits toward p,
 * MIS-weighted against light sampling. */
static vec3 direct_from_dir(const scene *sc, const integrator_opts *opt, const vertex *p, const hit *q, const ray *ray_pq, float pdf2_sa)
{
    vec3 Le = surface_emitted(sc, opt->filter, q, ray_pq->d);
    float w_mis = 1.0f;
    if (v3_is_zero(Le)) return Le;
    if (uses_light_sampling(opt->direct)) {
        float pdf1_sa = light_pdf1_sa(sc, opt, p, q, ray_pq);
        w_mis = mis_weight(opt->direct, pdf2_sa, pdf1_sa);
    }
    return v3_scale(Le, w_mis);
}

/* L_k by direction sampling: the ray from p, of density pdf2_sa, left the scene: the sky's L, MIS-weighted
 * against light sampling of the sky. */
static vec3 sky_from_dir(const scene *sc, const integrator_opts *opt, const ray *ray_pq, float pdf2_sa)
{
    vec3 L = sky_radiance(&sc->sky, ray_pq->d);
    float w_mis = 1.0f;
    if (uses_light_sampling(opt->direct)) w_mis = mis_weight(opt->direct, pdf2_sa, (float)sc->sky_prob * sky_pdf_sa(&sc->sky, ray_pq->d));
    return v3_scale(L, w_mis);
}

/* *r = the ray from just off p in the direction wi_local, toward the next vertex q. Written field by
 * field: a returned struct was stored with a 16-byte write across o and d.x, and the traversal's
 * 8-byte read of d.x, d.y straddled two stores, which the CPU cannot forward (a stall per ray). */
static void continuation_ray(ray *r, const vertex *p, vec3 wi_local)
{
    r->o = offset_ray_origin(p->pos, p->ng, p->scale);
    r->d = frame_to_world(&p->frame, wi_local);
    r->tmax = INFINITY;
}

/* "et on arrête quand ?": Russian roulette. The path goes on with probability p_survive, which
 * follows its throughput, p_survive = max(beta) / below, and a surviving path's throughput is
 * divided by p_survive, so that E[beta] is unchanged and no L_k is biased; a survivor's throughput
 * is then `below` at most, and the clamp at 0.05 bounds the weight 1 / p_survive by 20. With below
 * = 1 (pbrt's rule) a path that has lost half of its throughput has one chance in two to go on;
 * below = 1/3 keeps it for sure until its throughput falls under 1/3: more bounces, less
 * noise from the roulette itself, which is what costs most once the samples are stratified. The cap
 * at RR_SURVIVE_MAX (Mitsuba 3 caps it at 0.95 too), from bounce RR_CAP_FROM on, ends every path
 * after 1 / (1 - 0.95) = 20 more bounces on average whatever the materials: with Kd >= 1 the
 * throughput never falls, and a survival probability of 1 ran every path to the bounce cap (0.8 s
 * per sample in a closed box). Before RR_CAP_FROM a path whose throughput is at least `below` goes
 * on for sure, as in Cycles: in an open box with Kd = 1 walls (McGuire's CornellBox-Empty-White)
 * the cap's 5 % coin at every bounce was most of the noise (docs/performance.md, Cycles section).
 * Returns 0 when the path stops. */
#define RR_SURVIVE_MAX 0.95f
#define RR_CAP_FROM 32
static int survives_roulette(vec3 *beta, sampler *smp, int k, float below)
{
    vec3 before = *beta;
    float cap = k < RR_CAP_FROM ? 1.0f : RR_SURVIVE_MAX;
    float p_survive = fminf(cap, fmaxf(0.05f, v3_max_comp(before) / below));
    assert(below > 0.0f);
    /* a sure survivor needs no number: a Sobol number costs a chain of hashes (sampler.c), and
     * skipping it shifts no other use's dimension */
    if (p_survive >= 1.0f) return 1;
    if (sampler_roulette(smp) >= p_survive) return 0;
    *beta = v3_scale(before, 1.0f / p_survive);
    /* below the cap, p_survive is >= every channel of beta / below, which thus ends <= below (at
     * the cap, 1 before bounce RR_CAP_FROM and 0.95 after, materials with Kd + Ks > 1 may make beta
     * grow without bound: their image has no limit) */
    assert(p_survive == cap || p_survive == 0.05f || v3_max_comp(*beta) <= below * 1.000001f);
    return 1;
}

/* The radiance of one camera ray: L = the sum in path order, and with Lk each L_k on its own. */
typedef struct {
    vec3 L, *Lk;
    int bmin, bmax;
} radiance_sum;

static radiance_sum radiance_start(const integrator_opts *opt, vec3 *Lk)
{
    radiance_sum sum;
    int k;
    assert(0 <= opt->bmin && opt->bmin <= opt->bmax);
    sum.L = v3(0, 0, 0);
    sum.Lk = Lk;
    sum.bmin = opt->bmin, sum.bmax = opt->bmax;
    for (k = 0; Lk && k <= opt->bmax; k++) Lk[k] = v3(0, 0, 0);
    return sum;
}

/* Adds c to L_k. L is summed in path order whether or not Lk is kept, so that --split leaves the
 * total image bit for bit the same. */
static void add_Lk(radiance_sum *sum, int k, vec3 c)
{
    assert(sum->bmin <= k && k <= sum->bmax);
    sum->L = v3_add(sum->L, c);
    if (sum->Lk) sum->Lk[k] = v3_add(sum->Lk[k], c);
}

vec3 integrate(const scene *sc, const integrator_opts *opt, const ray *camera, sampler *smp, vec3 *Lk, trace_stats *st)
{
    radiance_sum sum = radiance_start(opt, Lk);
    ray ray_pq = *camera;     /* from p (first the eye) toward the next vertex q */
    hit q;
    vec3 beta = v3(1, 1, 1);  /* the path throughput: the product of f G / pdf2(q) over the vertices before p */
    /* the hard bounce cap: with the roulette on (p_survive <= 0.95 from bounce 32) a path reaches it with
     * probability below 0.95^(BOUNCES_CAP - RR_CAP_FROM), never in practice; with --rr off and Kd >= 1
     * it is what ends the path. The paths it cuts are counted: the stats line shows them. */
    int k, has_lights = scene_has_light(sc), kmax = opt->bmax < BOUNCES_CAP ? opt->bmax : BOUNCES_CAP;

    st->camera_rays++;
    if (!bvh_intersect(sc->accel, &ray_pq, &q)) {                                     /* L0: the sky */
        if (opt->bmin == 0) add_Lk(&sum, 0, sky_radiance(&sc->sky, ray_pq.d));
        return sum.L;
    }
    if (opt->bmin == 0) add_Lk(&sum, 0, surface_emitted(sc, opt->filter, &q, ray_pq.d));                    /* L0 */

    for (k = 1; k <= kmax; k++) {
        vertex p;
        vec3 wi_local, f;
        float pdf2_sa, cos_p;
        int adds_Lk = k >= opt->bmin && has_lights, samples_light = adds_Lk && uses_light_sampling(opt->direct);
        /* the last bounce needs a continuation ray only to find emitters by direction sampling */
        int continues = k < kmax || uses_dir_sampling(opt->direct);
        vertex_numbers u;
        make_vertex(&p, sc, opt, &q, ray_pq.d);              /* the last q is the new p */
        sampler_vertex(smp, k);                         /* the numbers of vertex k */
        draw_numbers(opt, &p, smp, samples_light, continues, &u);

        /* L_k by light sampling: a point s on a light, with pdf1(s) */
        if (samples_light) add_Lk(&sum, k, v3_mul(beta, direct_from_light(sc, opt, &p, &u, st)));
        if (!continues) break;

        /* the next vertex q, in a direction chosen with pdf2: beta *= f G(p, q) / pdf2_area(q) */
        wi_local = sample_dir(opt, &p, &u, &pdf2_sa);
        if (!(pdf2_sa > 0.0f)) break;
        continuation_ray(&ray_pq, &p, wi_local);
        if (p.shaded && !(v3_dot(ray_pq.d, p.ng) > 0.0f)) break;       /* into the surface: no light comes from there */
        f = brdf_eval(p.mat, p.wo_local, wi_local);
        cos_p = wi_local.z;
        beta = v3_mul(beta, v3_scale(f, cos_p / pdf2_sa));
        if (v3_is_zero(beta)) break;                                    /* no light can follow */
        st->continuation_rays++;
        if (!bvh_intersect(sc->accel, &ray_pq, &q)) {   /* L_k by direction sampling: the sky */
            if (adds_Lk && uses_dir_sampling(opt->direct) && sc->sky.w) add_Lk(&sum, k, v3_mul(beta, sky_from_dir(sc, opt, &ray_pq, pdf2_sa)));
            break;
        }

        /* L_k by direction sampling: q is on a light */
        if (adds_Lk && uses_dir_sampling(opt->direct))
            add_Lk(&sum, k, v3_mul(beta, direct_from_dir(sc, opt, &p, &q, &ray_pq, pdf2_sa)));

        /* "et on arrête quand ?" */
        if (opt->rr_depth >= 0 && k >= opt->rr_depth && k < kmax && !survives_roulette(&beta, smp, k, opt->rr_below)) break;
    }
    if (k >= kmax && kmax < opt->bmax) st->paths_cut++;   /* it reached the cap: its next bounces are lost */
    return sum.L;
}
