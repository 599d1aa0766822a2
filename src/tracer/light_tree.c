/* light_tree.c — the light tree of light_tree.h: its build (bounds, normal cones, powers, median
 * splits) and the descent from p, whose probabilities the pdf recomputes along an emitter's path. */
#include "tracer/light_tree.h"
#include "math/dvec.h"
#include <assert.h>
#include <float.h>
#include <stdlib.h>

/* cos(theta') below -MARGIN: no emitter of the node faces p. Between -MARGIN and MARGIN the float
 * rounding of the cone and the bounds could hide an emitter that just faces p: it keeps a small
 * importance instead of 0 (wasted samples, never a bias). */
#define CONE_MARGIN 1e-3f

/* ---------- importance ---------- */

/* cos of theta - theta_b, or 1 when theta <= theta_b: the smallest angle between a direction
 * within theta_b of one at angle theta (of cosine cos_t) and the axis theta is measured from. */
static inline float cos_minus(float cos_t, float cos_b, float sin_b)
{
    float sin_t;
    if (cos_t >= cos_b) return 1.0f;
    sin_t = sqrtf(1.0f - cos_t * cos_t > 0.0f ? 1.0f - cos_t * cos_t : 0.0f);
    return cos_t * cos_b + sin_t * sin_b;
}

/* (inline here: the descent calls it twice per level, the hottest code of a light sample) */
static inline float importance(const light_node *nd, vec3 p, vec3 n)
{
    vec3 v = v3_sub(p, nd->c);
    float d2 = v3_dot(v, v), inv_d, cos_w, sin_w, cos_x, sin_x, sin_b, cos_b, cos_i;
    /* p in the bounding sphere: any emitter may face it, and 1/d^2 is clamped at the sphere */
    if (d2 <= nd->r * nd->r) return nd->r > 0.0f ? nd->power / (nd->r * nd->r) : nd->power;
    inv_d = 1.0f / sqrtf(d2);
    cos_x = 1.0f, sin_x = 0.0f;
    cos_w = v3_dot(nd->axis, v) * inv_d;   /* theta_w: from the cone's axis to the direction c -> p */
    if (cos_w < nd->cos_o) {   /* theta_w - theta_o: the smallest angle between a normal of the cone and c -> p */
        sin_w = sqrtf(1.0f - cos_w * cos_w > 0.0f ? 1.0f - cos_w * cos_w : 0.0f);
        cos_x = cos_w * nd->cos_o + sin_w * nd->sin_o, sin_x = sin_w * nd->cos_o - cos_w * nd->sin_o;
    }
    /* minus theta_b, the half-angle of the sphere seen from p: s -> p is within theta_b of c -> p */
    sin_b = nd->r * inv_d, cos_b = sqrtf(1.0f - sin_b * sin_b);
    if (cos_x < cos_b) cos_x = cos_x * cos_b + sin_x * sin_b;
    else cos_x = 1.0f;
    if (cos_x < -CONE_MARGIN) return 0.0f;   /* theta' > pi/2: every emitter below shows p its back */
    /* theta_i, from n to p -> s, is at least the angle from n to p -> c minus theta_b: past pi/2
     * every emitter below is under p's surface (n = 0: no normal, no bound) */
    cos_i = 1.0f;
    if (v3_dot(n, n) > 0.0f && (cos_i = cos_minus(-v3_dot(n, v) * inv_d, cos_b, sin_b)) < -CONE_MARGIN) return 0.0f;
    return nd->power * (cos_x > CONE_MARGIN ? cos_x : CONE_MARGIN) * (cos_i > CONE_MARGIN ? cos_i : CONE_MARGIN) / d2;
}

float light_node_importance(const light_node *nd, vec3 p, vec3 n) { return importance(nd, p, n); }

double light_tree_first_prob(const light_tree *t, int k, vec3 p, vec3 n)
{
    const light_node *nd = &t->node[k];
    double i1 = importance(nd + 1, p, n), i2 = importance(&t->node[nd->right], p, n);
    /* neither child can light p: any choice gives 0, but it must have a probability */
    return i1 + i2 > 0.0 ? i1 / (i1 + i2) : 0.5;
}

/* ---------- the descent and its probability ---------- */

int light_tree_pick(const light_tree *t, vec3 p, vec3 n, double *u, double *prob)
{
    double pr = 1.0;
    int k = 0;
    while (t->node[k].right >= 0) {
        double q = light_tree_first_prob(t, k, p, n);
        if (*u < q) *u = *u / q, pr *= q, k = k + 1;
        else *u = (*u - q) / (1.0 - q), pr *= 1.0 - q, k = t->node[k].right;
        if (!(*u < 1.0)) *u = 1.0 - DBL_EPSILON / 2;   /* rounded up to 1 */
    }
    *prob = pr;
    return t->node[k].emitter;
}

double light_tree_prob(const light_tree *t, int i, vec3 p, vec3 n)
{
    double pr = 1.0;
    int k = 0, level;
    for (level = 0; level < t->depth[i]; level++) {
        double q = light_tree_first_prob(t, k, p, n);
        if (t->path[i] >> level & 1u) pr *= 1.0 - q, k = t->node[k].right;
        else pr *= q, k = k + 1;
    }
    assert(t->node[k].right < 0 && t->node[k].emitter == i);
    return pr;
}

/* ---------- the build ---------- */

typedef struct {
    light_tree *t;
    const light_bounds *e;
    int *order;       /* emitter indices, reordered by the splits */
    vec3 *centroid;   /* of each emitter's box */
    int next;         /* the next free node */
} builder;

/* The node's sphere, cone and power from its emitters order[lo..hi-1] (in double: sums of many) */
static void bound_node(const builder *b, int lo, int hi, light_node *nd)
{
    vec3 bmin = v3(FLT_MAX, FLT_MAX, FLT_MAX), bmax = v3(-FLT_MAX, -FLT_MAX, -FLT_MAX), h;
    dvec sum = dv(0, 0, 0), axis;
    double power = 0.0, cos_o = 1.0, len;
    int j;
    for (j = lo; j < hi; j++) {
        const light_bounds *e = &b->e[b->order[j]];
        bmin = v3_min(bmin, e->lo), bmax = v3_max(bmax, e->hi);
        sum = dv_lin(sum, 1.0, dv_of(e->n), 1.0);
        power += e->power;
    }
    h = v3_scale(v3_sub(bmax, bmin), 0.5f);
    nd->c = v3_scale(v3_add(bmin, bmax), 0.5f);
    nd->r = v3_length(h) * (1.0f + 1e-6f);   /* the rounding of c and of r must not shrink it */
    nd->power = (float)power;
    len = sqrt(dv_dot(sum, sum));
    /* the cone's axis: the mean normal; its half-angle: the widest normal from it */
    axis = len > 1e-6 * (hi - lo) ? dv_normalize(sum) : dv(0, 0, 1);
    if (len <= 1e-6 * (hi - lo)) cos_o = -1.0;   /* normals that cancel out: any direction */
    for (j = lo; j < hi && cos_o > -1.0; j++) cos_o = fmin(cos_o, dv_dot(axis, dv_of(b->e[b->order[j]].n)));
    nd->axis = fv_of(axis);
    nd->cos_o = (float)cos_o;
    nd->sin_o = (float)sqrt(fmax(0.0, 1.0 - cos_o * cos_o));
}

static float key(const builder *b, int j, int axis) { return v3_comp(b->centroid[b->order[j]], axis); }

/* Puts in order[nth] the emitter of the nth centroid along axis, smaller ones before it and larger
 * ones after (quickselect, Hoare's partition: O(hi - lo) on average, even with equal keys). */
static void select_nth(builder *b, int lo, int hi, int nth, int axis)
{
    while (hi - lo > 1) {
        float pivot = key(b, lo + (hi - lo) / 2, axis);
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (key(b, i, axis) < pivot) i++;
            while (key(b, j, axis) > pivot) j--;
            if (i <= j) {
                int tmp = b->order[i];
                b->order[i++] = b->order[j], b->order[j--] = tmp;
            }
        }
        if (nth <= j) hi = j + 1;
        else if (nth >= i) lo = i;
        else return;
    }
}

/* The axis along which the centroids of order[lo..hi-1] spread most */
static int widest_axis(const builder *b, int lo, int hi)
{
    vec3 cmin = b->centroid[b->order[lo]], cmax = cmin, ext;
    int j;
    for (j = lo + 1; j < hi; j++) cmin = v3_min(cmin, b->centroid[b->order[j]]), cmax = v3_max(cmax, b->centroid[b->order[j]]);
    ext = v3_sub(cmax, cmin);
    return ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
}

/* The subtree of order[lo..hi-1], reached from the root by `path` in `depth` steps */
static void build_node(builder *b, int lo, int hi, uint64_t path, int depth)
{
    light_node *nd = &b->t->node[b->next++];
    int mid = lo + (hi - lo) / 2;
    bound_node(b, lo, hi, nd);
    nd->emitter = -1;
    if (hi - lo == 1) {
        nd->right = -1, nd->emitter = b->order[lo];
        b->t->path[nd->emitter] = path, b->t->depth[nd->emitter] = (unsigned char)depth;
        return;
    }
    select_nth(b, lo, hi, mid, widest_axis(b, lo, hi));
    build_node(b, lo, mid, path, depth + 1);
    nd->right = b->next;
    build_node(b, mid, hi, path | (uint64_t)1 << depth, depth + 1);
}

int light_tree_build(light_tree *t, const light_bounds *e, int n)
{
    builder b;
    int i, ok;
    assert(n > 0);
    t->nnodes = 2 * n - 1;
    t->node = malloc(sizeof(light_node) * (size_t)t->nnodes);
    t->path = malloc(sizeof(uint64_t) * (size_t)n);
    t->depth = malloc((size_t)n);
    b.order = malloc(sizeof(int) * (size_t)n);
    b.centroid = malloc(sizeof(vec3) * (size_t)n);
    ok = t->node && t->path && t->depth && b.order && b.centroid;
    if (ok) {
        b.t = t, b.e = e, b.next = 0;
        for (i = 0; i < n; i++) {
            b.order[i] = i;
            b.centroid[i] = v3_scale(v3_add(e[i].lo, e[i].hi), 0.5f);
        }
        build_node(&b, 0, n, 0, 0);   /* median splits: depth <= ceil(log2 n) <= 31 < 64 path bits */
    }
    free(b.order), free(b.centroid);
    return !ok;
}

void light_tree_free(light_tree *t)
{
    free(t->node), free(t->path), free(t->depth);
    t->node = NULL, t->path = NULL, t->depth = NULL;
}
