/* cli.h — a command's arguments: its flags as a table read by cli_parse, and strict parsers of
 * flag values. Every error names the command, the flag and the value, for a student:
 *   pathlab render: --spp expects a whole number from 1 to 1073741824, got 'abc'
 * Every command reads its arguments with cli_parse. */
#ifndef PATHLAB_CLI_H
#define PATHLAB_CLI_H
#include <stddef.h>
#include <stdio.h>
#include <stdint.h>
#include "math/vec.h"

/* A flag of a table. kind says what the value is and what `dest` points to:
 *   CLI_SWITCH  no value; int *dest = 1          CLI_STRING  const char **dest = the word
 *   CLI_INT     int *dest in [lo, hi]            CLI_U64     uint64_t *dest
 *   CLI_FLOAT   float *dest (finite)             CLI_DOUBLE  double *dest in [lo, hi]
 *   CLI_VEC3    vec3 *dest from "x,y,z"          CLI_SIZE    int dest[2] from "WxH"
 *   CLI_CHOICE  int *dest = the index of the value in `choices` (NULL-terminated)
 *   CLI_CUSTOM  custom(ctx, flag, value) parses the value itself (0 on success, else 1 after printing why);
 *               its `choices`, if set, are the values it takes (listed for the shell's completion)
 * If `given` is not NULL, *given is set to 1 when the flag appears. A table ends with a NULL name. */
typedef enum { CLI_SWITCH, CLI_STRING, CLI_INT, CLI_U64, CLI_FLOAT, CLI_DOUBLE, CLI_VEC3, CLI_SIZE, CLI_CHOICE, CLI_CUSTOM } cli_kind;
typedef struct {
    const char *name;
    cli_kind kind;
    void *dest;
    double lo, hi;
    const char *const *choices;
    int (*custom)(void *ctx, const char *flag, const char *value);
    int *given;
} cli_flag;

/* The arguments argv[1..argc-1] of command `cmd` ("render", "diff"...): flags of the tables (a flag
 * may appear in several tables: the first match wins), and up to max_words words (file names),
 * stored in words[] and counted in *nwords. Flags and words come in any order; a flag's value is
 * the next argument whatever it starts with (--eye -1,0,0), or follows '=' (--spp=64). After "--" every
 * argument is a word (a student's file named -x.pfm). Returns 0, or 1 after printing what is
 * wrong (unknown flag, missing or bad value, one word too many). */
int cli_parse(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
              const char **words, int max_words, int *nwords);
/* The same, but a flag given twice is an error (with cli_parse the last one wins): for a command
 * whose words are students' files, expanded by the shell (grade's *.pfm), where a file named
 * --ref=x.pfm would otherwise replace the teacher's flag. */
int cli_parse_once(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
                   const char **words, int max_words, int *nwords);
/* The flag argv[*i] of the tables and its value, leaving *i on the last argument used; 0 or 1 as cli_parse. */
int cli_parse_flag(const char *cmd, int argc, char **argv, int *i, const cli_flag *const *tables, void *ctx);
/* The value of flag f, stored as f says (CLI_CUSTOM gets ctx); 0, or 1 after printing why. */
int cli_parse_value(const char *cmd, const cli_flag *f, const char *value, void *ctx);
/* For the shell's completion (util/commands.h): cli_list_flags(f) makes cli_parse and cli_parse_flag
 * write each flag of their tables on a line of f ("--dir uniform cosine brdf": the flag, then its
 * values when it takes one of a list) and return 1 without parsing; cli_list_flags(NULL) ends it.
 * cli_listing() says whether it is on. */
void cli_list_flags(FILE *f);
int cli_listing(void);
/* 1 if arg is the flag `name`, alone or as name=value. */
int cli_flag_is(const char *arg, const char *name);
/* For "did you mean": if name is close enough to what the user typed (word, leading dashes aside) and
 * closer than *best (NULL at first), sets *best = name and *best_d to its distance. */
void cli_consider(const char *word, const char *name, const char **best, int *best_d);
/* A value that is none of names (NULL-terminated): prints "pathlab CMD: FLAG expects one of a, b, c,
 * got 'VALUE'; did you mean b?" (the closest name, if one is close enough); returns 1. For CLI_CHOICE
 * and for the parsers of their own whose value is one of a list. */
int cli_fail_choice(const char *cmd, const char *flag, const char *value, const char *const *names);
/* 1 if arg is a word, not a flag: it does not start with '-', or it is "-" alone. */
int cli_is_word(const char *arg);
/* Prints "pathlab CMD: FLAG expects WHAT, got 'VALUE'" ("pathlab: ..." if cmd is NULL); returns 1. */
int cli_fail(const char *cmd, const char *flag, const char *what, const char *value);

#endif
