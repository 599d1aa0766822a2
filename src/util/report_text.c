/* report_text.c — text escaped for a Markdown table cell or a CSV field (see report_text.h). */
#include "util/report_text.h"
#include <string.h>
#include "sys/shown.h"

/* 1 when s (at index k of the text t) is the dot of "www." */
static int www_dot(const char *t, size_t k)
{
    size_t i;
    if (t[k] != '.' || k < 3) return 0;
    for (i = k - 3; i < k; i++) if (t[i] != 'w' && t[i] != 'W') return 0;
    return 1;
}

static int alnum(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

void md_put_text(FILE *f, const char *text)
{
    const char *t = shown(text);
    size_t k;
    for (k = 0; t[k]; k++) {
        char c = t[k];
        int url = c == ':' && t[k + 1] == '/' && t[k + 2] == '/';   /* http:// : an autolink */
        int flanking = c == '_' && !(k > 0 && alnum(t[k - 1]) && alnum(t[k + 1]));
        if (c == '@' || url || www_dot(t, k)) fprintf(f, "`%c`", c);   /* a code span: no renderer links across it */
        else if (strchr("&<>\"'\\|[]", c)) fprintf(f, "&#%d;", (unsigned char)c);
        else if (strchr("`*~", c) || flanking) fprintf(f, "\\%c", c);
        else fputc(c, f);
    }
}

void csv_put_field(FILE *f, const char *text)
{
    const char *t = shown(text);
    fputc('"', f);
    if (t[0] && strchr("=+-@\t\r", t[0])) fputc('\'', f);
    for (; *t; t++) {
        if (*t == '"') fputc('"', f);
        fputc(*t, f);
    }
    fputc('"', f);
}
