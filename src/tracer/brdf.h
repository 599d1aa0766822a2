/* brdf.h — the course's BRDF, in the local frame where the normal is +z (cos theta = z):
 *   f(wo, wi) = Kd/pi + Ks (Ns+8)/(8 pi) cos^Ns(theta_h),  theta_h between n and h = (wo+wi)/|wo+wi|.
 * Both directions point away from the surface; f = 0 unless both are above it. */
#ifndef PATHLAB_BRDF_H
#define PATHLAB_BRDF_H
#include "scene/mesh.h"

/* --material: the course's blinn (Kd/pi + the Ks lobe, the default) or gKit's Monte Carlo tutorials'
 * diffuse (Kd/pi alone: Ks is ignored). docs/gkit.md. */
typedef enum { BRDF_BLINN, BRDF_DIFFUSE } brdf_model;
extern const char *const BRDF_MODEL_NAMES[];   /* in enum order, NULL-terminated */

/* f(wo, wi) per channel, per steradian. */
vec3 brdf_eval(const material *m, vec3 wo, vec3 wi);

/* Probability of choosing the glossy lobe when sampling the BRDF: mean(Ks) / (mean(Kd) + mean(Ks)). */
float brdf_glossy_prob(const material *m);

/* Samples wi from the mixture: cosine lobe for Kd, Blinn lobe for Ks (half vector with density
 * (Ns+1)/(2 pi) cos^Ns(theta_h), reflected about it). Returns the mixture pdf per steradian in *pdf
 * (0 if wi fell below the surface: the sample then carries no light). */
vec3 brdf_sample(const material *m, vec3 wo, float u_lobe, float u1, float u2, float *pdf);

/* The mixture pdf of brdf_sample for the pair (wo, wi), per steradian. */
float brdf_pdf(const material *m, vec3 wo, vec3 wi);

/* Density of the reflected direction wi when the half vector has density pdf_cos_power:
 * pdf(wi) = (Ns+1)/(2 pi) cos^Ns(theta_h) / (4 wo.h), as on the slides. */
float blinn_pdf(vec3 wo, vec3 wi, float Ns);
#endif
