/* sha256.h — SHA-256 (FIPS 180-4), written here: the hash of the viewer's script that the pages'
 * Content-Security-Policy allows (image/html_page.c), and the fingerprint of an image's pixels that
 * finds two students' identical images (grade/integrity.h). */
#ifndef PATHLAB_SHA256_H
#define PATHLAB_SHA256_H
#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint32_t h[8];
    uint64_t bytes;            /* hashed so far */
    unsigned char block[64];   /* the block being filled */
} sha256_ctx;

void sha256_init(sha256_ctx *c);
void sha256_update(sha256_ctx *c, const void *data, size_t n);
void sha256_final(sha256_ctx *c, unsigned char digest[32]);
/* The digest of n bytes at once. */
void sha256(const void *data, size_t n, unsigned char digest[32]);
#endif
