/* brdf.c — the course's diffuse + Blinn BRDF, its sampling and pdf. */
#include "tracer/brdf.h"
#include "tracer/sampling.h"

const char *const BRDF_MODEL_NAMES[] = {"blinn", "diffuse", 0};

static vec3 half_vector(vec3 wo, vec3 wi) { return v3_normalize(v3_add(wo, wi)); }

vec3 brdf_eval(const material *m, vec3 wo, vec3 wi)
{
    vec3 f;
    if (wo.z <= 0.0f || wi.z <= 0.0f) return v3(0, 0, 0);
    f = v3_scale(m->Kd, INV_PI_F);
    if (!v3_is_zero(m->Ks)) {   /* no glossy work for a purely diffuse material */
        float cos_h = half_vector(wo, wi).z;
        float lobe = (m->Ns + 8.0f) / (8.0f * PI_F) * powf(cos_h, m->Ns);
        f = v3_madd(f, m->Ks, lobe);
    }
    return f;
}

float brdf_glossy_prob(const material *m)
{
    float d = v3_mean(m->Kd), s = v3_mean(m->Ks);
    return d + s > 0.0f ? s / (d + s) : 0.0f;
}

float blinn_pdf(vec3 wo, vec3 wi, float Ns)
{
    vec3 h = half_vector(wo, wi);
    float wo_h = v3_dot(wo, h);
    /* pdf(wi) = pdf(h) |dh/dwi| with |dh/dwi| = 1 / (4 wo.h) for a reflection */
    return wo_h > 0.0f ? pdf_cos_power(h, Ns) / (4.0f * wo_h) : 0.0f;
}

float brdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    float ps = brdf_glossy_prob(m), pdf = 0.0f;
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    if (ps < 1.0f) pdf += (1.0f - ps) * pdf_cosine_hemisphere(wi);
    if (ps > 0.0f) pdf += ps * blinn_pdf(wo, wi, m->Ns);
    return pdf;
}

static vec3 reflect(vec3 wo, vec3 h) { return v3_sub(v3_scale(h, 2.0f * v3_dot(wo, h)), wo); }

vec3 brdf_sample(const material *m, vec3 wo, float u_lobe, float u1, float u2, float *pdf)
{
    float ps = brdf_glossy_prob(m);
    vec3 wi = u_lobe < ps ? reflect(wo, sample_cos_power(u1, u2, m->Ns))
                          : sample_cosine_hemisphere(u1, u2);
    /* the pdf of a mixture sample is the mixture's pdf, whichever lobe produced it */
    *pdf = brdf_pdf(m, wo, wi);
    return wi;
}
