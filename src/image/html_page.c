/* html_page.c — writes the viewer's page (html_page.h): the HTML skeleton, the embedded style and
 * script (web/viewer.css, web/viewer.js, compiled in by tools/embed.c), the page's settings as JSON
 * and each image as little-endian half floats in base64. Half floats keep 11 significant bits
 * (relative error <= 2^-11, about 5e-4), enough for a viewer, at a third of the size of text numbers.
 * Variances travel as standard deviations, which stay in the half-float range far further down. */
#include "image/html_page.h"
#include "sys/shown.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "math/sha256.h"
#include "sys/atomic_file.h"

extern const unsigned char pathlab_viewer_js[], pathlab_viewer_css[];   /* $(BUILD)/gen/web_assets.c */

/* The nearest half float (round to nearest even); beyond 65504 it is infinite, NaN stays NaN. */
static uint16_t half_of(float f)
{
    uint32_t u, sign, mant;
    int exp;
    memcpy(&u, &f, 4);
    sign = (u >> 16) & 0x8000u;
    exp = (int)((u >> 23) & 0xff) - 127 + 15;
    mant = u & 0x7fffffu;
    if (((u >> 23) & 0xff) == 0xff) return (uint16_t)(sign | 0x7c00u | (mant ? 0x200u : 0));
    if (exp >= 31) return (uint16_t)(sign | 0x7c00u);
    if (exp <= 0) {   /* a subnormal half, or zero: the implicit 1 shifted in */
        int shift = 14 - exp;
        uint32_t m = mant | 0x800000u, h, rest;
        if (shift > 24) return (uint16_t)sign;
        h = m >> shift;
        rest = m & ((1u << shift) - 1);
        if (rest > (1u << (shift - 1)) || (rest == (1u << (shift - 1)) && (h & 1))) h++;
        return (uint16_t)(sign | h);
    }
    {   /* normal: the carry of the rounding may move into the exponent, which is right */
        uint32_t h = ((uint32_t)exp << 10) | (mant >> 13), rest = mant & 0x1fffu;
        if (rest > 0x1000u || (rest == 0x1000u && (h & 1))) h++;
        return (uint16_t)(sign | h);
    }
}

/* n (1 to 3) bytes as 4 characters of base64, '=' for the missing ones. */
static void b64_group(char out[4], const unsigned char *b, int n)
{
    static const char B64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    unsigned w = (unsigned)b[0] << 16 | (n > 1 ? (unsigned)b[1] << 8 : 0) | (n > 2 ? b[2] : 0);
    out[0] = B64[w >> 18 & 63];
    out[1] = B64[w >> 12 & 63];
    out[2] = n > 1 ? B64[w >> 6 & 63] : '=';
    out[3] = n > 2 ? B64[w & 63] : '=';
}

/* Writes n values (3 per pixel), each as a little-endian half, in base64 lines of 76 characters;
 * the square root of each when sd (a variance). */
static void write_halves(FILE *f, const float *v, long n, int sd)
{
    unsigned char buf[3];
    char quad[4];
    long nbytes = 2 * n, k;
    int used = 0;
    for (k = 0; k < nbytes; k++) {
        float x = v[k / 2];
        uint16_t h = half_of(sd ? sqrtf(fmaxf(x, 0.0f)) : x);
        buf[used++] = (unsigned char)(k % 2 ? h >> 8 : h & 0xff);
        if (used == 3 || k == nbytes - 1) {
            b64_group(quad, buf, used);
            fwrite(quad, 1, 4, f);
            used = 0;
            if (k % 57 == 56) putc('\n', f);
        }
    }
}

/* The base 85 digits of the compact pages: '#' (35) to '~' (126) without < > & \ (no "</script" can
 * appear, no entity), the first 85 of them; web/viewer.js holds the same string. */
static const char B85[] = "#$%'()*+,-./0123456789:;=?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[]^_`abcdefghijklmnopqrstuvwxyz{";

/* One pixel as RGBE (Ward): the exponent of the largest channel, mantissas truncated; read back as
 * (m + 0.5) 2^(e - 136), within half a step. Negative and NaN values as 0, beyond 2^127 as the largest. */
static void rgbe_of(const float *v, unsigned char out[4])
{
    double c[3], m;
    int e, k;
    for (k = 0; k < 3; k++) c[k] = v[k] > 0.0f ? fmin(v[k], 1e38) : 0.0;
    m = fmax(c[0], fmax(c[1], c[2]));
    if (m < 1e-38) { out[0] = out[1] = out[2] = out[3] = 0; return; }
    frexp(m, &e);
    for (k = 0; k < 3; k++) out[k] = (unsigned char)fmin(255.0, ldexp(c[k], 8 - e));
    out[3] = (unsigned char)(e + 128);
}

/* n pixels as RGBE in base 85: each 4 bytes (big-endian) as 5 digits, a line break every 80 pixels. */
static void write_rgbe85(FILE *f, const float *v, long n)
{
    long p;
    for (p = 0; p < n; p++) {
        unsigned char b[4];
        unsigned long w;
        char d[5];
        int k;
        rgbe_of(&v[3 * p], b);
        w = (unsigned long)b[0] << 24 | (unsigned long)b[1] << 16 | (unsigned long)b[2] << 8 | b[3];
        for (k = 4; k >= 0; k--, w /= 85) d[k] = B85[w % 85];
        fwrite(d, 1, 5, f);
        if (p % 80 == 79) putc('\n', f);
    }
}

/* 1 when the page's images in half floats (base 64) would take more than page->max_bytes. */
static int compact_page(const html_page *page, const html_image **all, int n)
{
    double bytes = 0.0;
    int i;
    for (i = 0; i < n; i++) bytes += (all[i]->var ? 2.0 : 1.0) * 8.0 * all[i]->img->w * all[i]->img->h;
    return page->max_bytes > 0 && bytes > (double)page->max_bytes;
}

char *html_data_uri(const char *mime, const void *bytes, size_t n)
{
    const unsigned char *b = bytes;
    size_t head = strlen("data:;base64,") + strlen(mime), i;
    char *uri = malloc(head + 4 * ((n + 2) / 3) + 1), *o;
    if (!uri) return NULL;
    o = uri + sprintf(uri, "data:%s;base64,", mime);
    for (i = 0; i < n; i += 3, o += 4) b64_group(o, b + i, n - i < 3 ? (int)(n - i) : 3);
    *o = 0;
    return uri;
}

/* A JSON string (or null), with < written \u003c so that "</script>" never appears in the page. */
static void json_string(FILE *f, const char *s)
{
    if (!s) { fputs("null", f); return; }
    s = shown(s);   /* no control or bidirectional character reaches the page: a name shows as itself */
    putc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20 || c == '<' || c == '>' || c == '&') fprintf(f, "\\u%04x", c);
        else putc(c, f);
    }
    putc('"', f);
}

/* Every image of the page in one list: the images, the reference, the strip; n of them in *n. */
static const html_image **all_images(const html_page *p, int *n)
{
    const html_image **all = malloc(sizeof *all * (size_t)(p->nimages + p->nstrip + 1));
    int i, k = 0;
    if (!all) return NULL;
    for (i = 0; i < p->nimages; i++) all[k++] = &p->images[i];
    if (p->ref) all[k++] = p->ref;
    for (i = 0; i < p->nstrip; i++) all[k++] = &p->strip[i];
    *n = k;
    return all;
}

/* 0 if every image (and variance) is as large as the first; else 1 after naming both sizes. */
static int check_sizes(const char *path, const html_image **all, int n)
{
    int i, w = all[0]->img->w, h = all[0]->img->h;
    for (i = 0; i < n; i++) {
        const image *v = all[i]->var;
        if (all[i]->img->w != w || all[i]->img->h != h || (v && (v->w != w || v->h != h))) {
            const image *bad = all[i]->img->w != w || all[i]->img->h != h ? all[i]->img : v;
            fprintf(stderr, "%s: %s%s is %dx%d, %s is %dx%d: a page shows images of one size\n", shown(path), shown(all[i]->name),
                    bad == v ? "'s variance" : "", bad->w, bad->h, shown(all[0]->name), w, h);
            return 1;
        }
    }
    return 0;
}

/* One image's entry of the settings: its name, link, the ids of its data and their encoding. */
static void json_image(FILE *f, const html_image *im, int id, int compact)
{
    fputs("{\"name\":", f);
    json_string(f, im->name);
    fputs(",\"link\":", f);
    json_string(f, im->link);
    fprintf(f, ",\"enc\":\"%s\",\"rgb\":\"pathlab-rgb-%d\",\"sd\":", compact ? "rgbe85" : "half", id);
    if (im->var && !compact) fprintf(f, "\"pathlab-sd-%d\"}", id);
    else fputs("null}", f);
}

/* The settings: {"title", "w", "h", "images":[...], "ref", "strip":[...], "marks":[...]}. */
static void write_settings(FILE *f, const html_page *p, int compact)
{
    int i, id = 0;
    fprintf(f, "<script type=\"application/json\" id=\"pathlab-settings\">{\"title\":");
    json_string(f, p->title);
    fprintf(f, ",\"w\":%d,\"h\":%d,\"images\":[", p->images[0].img->w, p->images[0].img->h);
    for (i = 0; i < p->nimages; i++, id++) { if (i) putc(',', f); json_image(f, &p->images[i], id, compact); }
    fputs("],\"ref\":", f);
    if (p->ref) json_image(f, p->ref, id++, compact);
    else fputs("null", f);
    fputs(",\"strip\":[", f);
    for (i = 0; i < p->nstrip; i++, id++) { if (i) putc(',', f); json_image(f, &p->strip[i], id, compact); }
    fputs("],\"marks\":[", f);
    for (i = 0; i < p->nmarks; i++) {
        const html_mark *m = &p->marks[i];
        fprintf(f, "%s{\"x\":%d,\"y\":%d,\"w\":%d,\"h\":%d,\"label\":", i ? "," : "", m->x, m->y, m->w, m->h);
        json_string(f, m->label);
        putc('}', f);
    }
    fputs("]}</script>\n", f);
}

/* The text of the page's one script element, "\n" + web/viewer.js, as its Content-Security-Policy
 * hashes it: 'sha256-' and the base64 of its SHA-256, into out[64]. */
static void script_hash(char out[64])
{
    unsigned char d[33];
    sha256_ctx c;
    int i;
    sha256_init(&c);
    sha256_update(&c, "\n", 1);
    sha256_update(&c, pathlab_viewer_js, strlen((const char *)pathlab_viewer_js));
    sha256_final(&c, d);
    d[32] = 0;
    memcpy(out, "'sha256-", 8);
    for (i = 0; i < 33; i += 3) b64_group(out + 8 + 4 * i / 3, d + i, i + 3 <= 32 ? 3 : 32 - i);
    memcpy(out + 52, "'", 2);
}

/* The page itself, into f. Its Content-Security-Policy runs no script but the viewer's (by its
 * hash: nothing a name or a title could inject runs), loads nothing from anywhere, and allows no
 * <base> and no form. */
static void write_page(FILE *f, const html_page *p, const html_image **all, int n)
{
    char *title = html_escape(p->title ? p->title : "pathlab"), hash[64];
    int i, compact = compact_page(p, all, n);
    script_hash(hash);
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
               "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src %s; "
               "style-src 'unsafe-inline'; img-src data: blob:; base-uri 'none'; form-action 'none'\">\n<title>%s</title>\n"
               "<style>\n%s</style>\n</head><body>\n", hash, title ? title : "pathlab", (const char *)pathlab_viewer_css);
    free(title);
    if (p->before_html) fprintf(f, "%s\n", p->before_html);
    fputs("<div id=\"pathlab-viewer\"></div>\n", f);
    if (p->after_html) fprintf(f, "%s\n", p->after_html);
    write_settings(f, p, compact);
    for (i = 0; i < n; i++) {
        long count = 3L * all[i]->img->w * all[i]->img->h;
        fprintf(f, "<script type=\"application/octet-stream\" id=\"pathlab-rgb-%d\">\n", i);
        if (compact) write_rgbe85(f, all[i]->img->px, count / 3);
        else write_halves(f, all[i]->img->px, count, 0);
        fputs("</script>\n", f);
        if (!all[i]->var || compact) continue;
        fprintf(f, "<script type=\"application/octet-stream\" id=\"pathlab-sd-%d\">\n", i);
        write_halves(f, all[i]->var->px, count, 1);
        fputs("</script>\n", f);
    }
    fprintf(f, "<script>\n%s</script>\n</body></html>\n", (const char *)pathlab_viewer_js);
}

int html_page_write(const char *path, const html_page *page)
{
    int n = 0;
    char *tmp;
    FILE *f;
    const html_image **all;
    if (page->nimages < 1) { fprintf(stderr, "%s: a page needs an image\n", shown(path)); return 1; }
    all = all_images(page, &n);
    if (!all) { fprintf(stderr, "%s: out of memory\n", shown(path)); return 1; }
    if (check_sizes(path, all, n)) { free(all); return 1; }
    f = atomic_file_open(path, &tmp);
    if (!f) { free(all); return 1; }
    write_page(f, page, all, n);
    free(all);
    return atomic_file_close(f, tmp, path, 1);   /* a failed write (a full disk) is found there and said, with its reason */
}

char *html_escape(const char *text)
{
    size_t n = 1;
    const char *s;
    char *out, *o;
    text = shown(text);   /* control and bidirectional characters as visible escapes (sys/shown.h) */
    for (s = text; *s; s++) n += strchr("&<>\"'", *s) ? 6 : 1;
    out = o = malloc(n);
    if (!out) return NULL;
    for (s = text; *s; s++) {
        switch (*s) {
        case '&': o += sprintf(o, "&amp;"); break;
        case '<': o += sprintf(o, "&lt;"); break;
        case '>': o += sprintf(o, "&gt;"); break;
        case '"': o += sprintf(o, "&quot;"); break;
        case '\'': o += sprintf(o, "&#39;"); break;
        default: *o++ = *s;
        }
    }
    *o = 0;
    return out;
}

int html_put_escaped(FILE *f, const char *text)
{
    char *e = html_escape(text);
    if (!e) return 1;
    fputs(e, f);
    free(e);
    return 0;
}
