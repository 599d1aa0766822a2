/* objtext.c — the line reader of the OBJ and MTL parsers; see objtext.h.
 * Cutting lines in place, in a buffer that holds the whole file, costs one memchr per line and
 * no copy (only '\'-continued lines are copied, into t->join). */
#include "scene/objtext.h"
#include "sys/shown.h"
#include "sys/input_file.h"
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/* Reading in a loop rather than asking for the size works for pipes and reports directories.
 * Reading stops after a chunk with a NUL byte: objtext_check refuses the file anyway, and
 * /dev/zero or a binary would otherwise be read whole (or forever). With max > 0 the file must be
 * a regular one of at most max bytes: opened without blocking (a FIFO swapped in after the
 * caller's checks must not hang the reader) and read no further than max + 1 bytes. Any file must
 * be a regular one (ENODEV, EISDIR otherwise): a scene is a file, never a FIFO or a device. */
int objtext_open_bounded(objtext *t, const char *path, int quiet, size_t max)
{
    FILE *f;
    char *buf = NULL, *bigger;
    size_t len = 0, cap = 1 << 16, got;
    int err = 0;
    memset(t, 0, sizeof *t);
    t->path = path;
    t->quiet = quiet;
    if (!(f = input_file_open(path, 1))) return errno;   /* a FIFO, a device or a folder: refused at once */
    for (;;) {
        if (!(bigger = realloc(buf, cap + 1))) { err = ENOMEM; break; } /* +1: the final NUL */
        buf = bigger;
        errno = 0;
        len += got = fread(buf + len, 1, cap - len, f);
        if (max && len > max) { err = EFBIG; break; }
        if (len < cap) {
            if (ferror(f)) err = errno ? errno : EIO;
            break;
        }
        if (memchr(buf + len - got, '\0', got)) break;
        cap *= 2;
        if (max && cap > max + 1) cap = max + 1;
    }
    fclose(f);
    if (err) { free(buf); return err; }
    buf[len] = '\0';
    t->buf = t->at = buf;
    t->end = buf + len;
    return 0;
}

int objtext_open(objtext *t, const char *path, int quiet) { return objtext_open_bounded(t, path, quiet, 0); }

const char *objtext_cut_tail(const char *s)
{
    return strnlen(s, OBJTEXT_CUT_LEN + 1) > OBJTEXT_CUT_LEN ? "..." : "";
}

void objtext_close(objtext *t)
{
    free(t->buf);
    free(t->join);
    t->buf = t->at = t->end = t->join = NULL;
}

/* A NUL byte would silently cut a line short, so a file with one is refused; UTF-16 text has
 * one in every ASCII character. A UTF-8 byte-order mark is skipped. */
int objtext_check(objtext *t)
{
    const unsigned char *u = (const unsigned char *)t->buf;
    size_t len = (size_t)(t->end - t->buf);
    const char *nul = memchr(t->buf, '\0', len), *p;
    if (len >= 2 && ((u[0] == 0xFE && u[1] == 0xFF) || (u[0] == 0xFF && u[1] == 0xFE))) nul = t->buf;
    if (nul) {
        for (t->line = 1, p = t->buf; p < nul; p++) t->line += *p == '\n';
        return objtext_fail(t, "not a text file (UTF-16?)");
    }
    if (len >= 3 && u[0] == 0xEF && u[1] == 0xBB && u[2] == 0xBF) t->at += 3;
    return 1;
}

/* Cuts off the next physical line in place: NUL-terminated, without its '#' comment, CR and
 * trailing blanks. The comment goes first so that a comment ending in '\' continues nothing. */
static char *physical_line(objtext *t, size_t *len)
{
    char *s = t->at, *e, *hash;
    if (s >= t->end) return NULL;
    if (!(e = memchr(s, '\n', (size_t)(t->end - s)))) e = t->end;
    t->at = e < t->end ? e + 1 : e;
    if ((hash = memchr(s, '#', (size_t)(e - s)))) e = hash;
    while (e > s && is_blank(e[-1])) e--;
    *e = '\0';
    t->next_line++;
    *len = (size_t)(e - s);
    return s;
}

/* Makes room for need bytes in t->join, doubling; 0 when out of memory. */
static int reserve_join(objtext *t, size_t need)
{
    size_t cap = t->joincap ? t->joincap : 256;
    char *bigger;
    if (need <= t->joincap) return 1;
    while (cap < need) cap *= 2;
    if (!(bigger = realloc(t->join, cap))) return 0;
    t->join = bigger;
    t->joincap = cap;
    return 1;
}

/* Continued lines are joined with one blank, so "f 1 2 \" + "3" reads as "f 1 2 3". The logical
 * line is numbered after its first physical line. */
char *objtext_line(objtext *t)
{
    size_t len, used = 0;
    char *s = physical_line(t, &len);
    t->line = t->next_line;
    if (!s || len == 0 || s[len - 1] != '\\') return s;
    for (;;) {
        int more = len > 0 && s[len - 1] == '\\';
        if (more) len--;
        if (!reserve_join(t, used + len + 1)) { t->oom = 1; return NULL; }
        memcpy(t->join + used, s, len);
        used += len;
        t->join[used++] = ' ';
        if (!more || !(s = physical_line(t, &len))) break;
    }
    t->join[used - 1] = '\0';
    return t->join;
}

char *objtext_word(char **s)
{
    char *p = *s, *w;
    while (is_blank(*p)) p++;
    if (!*p) { *s = p; return NULL; }
    for (w = p; *p && !is_blank(*p); p++) {}
    if (*p) *p++ = '\0';
    *s = p;
    return w;
}

/* Trailing blanks were cut with the line already. */
char *objtext_rest(char *s)
{
    while (is_blank(*s)) s++;
    return s;
}

/* strtod must eat the whole word: "1.5x" is an error, not 1.5. Doubles beyond the float range
 * become inf and are refused with NaN and inf. */
static int parse_float(const objtext *t, const char *w, float *v)
{
    char *end;
    *v = (float)strtod(w, &end);
    if (end == w || *end) return objtext_fail(t, "bad number '%.*s%s'", OBJTEXT_CUT(w));
    if (!isfinite(*v)) return objtext_fail(t, "'%.*s%s' is not a finite float", OBJTEXT_CUT(w));
    return 1;
}

int objtext_numbers(const objtext *t, char **s, const char *kw, float *v, int min, int max)
{
    char *w;
    int n = 0;
    while ((w = objtext_word(s))) {
        if (n == max) {
            objtext_fail(t, "too many numbers after '%s' (at most %d)", kw, max);
            return -1;
        }
        if (!parse_float(t, w, &v[n++])) return -1;
    }
    if (n >= min) return n;
    if (min == max) objtext_fail(t, "'%s' needs %d numbers, found %d", kw, min, n);
    else objtext_fail(t, "'%s' needs %d to %d numbers, found %d", kw, min, max, n);
    return -1;
}

/* The message is shown() whole: the words it quotes come from the student's file (a name, a bad
 * number) and may hold terminal escapes. */
static void vsay(const char *path, int line, const char *fmt, va_list ap)
{
    char msg[2048];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (line > 0) fprintf(stderr, "%s:%d: ", shown(path), line);
    else fprintf(stderr, "%s: ", shown(path));
    fputs(shown(msg), stderr);
    fputc('\n', stderr);
}

int objtext_fail(const objtext *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsay(t->path, t->line, fmt, ap);
    va_end(ap);
    return 0;
}

void objtext_warn(const objtext *t, int line, const char *fmt, ...)
{
    va_list ap;
    if (t->quiet) return;
    va_start(ap, fmt);
    vsay(t->path, line, fmt, ap);
    va_end(ap);
}

/* Keys are compared on their first OBJTEXT_SEEN_LEN - 1 characters; past OBJTEXT_SEEN_MAX keys a
 * warning may repeat, which is better than an allocation that could fail. */
int objtext_first_time(objtext *t, const char *key)
{
    size_t n = strlen(key);
    int i;
    if (n > OBJTEXT_SEEN_LEN - 1) n = OBJTEXT_SEEN_LEN - 1;
    for (i = 0; i < t->nseen; i++)
        if (strncmp(t->seen[i], key, n) == 0 && t->seen[i][n] == '\0') return 0;
    if (t->nseen < OBJTEXT_SEEN_MAX) {
        memcpy(t->seen[t->nseen], key, n);
        t->seen[t->nseen++][n] = '\0';
    }
    return 1;
}
