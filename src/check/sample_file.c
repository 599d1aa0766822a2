/* sample_file.c — reading a student's `x y z [pdf]` file (sample_file.h). */
#include "check/sample_file.h"
#include "sys/input_file.h"
#include "sys/shown.h"
#include <errno.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define LINE_MAX_CHARS 4096
#define SAMPLE_FILE_MAX (1L << 30)   /* bytes: 25 million samples of 40 characters */

/* Up to 5 numbers of the line into v (5: so that one too many is seen); -1 if a word is not a
 * finite number. */
static int parse_numbers(const char *line, double *v)
{
    int k = 0;
    const char *p = line;
    for (;;) {
        char *end;
        while (isspace((unsigned char)*p)) p++;
        if (!*p) return k;
        if (k == 5) return k + 1;
        v[k] = strtod(p, &end);
        if (end == p || !isfinite(v[k]) || (*end && !isspace((unsigned char)*end))) return -1;
        k++, p = end;
    }
}

/* Appends a sample, growing the arrays by doubling; 0, or 1 when out of memory. */
static int push(sample_file *s, long *cap, const double *v, int has_pdf, long line)
{
    if (s->n == *cap) {
        long c = *cap ? 2 * *cap : 1024;
        dvec *w = realloc(s->w, sizeof *w * (size_t)c);
        double *pdf = w ? realloc(s->pdf, sizeof *pdf * (size_t)c) : NULL;
        long *ln = pdf ? realloc(s->line, sizeof *ln * (size_t)c) : NULL;
        if (w) s->w = w;
        if (pdf) s->pdf = pdf;
        if (!ln) return 1;
        s->line = ln, *cap = c;
    }
    s->w[s->n] = dv(v[0], v[1], v[2]);
    s->pdf[s->n] = has_pdf ? v[3] : 0.0;
    s->line[s->n++] = line;
    return 0;
}

/* The text of the line without its newline, for the messages. */
static void chomp(char *buf)
{
    size_t len = strlen(buf);
    while (len && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) buf[--len] = 0;
}

/* One line: 0 if it is a sample or nothing, else 1 with err set. *ncols is the first sample's count. */
static int read_line(const char *path, char *buf, long ln, int *ncols, long *first, double *v, char *err, int errlen)
{
    int k;
    const char *p = buf;
    double len;
    chomp(buf);
    while (isspace((unsigned char)*p)) p++;
    if (!*p || *p == '#') return 0;
    k = parse_numbers(p, v);
    if (k != 3 && k != 4) {
        snprintf(err, (size_t)errlen, "%s:%ld: expected 3 or 4 numbers (x y z [pdf]), got '%.60s'", shown(path), ln, shown(p));
        return 1;
    }
    if (*ncols && k != *ncols) {
        snprintf(err, (size_t)errlen, "%s:%ld: %d numbers, but line %ld has %d: give every line a pdf, or none", shown(path), ln, k,
                 *first, *ncols);
        return 1;
    }
    len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(fabs(len - 1.0) < SAMPLE_UNIT_TOL)) {
        snprintf(err, (size_t)errlen, "%s:%ld: the direction (%g, %g, %g) has length %.6g, not 1 (to %g): normalize it", shown(path),
                 ln, v[0], v[1], v[2], len, SAMPLE_UNIT_TOL);
        return 1;
    }
    if (k == 4 && v[3] < 0.0) {
        snprintf(err, (size_t)errlen, "%s:%ld: the pdf %g is negative: a density is >= 0", shown(path), ln, v[3]);
        return 1;
    }
    if (!*ncols) *ncols = k, *first = ln;
    return 2;
}

/* One physical line of f into buf (its newline dropped): 1 if there was one, 0 at the end of the
 * file, -1 with err set when it holds a NUL byte (not a text file: a sparse or binary file) or is
 * longer than the buffer (cut in two, its halves would read as two lines). */
static int next_line(FILE *f, char *buf, size_t cap, const char *path, long ln, char *err, int errlen)
{
    size_t len = 0;
    int c;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (c == 0) return snprintf(err, (size_t)errlen, "%s:%ld: a NUL byte: not a text file", shown(path), ln), -1;
        if (len + 1 >= cap)
            return snprintf(err, (size_t)errlen, "%s:%ld: a line over %zu bytes: one sample 'x y z [pdf]' a line", shown(path), ln,
                            cap - 1), -1;
        buf[len++] = (char)c;
    }
    buf[len] = 0;
    return c != EOF || len > 0;
}

int sample_file_read(const char *path, sample_file *s, char *err, int errlen)
{
    char buf[LINE_MAX_CHARS];
    double v[6];
    long ln = 0, cap = 0, first = 0;
    int ncols = 0, rc = 0, got;
    struct stat st;
    FILE *f = input_file_open(path, 1);   /* a FIFO, a device or a folder: refused at once, never a hang */
    memset(s, 0, sizeof *s);
    if (!f) {
        snprintf(err, (size_t)errlen, "%s: cannot open it: %s", shown(path), input_file_why(errno));
        return 1;
    }
    if (fstat(fileno(f), &st) == 0 && st.st_size > SAMPLE_FILE_MAX) {
        snprintf(err, (size_t)errlen, "%s: %lld bytes, over the %ld a sample file may have (25 million samples)", shown(path),
                 (long long)st.st_size, SAMPLE_FILE_MAX);
        fclose(f);
        return 1;
    }
    while (!rc && (got = next_line(f, buf, sizeof buf, path, ln + 1, err, errlen)) != 0) {
        ln++;
        if (got < 0) { rc = 1; break; }
        if (ln == 1 && !strncmp(buf, "\xef\xbb\xbf", 3)) memmove(buf, buf + 3, strlen(buf + 3) + 1);   /* a UTF-8 byte-order mark */
        rc = read_line(path, buf, ln, &ncols, &first, v, err, errlen);
        if (rc == 2) rc = push(s, &cap, v, ncols == 4, ln) ? (snprintf(err, (size_t)errlen, "%s: out of memory", shown(path)), 1) : 0;
    }
    if (!rc && ferror(f)) rc = 1, snprintf(err, (size_t)errlen, "%s: read error: %s", shown(path), strerror(errno));
    fclose(f);
    if (!rc && s->n == 0) rc = 1, snprintf(err, (size_t)errlen, "%s: no sample in the file (lines 'x y z [pdf]')", shown(path));
    if (rc) sample_file_free(s);
    else if (ncols == 3) free(s->pdf), s->pdf = NULL;
    return rc;
}

void sample_file_free(sample_file *s)
{
    free(s->w), free(s->pdf), free(s->line);
    memset(s, 0, sizeof *s);
}
