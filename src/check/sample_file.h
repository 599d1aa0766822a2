/* sample_file.h — a student's directions read from a text file, one per line: `x y z [pdf]`
 * (whitespace separated; blank lines and lines starting with # ignored), unit directions in the
 * local frame where the normal is +z, and optionally the pdf their code returned for each. Every line
 * has a pdf or none does. A bad line is reported as FILE:LINE: what is wrong, for the student. */
#ifndef PATHLAB_SAMPLE_FILE_H
#define PATHLAB_SAMPLE_FILE_H
#include "math/dvec.h"

#define SAMPLE_UNIT_TOL 1e-3   /* | |w| - 1 |: a direction printed with %g keeps 6 digits */

typedef struct {
    dvec *w;        /* the directions, as read (not renormalized) */
    double *pdf;    /* the 4th column, or NULL when the file has none */
    long *line;     /* the line number of each sample, for the messages */
    long n;
} sample_file;

/* Reads path; 0 on success, else 1 with a message ("samples.txt:17: expected 3 or 4 numbers, got
 * 'nan 0 1'") in err. The file holds at least one sample on success. */
int sample_file_read(const char *path, sample_file *s, char *err, int errlen);
void sample_file_free(sample_file *s);
#endif
