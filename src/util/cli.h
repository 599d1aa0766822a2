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
/* The value after argv[*i], advancing *i; prints an error and returns NULL if missing. */
const char *cli_value(int argc, char **argv, int *i);

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
