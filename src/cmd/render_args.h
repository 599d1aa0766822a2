/* render_args.h — the flags of `pathlab render`, shared with `pathlab compare` (one set per
 * estimator): their defaults, their cli_flag table, one flag at a time, and the camera they describe
 * (made by files/view_setup.h). */
#ifndef PATHLAB_RENDER_ARGS_H
#define PATHLAB_RENDER_ARGS_H
#include "util/cli.h"
#include "render/adaptive.h"
#include "render/render.h"
#include "files/view_setup.h"

typedef struct {
    const char *cmd;                 /* the command, in messages: "render" (set by render_args_init) */
    const cli_flag *more_flags;      /* the calling command's own flags, for "did you mean" (or NULL) */
    const char *scene, *out, *variance;
    float exposure;
    view_setup cam;                  /* the camera flags and files, and the view made of them */
    int spp;                         /* --spp N: the samples the image is to hold (16 if not given) */
    int64_t samples[2];              /* --samples A:B: the sample indices A .. B - 1 */
    int spp_given, samples_given, resume;
    int sampler_given;               /* --sampler given (else the plan picks one: render_plan_default_sampler) */
    render_opts ro;                  /* the other flags' values (ro.first, ro.spp: see render_plan) */
    scene_opts so;                   /* --mtl, --texture-decode, and --material's model (also in ro.io) */
    /* render only (cmd/render_adaptive.h): adaptive sampling */
    int adaptive, target_given, pilot_given, min_given;
    const char *sample_count;        /* --sample-count FILE.pfm (NULL if not given) */
    adaptive_opts ao;
} render_args;

#define RENDER_NFLAGS 36   /* the flags of render_flag_table, and its closing NULL entry */

/* The defaults of pathlab render (16 spp, seed 1, every core, area, brdf, mis-power, 0:inf, rr 3;
 * ro.sampler independent, which is compare's default: render's plan picks its own when --sampler is
 * not given, render_plan). */
void render_args_init(render_args *a);
/* Fills t with render's flags, each writing into *a; parse them with cli_parse(..., ctx = a, ...). */
void render_flag_table(render_args *a, cli_flag t[RENDER_NFLAGS]);
/* One argument argv[*i]: a flag of the table (advancing *i past its value), or a word, which is the
 * scene. 0 if understood and valid, else 1 after printing why. */
int render_parse_flag(render_args *a, int argc, char **argv, int *i);
/* The camera flags that cannot make a camera whatever the scene (--fov out of (0, 180), --up 0,0,0,
 * --eye equal to --target, --up along the view): checked before the scene loads. 0, or 1 after
 * printing why, naming the flag. */
int render_check_camera_flags(const render_args *a);
/* The view: --orbiter FILE, --view FILE or else SCENE.view if it exists, then the camera flags on top,
 * then framing for what is left; the camera made of it (view_setup_write writes it to --write-view,
 * after the images). 0, or 1 after printing why. */
int render_make_camera(render_args *a, const scene *s, camera *cam);
#endif
