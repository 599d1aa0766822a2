/* inflate.c — see inflate.h. Written from RFC 1950 (zlib) and RFC 1951 (deflate).
 *
 * Bits are read least significant first from a 64-bit buffer. A Huffman code is decoded with one
 * table lookup: deflate packs a code's bits most significant first, so a code c of length L is at
 * every index whose low L bits are c reversed; the table has 2^(longest length) entries, each the
 * symbol and its length (length 0: no code there, an error in the stream). */
#include "image/inflate.h"
#include <stdint.h>
#include <string.h>

#define MAX_BITS 15

typedef struct {
    const unsigned char *in;
    size_t n, pos;          /* bytes, and the next one to load into bits */
    uint64_t bits;
    int count;              /* bits held */
    int pad;                /* of which zeros added past the end (the top ones): consuming them is an error */
    unsigned char *out;
    size_t cap, len;
} inflater;

typedef struct {
    uint16_t entry[1 << MAX_BITS];   /* symbol << 4 | length */
    int max_len;
} huffman;

static void refill(inflater *z)
{
    while (z->count <= 56) {
        if (z->pos < z->n) z->bits |= (uint64_t)z->in[z->pos++] << z->count;
        else z->pad += 8;   /* zeros past the end: harmless unless consumed */
        z->count += 8;
    }
}

/* Bits past the end of the data were consumed. */
static int overrun(const inflater *z) { return z->count < z->pad; }

static unsigned take(inflater *z, int k)
{
    unsigned v;
    if (z->count < k) refill(z);
    v = (unsigned)(z->bits & ((1u << k) - 1));
    z->bits >>= k;
    z->count -= k;
    return v;
}

/* The canonical code (RFC 1951 3.2.2) of lengths len[0..n): 0, or -1 when over-subscribed. */
static int build(huffman *h, const unsigned char *len, int n)
{
    int count[MAX_BITS + 1] = {0}, next[MAX_BITS + 2], s, l, code = 0, left = 1;
    for (s = 0; s < n; s++) count[len[s]]++;
    count[0] = 0;
    for (l = 1; l <= MAX_BITS; l++) {
        left = 2 * left - count[l];
        if (left < 0) return -1;
    }
    for (h->max_len = MAX_BITS; h->max_len > 1 && !count[h->max_len]; h->max_len--) {}
    memset(h->entry, 0, sizeof(uint16_t) << h->max_len);
    for (l = 1; l <= MAX_BITS; l++) {
        code = (code + count[l - 1]) << 1;
        next[l] = code;
    }
    for (s = 0; s < n; s++) {
        int L = len[s], c, r = 0, k, i;
        if (!L) continue;
        c = next[L]++;
        for (i = 0; i < L; i++) r |= (c >> i & 1) << (L - 1 - i);
        for (k = r; k < 1 << h->max_len; k += 1 << L) h->entry[k] = (uint16_t)(s << 4 | L);
    }
    return 0;
}

/* One symbol, or -1 for a code the table does not have. */
static int decode(inflater *z, const huffman *h)
{
    unsigned e;
    if (z->count < h->max_len) refill(z);
    e = h->entry[z->bits & ((1u << h->max_len) - 1)];
    if (!(e & 15)) return -1;
    z->bits >>= e & 15;
    z->count -= (int)(e & 15);
    return (int)(e >> 4);
}

static const char *stored(inflater *z)
{
    unsigned len, nlen;
    take(z, z->count & 7);   /* to the byte boundary */
    len = take(z, 16);
    nlen = take(z, 16);
    if (overrun(z)) return "truncated";
    if ((len ^ 0xffff) != nlen) return "a stored block whose LEN and NLEN disagree";
    while (len > 0 && z->count - z->pad >= 8) {   /* bytes already in the bit buffer */
        if (z->len >= z->cap) return "more data than expected";
        z->out[z->len++] = (unsigned char)take(z, 8);
        len--;
    }
    if (len > z->n - z->pos) return "truncated";
    if (len > z->cap - z->len) return "more data than expected";
    memcpy(z->out + z->len, z->in + z->pos, len);
    z->len += len;
    z->pos += len;
    return NULL;
}

static const unsigned short LEN_BASE[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59,
                                            67, 83, 99, 115, 131, 163, 195, 227, 258};
static const unsigned char LEN_EXTRA[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const unsigned short DIST_BASE[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                             1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const unsigned char DIST_EXTRA[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* The symbols of a Huffman block up to the end-of-block symbol 256. */
static const char *codes(inflater *z, const huffman *lit, const huffman *dist)
{
    for (;;) {
        int s = decode(z, lit), d;
        size_t length, distance;
        if (overrun(z)) return "truncated";
        if (s < 0) return "a code that is not in the block's Huffman table";
        if (s < 256) {
            if (z->len >= z->cap) return "more data than expected";
            z->out[z->len++] = (unsigned char)s;
            continue;
        }
        if (s == 256) return NULL;
        if (s > 285) return "a length symbol above 285";
        length = LEN_BASE[s - 257] + take(z, LEN_EXTRA[s - 257]);
        d = decode(z, dist);
        if (d < 0 || d > 29) return "a distance code that is not in the block's table";
        distance = DIST_BASE[d] + take(z, DIST_EXTRA[d]);
        if (overrun(z)) return "truncated";
        if (distance > z->len) return "a distance back before the start of the data";
        if (length > z->cap - z->len) return "more data than expected";
        for (; length > 0; length--, z->len++) z->out[z->len] = z->out[z->len - distance];
    }
}

static const char *fixed(inflater *z, huffman *lit, huffman *dist)
{
    unsigned char len[288];
    memset(len, 8, 144);
    memset(len + 144, 9, 112);
    memset(len + 256, 7, 24);
    memset(len + 280, 8, 8);
    build(lit, len, 288);
    memset(len, 5, 30);
    build(dist, len, 30);
    return codes(z, lit, dist);
}

/* The code lengths of a dynamic block (RFC 1951 3.2.7), through the code-length code. */
static const char *lengths(inflater *z, huffman *h, unsigned char *len, int total)
{
    int i = 0;
    while (i < total) {
        int s = decode(z, h), repeat, value = 0;
        if (overrun(z)) return "truncated";
        if (s < 0) return "a code-length code that is not in its table";
        if (s < 16) { len[i++] = (unsigned char)s; continue; }
        if (s == 16) {
            if (i == 0) return "a code length repeated with none before it";
            value = len[i - 1];
            repeat = 3 + (int)take(z, 2);
        } else repeat = s == 17 ? 3 + (int)take(z, 3) : 11 + (int)take(z, 7);
        if (repeat > total - i) return "code lengths past the number of codes";
        while (repeat-- > 0) len[i++] = (unsigned char)value;
    }
    return NULL;
}

static const char *dynamic(inflater *z, huffman *lit, huffman *dist)
{
    static const unsigned char order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    unsigned char len[320], cl[19] = {0};
    int hlit = 257 + (int)take(z, 5), hdist = 1 + (int)take(z, 5), hclen = 4 + (int)take(z, 4), i;
    const char *why;
    if (hlit > 286 || hdist > 30) return "more than 286 literal/length or 30 distance codes";
    for (i = 0; i < hclen; i++) cl[order[i]] = (unsigned char)take(z, 3);
    if (overrun(z)) return "truncated";
    if (build(lit, cl, 19)) return "an over-subscribed code-length code";
    if ((why = lengths(z, lit, len, hlit + hdist))) return why;
    if (!len[256]) return "no code for the end of the block";
    if (build(lit, len, hlit) || build(dist, len + hlit, hdist)) return "an over-subscribed Huffman code";
    return codes(z, lit, dist);
}

static uint32_t adler32(const unsigned char *b, size_t n)
{
    uint32_t a = 1, s = 0;
    size_t i = 0;
    while (i < n) {
        size_t end = i + 5552 < n ? i + 5552 : n;   /* sums stay below 2^32 for 5552 bytes */
        for (; i < end; i++) {
            a += b[i];
            s += a;
        }
        a %= 65521;
        s %= 65521;
    }
    return s << 16 | a;
}

/* The blocks, until the one marked last. */
static const char *blocks(inflater *z)
{
    static huffman lit, dist;   /* 128 KiB: not on the stack; PNG decoding is single-threaded */
    int last;
    do {
        unsigned type;
        const char *why;
        last = (int)take(z, 1);
        type = take(z, 2);
        if (overrun(z)) return "truncated";
        why = type == 0 ? stored(z) : type == 1 ? fixed(z, &lit, &dist) : type == 2 ? dynamic(z, &lit, &dist)
                                                                              : "a block of the reserved type 3";
        if (why) return why;
    } while (!last);
    return NULL;
}

int zlib_inflate(const unsigned char *in, size_t n, unsigned char *out, size_t cap, const char **why)
{
    inflater z;
    size_t end;
    if (n < 6) return *why = "truncated zlib stream", 1;
    if ((in[0] & 15) != 8 || in[0] >> 4 > 7 || (in[0] << 8 | in[1]) % 31 != 0 || (in[1] & 0x20))
        return *why = "not a zlib stream of deflate data (bad header)", 1;
    memset(&z, 0, sizeof z);
    z.in = in + 2;
    z.n = n - 2;
    z.out = out;
    z.cap = cap;
    if ((*why = blocks(&z))) return 1;
    end = z.pos - (size_t)((z.count - z.pad) / 8);   /* unused whole bytes go back */
    if (z.len != cap) return *why = "less data than expected", 1;
    if (z.n - end < 4) return *why = "truncated (no Adler-32 after the data)", 1;
    if (adler32(out, cap) != ((uint32_t)z.in[end] << 24 | (uint32_t)z.in[end + 1] << 16 | (uint32_t)z.in[end + 2] << 8 | z.in[end + 3]))
        return *why = "the Adler-32 checksum does not match the data", 1;
    return 0;
}
