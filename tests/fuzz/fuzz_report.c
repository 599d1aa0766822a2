/* fuzz_report.c — libFuzzer harness: grade's class reports (grade_write_report, Markdown and CSV) of
 * rows whose texts come from the input. The input is cut at NUL bytes into texts, taken in turn as
 * the reference's name, then each row's image name, where, likely mistake, page link and flag (up
 * to 8 rows; the first byte of each image name also chooses the row's verdict). Checked besides
 * memory errors and UB: the structure of both files, whatever the names — Markdown: 6 lines, then
 * one line per row, each with exactly the 8 '|' of its 7 cells, no '<', '>' or control character,
 * at most one link (the page's); CSV: a header and one line per row, 9 fields each, the text
 * fields in quotes, none starting with = + - @ (after its quote), no CR or LF inside. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "grade/grade_class.h"

#define MAX_ROWS 8

/* The file's text, to free; NULL if it cannot be read. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s;
    long n;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    rewind(f);
    s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) { free(s); s = NULL; }
    if (s) s[n] = '\0';
    fclose(f);
    return s;
}

static void check_md(const char *text, int n)
{
    const char *line = text;
    int k = 0;
    for (; *line; k++) {
        const char *end = strchr(line, '\n'), *s;
        int pipes = 0, links = 0;
        if (!end) abort();   /* every line ends */
        for (s = line; s < end; s++) {
            if ((unsigned char)*s < 0x20 || *s == 0x7f || *s == '<' || *s == '>') abort();
            pipes += *s == '|';
            links += s[0] == ']' && s[1] == '(';
        }
        if (k >= 4 && (pipes != 8 || links > 1)) abort();
        line = end + 1;
    }
    if (k != 6 + n) abort();
}

static void check_csv(const char *text, int n)
{
    const char *s = text;
    int k, field;
    for (k = 0; k <= n; k++) {
        for (field = 0;; field++) {
            int text_field = k > 0 && (field == 0 || field >= 5);
            if (*s == '"') {
                if (text_field && strchr("=+-@\t\r", s[1]) && s[1] != '"') abort();
                for (s++; !(s[0] == '"' && s[1] != '"'); s += s[0] == '"' ? 2 : 1)
                    if (!*s || *s == '\n' || *s == '\r') abort();
                s++;
            } else {
                if (text_field) abort();   /* a text field unquoted */
                while (*s && *s != ',' && *s != '\n') s++;
            }
            if (*s == ',') { s++; continue; }
            if (*s != '\n' || field != 8) abort();
            s++;
            break;
        }
    }
    if (*s) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static grade_row rows[MAX_ROWS];
    char *buf = malloc(size + 1), *next, *text[1 + 5 * MAX_ROWS];
    const char *md = fuzz_absent(0, "r.md"), *csv = fuzz_absent(1, "r.csv");
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    grade_refs refs;
    int nt = 0, n, k;
    char *out;
    if (!buf) return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    for (next = buf; nt < 1 + 5 * MAX_ROWS && next <= buf + size; next += strlen(next) + 1) text[nt++] = next;
    n = (nt - 1) / 5;
    memset(rows, 0, sizeof rows);
    memset(&refs, 0, sizeof refs);
    for (k = 0; k < n; k++) {
        char **t = &text[1 + 5 * k];
        rows[k].path = t[0];
        rows[k].status = (unsigned char)t[0][0] % 3;
        rows[k].bias = -0.5, rows[k].bias_se = (unsigned char)t[0][0] % 2 ? 0.01 : -1.0;
        snprintf(rows[k].channel, sizeof rows[k].channel, "red");
        snprintf(rows[k].where, sizeof rows[k].where, "%s", t[1]);
        snprintf(rows[k].mistake, sizeof rows[k].mistake, "%s", t[2]);
        snprintf(rows[k].page, sizeof rows[k].page, "%s", t[3]);
        snprintf(rows[k].remark, sizeof rows[k].remark, "%s", t[4]);
    }
    if (grade_write_report(md, rows, n, &o, text[0], &refs, NULL) || grade_write_report(csv, rows, n, &o, text[0], &refs, NULL)) abort();
    if (!(out = slurp(md))) abort();
    check_md(out, n);
    free(out);
    if (!(out = slurp(csv))) abort();
    check_csv(out, n);
    free(out);
    free(buf);
    return 0;
}
