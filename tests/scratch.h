/* scratch.h — what the test programs that read and write files share (tests/scratch.c, linked into
 * every tests/test_* program): a fresh folder in /tmp for their files, whole files written and read,
 * stderr captured to check the messages, and a small seeded random number generator. */
#ifndef PATHLAB_SCRATCH_H
#define PATHLAB_SCRATCH_H
#include <stddef.h>
#include <stdint.h>

extern char scratch_dir[64];   /* the folder of scratch_begin, e.g. /tmp/test_png.AbC123 */

/* Creates scratch_dir, /tmp/NAME.XXXXXX; when it cannot, prints a FAIL line and exits 1. */
void scratch_begin(const char *name);
/* Removes scratch_dir and the files in it (the folder is flat). */
void scratch_end(void);
/* scratch_dir/name; four results stay valid at once (a call takes the oldest buffer). */
const char *in_dir(const char *name);

/* Writes n bytes as the whole file path (silently nothing when it cannot be opened). */
void spit(const char *path, const void *bytes, size_t n);
/* The whole file path, malloc'ed (free it), its size in *n; NULL when it cannot be opened. */
unsigned char *slurp(const char *path, size_t *n);

/* Sends stderr (file descriptor 2, where the library prints its messages) into a temporary file. */
void capture_begin(void);
/* Gives stderr back and returns what was printed since capture_begin (the first 64 KiB), in a
 * buffer the next capture_end overwrites. */
char *capture_end(void);
/* text without its trailing newlines, for a one-line message; returns text. */
char *chop_newlines(char *text);

/* xorshift32: the same numbers on every machine, from the state rng_seed sets. */
void rng_seed(uint32_t seed);
uint32_t rng(void);
#endif
