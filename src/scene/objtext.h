/* objtext.h — the line reader shared by the OBJ and MTL parsers (obj.c, mtl.c).
 * A file is read whole into memory and cut in place into logical lines: '#' comments, CR and
 * trailing blanks are dropped, lines ending in '\' are joined with the next one. Lines have no
 * length limit. Messages have the form "file:line: message". */
#ifndef PATHLAB_OBJTEXT_H
#define PATHLAB_OBJTEXT_H
#include <stdio.h>
#include <stddef.h>

#define OBJTEXT_SEEN_MAX 64 /* keys remembered per file, so that each warning about them comes once */
#define OBJTEXT_SEEN_LEN 24

typedef struct {
    const char *path;
    char *buf, *at, *end; /* contents (NUL-terminated), next unread byte, end of the contents */
    int line, next_line;  /* number of the current logical line (0: none); physical lines read */
    char *join;           /* a logical line glued together from '\'-continued physical lines */
    size_t joincap;
    int oom, quiet;       /* oom: objtext_line() ran out of memory */
    char seen[OBJTEXT_SEEN_MAX][OBJTEXT_SEEN_LEN];
    int nseen;
} objtext;

#if defined(__GNUC__)
#define OBJTEXT_PRINTF(i) __attribute__((format(printf, i, i + 1)))
#else
#define OBJTEXT_PRINTF(i)
#endif

/* A token quoted in a message is cut to its first OBJTEXT_CUT_LEN characters, then "...": a
 * 100 MB word must not be echoed whole. Use with "%.*s%s": OBJTEXT_CUT(word). */
#define OBJTEXT_CUT_LEN 40
#define OBJTEXT_CUT(s) OBJTEXT_CUT_LEN, (s), objtext_cut_tail(s)
/* "..." when s is longer than OBJTEXT_CUT_LEN characters, else "". */
const char *objtext_cut_tail(const char *s);

/* Reads file path into t (path is kept, not copied). Returns 0, or the errno of the failure. */
int objtext_open(objtext *t, const char *path, int quiet);
/* The same for a file a scene names: with max > 0, anything but a regular file of at most max bytes
 * is refused (EISDIR for a folder, ENODEV for a device, FIFO or socket, EFBIG when larger). */
int objtext_open_bounded(objtext *t, const char *path, int quiet, size_t max);
/* Frees what objtext_open() allocated; harmless after a failed open. */
void objtext_close(objtext *t);
/* Refuses files with NUL bytes or a UTF-16 byte-order mark (prints the error, returns 0). */
int objtext_check(objtext *t);
/* The next logical line, modifiable, or NULL at the end of the file (or when t->oom). */
char *objtext_line(objtext *t);
/* The next blank-separated word of *s, NUL-terminated in place, or NULL when none is left. */
char *objtext_word(char **s);
/* The rest of a line with leading blanks skipped: a name that may contain blanks. */
char *objtext_rest(char *s);
/* Reads the min to max numbers that follow keyword kw into v: finite floats, each a whole word.
 * Returns how many, or -1 after printing the error. */
int objtext_numbers(const objtext *t, char **s, const char *kw, float *v, int min, int max);
/* Prints "file:line: message" for the current line on stderr (always) and returns 0. */
OBJTEXT_PRINTF(2) int objtext_fail(const objtext *t, const char *fmt, ...);
/* Prints a warning at line ("file: message" if line is 0), unless quiet. */
OBJTEXT_PRINTF(3) void objtext_warn(const objtext *t, int line, const char *fmt, ...);
/* 1 the first time key is passed for this file, then 0: for warnings that should come once. */
int objtext_first_time(objtext *t, const char *key);
#endif
