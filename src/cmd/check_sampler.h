/* check_sampler.h — `pathlab check-sampler FILE.txt --pdf NAME [--wo X,Y,Z] [--alpha A] [--seed S]`:
 * a student's directions (and the pdf their code returned) from a text file, checked against the
 * density they claim; the checks, diagnoses and lines are check/student_check.h, student_diagnosis.h
 * and student_print.h; this file reads the flags. docs/check-sampler.md is the student's guide. */
#ifndef PATHLAB_CMD_CHECK_SAMPLER_H
#define PATHLAB_CMD_CHECK_SAMPLER_H

#define CHECK_SAMPLER_USAGE \
    "  pathlab check-sampler FILE.txt --pdf uniform|hemisphere|cosine|cosm:M|blinn:M [--wo X,Y,Z] [--alpha A] [--seed S]\n" \
    "                does a student's sampler draw the pdf it claims? FILE: 'x y z [pdf]' per line (check-sampler --help)\n"

/* argv[0] = "check-sampler". 0 when every check passes, 1 if one fails, 2 on bad flags, a bad file, or too
 * few samples (under STUDENT_MIN_SAMPLES) to judge the chi-square when the other checks pass. */
int check_sampler_main(int argc, char **argv);
#endif
