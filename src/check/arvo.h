/* arvo.h — Arvo's map (1995) from [0,1]^2 onto a spherical triangle ABC, and its inverse, in double
 * precision: the reference the checks of light.c's float version bin its directions with.
 * u1 is the fraction of the triangle's area taken by the sub-triangle A B C' (C' on the arc AC),
 * u2 = (1 - B.w) / (1 - B.C') places w on the arc from B to C'. The map is uniform:
 * d omega = Omega du1 du2, so a direction sampler uniform over ABC gives (u1, u2) uniform. */
#ifndef PATHLAB_ARVO_H
#define PATHLAB_ARVO_H
#include "math/dvec.h"

typedef struct {
    dvec A, B, C;          /* unit corners */
    double omega;          /* solid angle (area), by Girard: alpha + beta + gamma - pi */
    double alpha;          /* angle at A between the arcs AB and AC */
} arvo_triangle;

/* The spherical triangle of unit corners A, B, C. */
arvo_triangle arvo_triangle_from(dvec A, dvec B, dvec C);
/* The direction of coordinates (u1, u2). */
dvec arvo_direction(const arvo_triangle *t, double u1, double u2);
/* The coordinates of a unit direction w in the triangle (clamped to [0, 1]). */
void arvo_coords(const arvo_triangle *t, dvec w, double *u1, double *u2);
#endif
