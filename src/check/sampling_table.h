/* sampling_table.h — what `pathlab check-sampling` prints: one row per case (routine, chi2, dof,
 * p-value, integral and its want, the pdf's gap to the course's formula, the verdict of verdict.h),
 * grouped by kind under a title that names the file and the cells, and the legend of the columns. */
#ifndef PATHLAB_SAMPLING_TABLE_H
#define PATHLAB_SAMPLING_TABLE_H
#include "check/case.h"

/* The rows of the n cases c and their results r; quiet: the failing rows only, no titles. */
void sampling_print_table(const sampling_case *c, const sampling_result *r, int n, double alpha_case, int quiet);
/* What the columns mean and the level of each case's chi-square. */
void sampling_print_legend(int n, double alpha_case);
#endif
