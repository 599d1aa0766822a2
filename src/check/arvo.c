/* arvo.c — Arvo's map and its inverse in double (arvo.h). */
#include "check/arvo.h"

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

/* Angle at A between the great arcs AB and AC: the angle between the normals A x B and A x C, with
 * (A x B) x (A x C) = (A.(B x C)) A and (A x B).(A x C) = B.C - (A.B)(A.C); atan2 keeps it accurate
 * for angles near 0 and pi. */
static double corner_angle(dvec A, dvec B, dvec C)
{
    return atan2(fabs(dv_dot(A, dv_cross(B, C))), dv_dot(B, C) - dv_dot(A, B) * dv_dot(A, C));
}

/* Area of the spherical triangle of unit corners A, B, C by Girard's theorem. */
static double arvo_area(dvec A, dvec B, dvec C)
{
    return corner_angle(A, B, C) + corner_angle(B, C, A) + corner_angle(C, A, B) - PI;
}

arvo_triangle arvo_triangle_from(dvec A, dvec B, dvec C)
{
    arvo_triangle t;
    t.A = A, t.B = B, t.C = C;
    t.omega = arvo_area(A, B, C);
    t.alpha = corner_angle(A, B, C);
    return t;
}

/* Van Oosterom and Strackee 1983: tan(Omega/2) = |A.(B x C)| / (1 + A.B + B.C + C.A); one atan2
 * where Girard needs three (it runs once per sample in arvo_coords) */
static double solid_angle(dvec A, dvec B, dvec C)
{
    return 2.0 * atan2(fabs(dv_dot(A, dv_cross(B, C))), 1.0 + dv_dot(A, B) + dv_dot(B, C) + dv_dot(C, A));
}

/* v minus its component along the unit vector u, normalised */
static dvec orthogonal_part(dvec v, dvec u) { return dv_normalize(dv_lin(v, 1.0, u, -dv_dot(v, u))); }

/* |a - b|^2 / 2 = 1 - a.b for unit vectors, without the cancellation */
static double one_minus_dot(dvec a, dvec b)
{
    dvec d = dv_lin(a, 1.0, b, -1.0);
    return 0.5 * dv_dot(d, d);
}

/* Arvo 1995, Graphics Gems V: the sub-triangle A B C' of area u1 Omega gives cos(arc AC') = q. */
dvec arvo_direction(const arvo_triangle *t, double u1, double u2)
{
    double sub = u1 * t->omega, s = sin(sub - t->alpha), c = cos(sub - t->alpha);
    double ca = cos(t->alpha), sa = sin(t->alpha), u = c - ca, v = s + sa * dv_dot(t->A, t->B);
    double q = ((v * c - u * s) * ca - v) / ((v * s + u * c) * sa), z;
    dvec C1;
    q = fmax(-1.0, fmin(1.0, q));
    C1 = dv_lin(t->A, q, orthogonal_part(t->C, t->A), sqrt(1.0 - q * q));
    z = 1.0 - u2 * one_minus_dot(C1, t->B);   /* cos(arc B w) */
    return dv_lin(t->B, z, orthogonal_part(C1, t->B), sqrt(fmax(0.0, 1.0 - z * z)));
}

/* C' is where the great circle through B and w meets the arc AC: along (A x C) x (B x w), on the
 * side of A + C. */
void arvo_coords(const arvo_triangle *t, dvec w, double *u1, double *u2)
{
    dvec n_bw = dv_cross(t->B, w), C1 = dv_cross(dv_cross(t->A, t->C), n_bw);
    double len = sqrt(dv_dot(C1, C1));
    if (!(len > 0.0)) {   /* w = B: every C' fits, u2 = 0 */
        *u1 = 0.5, *u2 = 0.0;
        return;
    }
    C1 = dv_lin(C1, 1.0 / len, C1, 0.0);
    if (dv_dot(C1, dv_lin(t->A, 1.0, t->C, 1.0)) < 0.0) C1 = dv_lin(C1, -1.0, C1, 0.0);
    *u1 = clamp01(solid_angle(t->A, t->B, C1) / t->omega);
    *u2 = clamp01(one_minus_dot(w, t->B) / one_minus_dot(C1, t->B));
}
