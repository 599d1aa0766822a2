/* scratch.c — the helpers of scratch.h, shared by the test programs. */
#include "scratch.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

char scratch_dir[64];

void scratch_begin(const char *name)
{
    snprintf(scratch_dir, sizeof scratch_dir, "/tmp/%s.XXXXXX", name);
    if (mkdtemp(scratch_dir)) return;
    /* check.h's FAIL line: its check() counts failures per program, and this one ends here */
    printf("FAIL mkdtemp: cannot create a folder in /tmp\n");
    exit(1);
}

void scratch_end(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) unlink(in_dir(e->d_name));
    if (d) closedir(d);
    if (rmdir(scratch_dir) != 0) fprintf(stderr, "could not remove %s\n", scratch_dir);
}

const char *in_dir(const char *name)
{
    static char buf[4][400];   /* scratch_dir (64) + "/" + a file name (up to 256) */
    static int next = 0;
    char *b = buf[next++ & 3];
    snprintf(b, sizeof buf[0], "%s/%s", scratch_dir, name);
    return b;
}

void spit(const char *path, const void *bytes, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fwrite(bytes, 1, n, f);
    fclose(f);
}

unsigned char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b;
    long len;
    *n = 0;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = malloc(len > 0 ? (size_t)len : 1);
    if (b) *n = fread(b, 1, (size_t)len, f);
    fclose(f);
    return b;
}

/* The descriptor 2 is redirected, not the FILE stderr, so that whatever writes to it is caught. */
static FILE *capture_file = NULL;
static int saved_stderr = -1;

void capture_begin(void)
{
    fflush(stderr);
    capture_file = tmpfile();
    saved_stderr = dup(2);
    if (capture_file) dup2(fileno(capture_file), 2);
}

char *capture_end(void)
{
    static char text[1 << 16];
    size_t n = 0;
    fflush(stderr);
    dup2(saved_stderr, 2);
    close(saved_stderr);
    if (capture_file) {
        rewind(capture_file);
        n = fread(text, 1, sizeof text - 1, capture_file);
        fclose(capture_file);
        capture_file = NULL;
    }
    text[n] = '\0';
    return text;
}

char *chop_newlines(char *text)
{
    size_t n = strlen(text);
    while (n > 0 && text[n - 1] == '\n') text[--n] = '\0';
    return text;
}

static uint32_t rng_state = 1u;

void rng_seed(uint32_t seed) { rng_state = seed; }

uint32_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}
