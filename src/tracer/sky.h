/* sky.h — the sky: radiance L(w) arriving from infinitely far away along every direction w that
 * leaves the scene, a light in the course's sense. Either constant (--sky R,G,B) or an
 * equirectangular image (--sky FILE.pfm|FILE.hdr), +Y up as in gKit's scenes. The image's pixel
 * (i, j), column i from the left, row j from the top, of a w x h image, covers the directions
 *   theta in [pi j / h, pi (j + 1) / h]            (the angle from +Y: row 0 is the zenith)
 *   phi   in [2 pi i / w - pi, 2 pi (i + 1) / w - pi]   (phi = atan2(z, x): +X at the image's
 *                                                        middle column, then +Z a quarter further right)
 * with w = (sin theta cos phi, cos theta, sin theta sin phi), and its value is the radiance of
 * each of them (the nearest texel, no filtering). That is Blender Cycles' Environment Texture
 * (equirectangular, Closest) once Blender's OBJ import has turned +Y up into +Z up (x, y, z) ->
 * (x, -z, y): Cycles' u = atan2(-Y, X) / 2pi + 1/2 is ours, its v (from the bottom) is 1 - j / h.
 * A constant sky is the 1 x 1 image.
 * pdf1 of a direction, per steradian, follows the luminance: a pixel is chosen in proportion to
 * luminance x its solid angle (= luminance x sin theta, integrated over its row: a marginal
 * distribution over the rows, a conditional one within the row), then a direction uniform in
 * solid angle inside it (cos theta uniform over the row, phi uniform over the column), so that
 * pdf1_sa(w) = luminance(L(w)) / (integral of the luminance over the sphere). A constant sky is
 * sampled uniformly over the sphere. */
#ifndef PATHLAB_SKY_H
#define PATHLAB_SKY_H
#include "image/image.h"

typedef enum { SKY_NONE, SKY_CONSTANT, SKY_IMAGE } sky_kind;

/* What --sky says: nothing, a constant radiance, or an image file (read by sky_build). */
typedef struct {
    sky_kind kind;
    vec3 rgb;            /* SKY_CONSTANT */
    const char *path;    /* SKY_IMAGE */
} sky_spec;

typedef struct {
    int w, h;            /* 0 x 0: no sky */
    float *L;            /* w h RGB radiances, row 0 at the top (the zenith, +Y) */
    float *pdf;          /* w h: pdf1 per steradian of each pixel's directions */
    double *row_cdf;     /* h: the marginal over the rows (cumulative) */
    double *col_cdf;     /* w h: in each row, the conditional over its columns (cumulative) */
    double *cos_edge;    /* h + 1: cos(pi j / h), the rows' bounds */
    double integral;     /* the integral over the sphere of luminance(L), in W / (m^2) */
} sky;

/* The sky of a spec: from the image file for SKY_IMAGE (.hdr: Radiance RGBE, image/rgbe.h; else a
 * PFM; its values must be finite and >= 0).
 * 0 on success; 1 after printing "path: reason". SKY_NONE gives the empty sky. */
int sky_build(sky *s, const sky_spec *spec);
/* The sky of an image in memory (copied), row 0 at the top; 0 on success, 1 out of memory. */
int sky_from_image(sky *s, const image *im);
void sky_free(sky *s);
static inline int sky_present(const sky *s) { return s->w > 0 && s->integral > 0.0; }
/* L(w): the radiance arriving along -w, that is seen when looking toward w (any length but 0). */
vec3 sky_radiance(const sky *s, vec3 w);
/* pdf1 per steradian of the direction w (any length but 0). */
float sky_pdf_sa(const sky *s, vec3 w);
/* A unit direction drawn with pdf1: u1 (in double: the remainder of the light's choice) picks the
 * row and cos theta in it, u2 the column and phi in it. Its pdf1 per steradian in *pdf_sa, its
 * radiance in *L. */
vec3 sky_sample(const sky *s, double u1, float u2, float *pdf_sa, vec3 *L);
#endif
