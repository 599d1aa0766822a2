/* help.c — help texts with the strategy-name tables expanded (help.h). */
#include "cmd/help.h"
#include <string.h>
#include "tracer/integrator.h"
#include "tracer/light.h"
#include "sampler/sampler.h"

typedef struct { const char *key; const char *const *names; } name_table;

static const name_table TABLES[] = {
    {"light", LIGHT_STRATEGY_NAMES}, {"dir", DIR_STRATEGY_NAMES}, {"direct", DIRECT_STRATEGY_NAMES},
    {"sampler", SAMPLER_NAMES}};

/* If text starts with {KEY|} or {KEY }, prints the table's names joined by that character and
 * returns the length of the token; else 0. */
static size_t expand(FILE *f, const char *text)
{
    size_t t, n, i;
    for (t = 0; t < sizeof TABLES / sizeof TABLES[0]; t++) {
        n = strlen(TABLES[t].key);
        if (text[0] != '{' || strncmp(text + 1, TABLES[t].key, n) || (text[n + 1] != '|' && text[n + 1] != ' ')
            || text[n + 2] != '}')
            continue;
        for (i = 0; TABLES[t].names[i]; i++) {
            if (i) fputc(text[n + 1], f);
            fputs(TABLES[t].names[i], f);
        }
        return n + 3;
    }
    return 0;
}

void help_print(FILE *f, const char *text)
{
    while (*text) {
        size_t used = expand(f, text);
        if (used) text += used;
        else fputc(*text++, f);
    }
}
