/* light.c — emitters and the choice of a point s on them. */
#include "light.h"
#include "sampling.h"
#include <stdlib.h>

static float luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* Weight of emitter i in the discrete choice of each strategy (before normalisation). */
static float choice_weight(const emitter *e, light_strategy st)
{
    switch (st) {
    case LIGHT_AREA: return e->area;
    case LIGHT_TRIANGLE: return 1.0f;
    default: return e->area * fmaxf(luminance(e->Le), 0.0f);
    }
}

static int build_cdf(light_set *ls, light_strategy st)
{
    double sum = 0.0, acc = 0.0;
    int i;
    ls->cdf[st] = malloc(sizeof(double) * (size_t)ls->n);
    if (!ls->cdf[st]) return 1;
    for (i = 0; i < ls->n; i++) sum += choice_weight(&ls->e[i], st);
    for (i = 0; i < ls->n; i++) {
        acc += choice_weight(&ls->e[i], st);
        ls->cdf[st][i] = sum > 0.0 ? acc / sum : (double)(i + 1) / ls->n;
    }
    ls->cdf[st][ls->n - 1] = 1.0;
    return 0;
}

int light_build(light_set *ls, const mesh *m, const vec3 *Ng, const float *area)
{
    double total_area = 0.0;   /* a float sum of 1e5 small areas drifts by 1e-4 or more */
    int i, st;
    ls->n = 0;
    ls->total_area = 0.0f;
    ls->e = malloc(sizeof(emitter) * (size_t)(m->ntris > 0 ? m->ntris : 1));
    ls->emitter_of_tri = malloc(sizeof(int) * (size_t)(m->ntris > 0 ? m->ntris : 1));
    for (st = 0; st < LIGHT_NSTRATEGIES; st++) ls->cdf[st] = NULL;
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
    for (st = 0; st < LIGHT_NSTRATEGIES; st++)
        if (build_cdf(ls, (light_strategy)st)) return 1;
    return 0;
}

void light_free(light_set *ls)
{
    int st;
    free(ls->e);
    free(ls->emitter_of_tri);
    for (st = 0; st < LIGHT_NSTRATEGIES; st++) free(ls->cdf[st]);
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

static float choice_prob(const light_set *ls, light_strategy st, int i)
{
    return (float)(ls->cdf[st][i] - (i > 0 ? ls->cdf[st][i - 1] : 0.0));
}

float light_pdf_area(const light_set *ls, light_strategy st, int i)
{
    /* the area strategy is exactly 1/A; computing it from the cdf would add rounding */
    if (st == LIGHT_AREA) return 1.0f / ls->total_area;
    return choice_prob(ls, st, i) / ls->e[i].area;
}

void light_sample_point(const light_set *ls, light_strategy st, double u0, float u1, float u2, light_sample *out)
{
    int i = pick(ls->cdf[st], ls->n, u0);
    const emitter *e = &ls->e[i];
    float b1, b2;
    sample_uniform_triangle(u1, u2, &b1, &b2);
    out->p = v3_add(e->a, v3_add(v3_scale(e->e1, b1), v3_scale(e->e2, b2)));
    out->n = e->n;
    out->Le = e->Le;
    out->emitter = i;
    out->pdf_area = light_pdf_area(ls, st, i);
}

const char *light_strategy_name(light_strategy st)
{
    static const char *names[] = {"area", "triangle", "power"};
    return names[st];
}
