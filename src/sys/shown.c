/* shown.c — names made safe to print (see shown.h). */
#include "sys/shown.h"
#include <stdio.h>
#include <string.h>

/* The length of the UTF-8 sequence at s (2 to 4 bytes, no overlong form, no surrogate, at most
 * U+10FFFF), or 0 if it is not one; *cp its code point. */
static int utf8_sequence(const unsigned char *s, unsigned long *cp)
{
    int n = s[0] >= 0xF0 ? 4 : s[0] >= 0xE0 ? 3 : s[0] >= 0xC0 ? 2 : 0, k;
    unsigned long c, min = n == 4 ? 0x10000 : n == 3 ? 0x800 : 0x80;
    if (!n || s[0] > 0xF4) return 0;
    c = s[0] & (0x7F >> n);
    for (k = 1; k < n; k++) {
        if ((s[k] & 0xC0) != 0x80) return 0;
        c = c << 6 | (s[k] & 0x3F);
    }
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
    *cp = c;
    return n;
}

/* 1 for the code points that reorder text (bidirectional controls) or are C1 controls. */
static int hidden_code_point(unsigned long c)
{
    return c < 0xA0 || c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) ||
           (c >= 0x2066 && c <= 0x2069);
}

/* The escape of the character at s into e[16] (e[0] = 0 when it is printed as it is); its length in bytes. */
static int escape_one(const unsigned char *s, char e[16])
{
    unsigned long cp;
    int n;
    e[0] = '\0';
    if (*s == '\\') { snprintf(e, 16, "\\\\"); return 1; }
    if (*s < 0x20 || *s == 0x7F) { snprintf(e, 16, "\\x%02x", *s); return 1; }
    if (*s < 0x80) return 1;
    n = utf8_sequence(s, &cp);
    if (!n) { snprintf(e, 16, "\\x%02x", *s); return 1; }
    if (hidden_code_point(cp)) snprintf(e, 16, cp < 0x100 ? "\\x%02lx" : "\\u%04lx", cp);
    return n;
}

/* name with its escapes into out[cap] (cut to fit, ending "..."); the length written. */
static size_t shown_into(char *out, size_t cap, const char *name)
{
    const unsigned char *s = (const unsigned char *)name;
    size_t used = 0;
    char e[16];
    if (!cap) return 0;
    while (*s) {
        int n = escape_one(s, e);
        size_t len = e[0] ? strlen(e) : (size_t)n;
        if (used + len + 4 > cap) {   /* cut: room for "..." and the NUL */
            used += (size_t)snprintf(out + used, cap - used, "%s", used + 4 <= cap ? "..." : "");
            return used;
        }
        memcpy(out + used, e[0] ? e : (const char *)s, len);
        used += len;
        s += n;
    }
    out[used] = '\0';
    return used;
}

const char *shown(const char *name)
{
    static char ring[SHOWN_RING][SHOWN_CAP];
    static unsigned next;
    const unsigned char *s;
    char e[16], *out;
    int n;
    if (!name) return "(null)";
    for (s = (const unsigned char *)name; *s; s += n)
        if ((n = escape_one(s, e)), e[0]) break;
    if (!*s) return name;   /* plain text: as it is */
    out = ring[next++ % SHOWN_RING];
    shown_into(out, sizeof ring[0], name);
    return out;
}
