/* student_diagnosis.h — what a student most likely got wrong, from the checks' numbers
 * (student_check.h): the classic mistakes of the course's samplers, each named.
 * Directions: below the surface; blinn's reflections below the surface left out of the file;
 * uniform in theta instead of in cos theta; cos theta = u^(1/M) instead of u^(1/(M+1)) (the lobe's
 * exponent K fitted from the mean cosine is M - 1); another exponent.
 * The pdf column: its ratio to the named density is a constant (pi: the 1/pi is missing; 2 pi;
 * (m+2)/(m+1), m/(m+1), (m+8)/(4(m+1)): the normalisation), or varies like 4 (wo.h) (the Jacobian of
 * the reflection dwh/dw = 1/(4 wo.h) is missing: the half vector's density), its square, or
 * (cos theta / cos theta_h)^m (cos^m of the direction's angle instead of the half vector's). */
#ifndef PATHLAB_STUDENT_DIAGNOSIS_H
#define PATHLAB_STUDENT_DIAGNOSIS_H
#include "check/student_check.h"

/* Why the domain or chi-square check failed, in buf; 0 if nothing specific was recognised. */
int student_diagnose_directions(const student_report *r, const student_pdf *p, char *buf, int len);
/* Why the column differs from the named density, in buf; 0 if nothing specific was recognised. */
int student_diagnose_pdf(const sample_file *s, const student_pdf *p, const student_report *r, char *buf, int len);
#endif
