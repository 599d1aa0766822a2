/* vec.h — 3-vectors of floats (the renderer's geometry; math/dvec.h has the double ones), the
 * orthonormal frame about a normal (local coordinates where cos theta = z), PI, and the Rec. 709
 * luminance of a colour. Everything is static inline so that hot paths (traversal, sampling) stay
 * call-free. */
#ifndef PATHLAB_VEC_H
#define PATHLAB_VEC_H
#include <math.h>

#define PI 3.14159265358979323846          /* in double, for the checks and statistics */
#define PI_F 3.14159265358979323846f
#define INV_PI_F 0.31830988618379067154f

typedef struct { float x, y, z; } vec3;

static inline vec3 v3(float x, float y, float z) { vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 v3_scale(vec3 a, float s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_madd(vec3 a, vec3 b, float s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline float v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float v3_length(vec3 a) { return sqrtf(v3_dot(a, a)); }
static inline vec3 v3_normalize(vec3 a) { return v3_scale(a, 1.0f / v3_length(a)); }
static inline vec3 v3_min(vec3 a, vec3 b) { return v3(fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z)); }
static inline float v3_comp(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline float v3_max_comp(vec3 a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
static inline float v3_mean(vec3 a) { return (a.x + a.y + a.z) * (1.0f / 3.0f); }
/* Rec. 709 luminance of a linear RGB colour: how bright it looks, for choosing lights by power. */
static inline float luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
static inline int v3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
static inline int v3_is_zero(vec3 a) { return a.x == 0.0f && a.y == 0.0f && a.z == 0.0f; }

/* Orthonormal frame (t, b, n) around a unit normal n, so that a direction sampled in local
 * coordinates (cos theta = z) maps to world space by t*x + b*y + n*z. (Duff et al. 2017.) */
typedef struct { vec3 t, b, n; } frame;
static inline frame frame_from_normal(vec3 n)
{
    frame f;
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    f.t = v3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = v3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}
static inline vec3 frame_to_world(const frame *f, vec3 l)
{
    return v3_add(v3_add(v3_scale(f->t, l.x), v3_scale(f->b, l.y)), v3_scale(f->n, l.z));
}
static inline vec3 frame_to_local(const frame *f, vec3 w)
{
    return v3(v3_dot(w, f->t), v3_dot(w, f->b), v3_dot(w, f->n));
}
#endif
