/* cli.h — strict parsing of flag values: every error names the flag and the value, for a student. */
#ifndef PATHLAB_CLI_H
#define PATHLAB_CLI_H
#include <stdint.h>
#include "tracer/render.h"
#include "math/vec.h"

/* Each returns 0 on success, or prints "pathlab: FLAG expects ..., got 'VALUE'" and returns 1. */
int cli_int(const char *flag, const char *s, int lo, int hi, int *out);
int cli_u64(const char *flag, const char *s, uint64_t *out);
int cli_float(const char *flag, const char *s, float *out);
int cli_vec3(const char *flag, const char *s, vec3 *out);
int cli_size(const char *flag, const char *s, int *w, int *h);
/* One of the names in a NULL-terminated list; *out is its index. */
int cli_choice(const char *flag, const char *s, const char *const *names, int *out);
int cli_double(const char *flag, const char *s, double lo, double hi, double *out);
/* The value after argv[*i], advancing *i; prints an error and returns NULL if missing. */
const char *cli_value(int argc, char **argv, int *i);

/* A command's flags as a table, parsed by cli_parse: every command reads its arguments this way.
 * kind says what the value is and what `dest` points to:
 *   CLI_SWITCH  no value; int *dest = 1          CLI_STRING  const char **dest = the word
 *   CLI_INT     int *dest in [lo, hi]            CLI_U64     uint64_t *dest
 *   CLI_FLOAT   float *dest (finite)             CLI_DOUBLE  double *dest in [lo, hi]
 *   CLI_VEC3    vec3 *dest from "x,y,z"          CLI_SIZE    int dest[2] from "WxH"
 *   CLI_CHOICE  int *dest = the index of the value in `choices` (NULL-terminated)
 *   CLI_CUSTOM  custom(ctx, flag, value) parses the value itself (0 on success, else 1 after printing why)
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

/* The arguments argv[1..argc-1] of command `cmd` ("render", "diff"...): flags of the table (a flag
 * may appear in several tables: the first match wins), and up to max_words other words (file names),
 * stored in words[] and counted in *nwords. A word is anything not starting with '-', or "-" alone.
 * Returns 0, or 1 after printing what is wrong (unknown flag, missing or bad value, extra word). */
int cli_parse(const char *cmd, int argc, char **argv, const cli_flag *const *tables, void *ctx,
              const char **words, int max_words, int *nwords);

/* The flags of `pathlab render`, shared with `pathlab compare` (one set per estimator). */
typedef struct {
    const char *scene, *out, *variance;
    float exposure;
    view vw, flags;                  /* flags: values given on the command line */
    int eye, target, up, fov, size;  /* which camera flags were given */
    render_opts ro;
} render_args;

/* The defaults of pathlab render (16 spp, seed 1, every core, area, brdf, mis-power, 0:inf, rr 3). */
void render_args_init(render_args *a);
/* One flag at argv[*i] (advancing *i past its value); a word without '-' is the scene.
 * 0 if understood and valid, else 1 after printing why. */
int render_parse_flag(render_args *a, int argc, char **argv, int *i);
/* The view: SCENE.view if it exists, then the camera flags on top, then framing for what is left. */
int render_make_camera(render_args *a, const scene *s, camera *cam);
/* ".pfm" of "dir/x.pfm", "" without an extension. */
const char *path_extension(const char *path);
#endif
