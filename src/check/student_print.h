/* student_print.h — what `pathlab check-sampler` prints: the file and the density checked, the
 * level of each test, then one verdict line per check of student_check.h (0. domain, 1. chi-square,
 * 2. integral and normalisation, 3. pdf column) with the figures behind it, the diagnoses of
 * student_diagnosis.h under the failing ones, and the count of failed checks. */
#ifndef PATHLAB_STUDENT_PRINT_H
#define PATHLAB_STUDENT_PRINT_H
#include "check/student_check.h"

/* Prints the checks of r (run on the directions s of file against p, at level alpha, seed); returns
 * how many failed. */
int student_print(const char *file, const sample_file *s, const student_report *r, const student_pdf *p, double alpha,
                  uint64_t seed);
#endif
