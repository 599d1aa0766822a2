/* dvec.h — 3-vectors and orthonormal frames in double precision: the light sampler's spherical
 * triangles (whose trigonometry float cannot carry) and the sampling checks' reference formulas.
 * A frame's directions are written in (t, phi) about its axis n, t = 1 - cos(angle to n), so that
 * d omega = dt dphi. */
#ifndef PATHLAB_DVEC_H
#define PATHLAB_DVEC_H
#include <math.h>
#include "math/vec.h"

typedef struct { double x, y, z; } dvec;
typedef struct { dvec t, b, n; } dframe;

static inline dvec dv(double x, double y, double z) { dvec r; r.x = x; r.y = y; r.z = z; return r; }
static inline dvec dv_of(vec3 a) { return dv(a.x, a.y, a.z); }
static inline vec3 fv_of(dvec a) { return v3((float)a.x, (float)a.y, (float)a.z); }
static inline double dv_dot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/* s a + r b */
static inline dvec dv_lin(dvec a, double s, dvec b, double r) { return dv(s * a.x + r * b.x, s * a.y + r * b.y, s * a.z + r * b.z); }
static inline dvec dv_normalize(dvec a) { return dv_lin(a, 1.0 / sqrt(dv_dot(a, a)), a, 0.0); }
static inline dvec dv_cross(dvec a, dvec b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
/* The mirror direction of wo about the unit normal h. */
static inline dvec dv_reflect(dvec wo, dvec h) { return dv_lin(h, 2.0 * dv_dot(wo, h), wo, -1.0); }

/* Orthonormal frame about the unit axis n (Duff et al. 2017, as frame_from_normal). */
dframe dframe_about(dvec n);
/* The direction at (t, phi) about F.n, and the (t, phi) of a unit direction (phi in [0, 2 pi)). */
dvec dframe_dir(const dframe *F, double t, double phi);
void dframe_coords(const dframe *F, dvec w, double *t, double *phi);

#endif
