/* render_cmd.c — pathlab render: flags, scene, camera, render, image files. */
#include "cmd/render_cmd.h"
#include <stdio.h>
#include <string.h>
#include "cmd/render_args.h"

/* The flags, then what render needs beyond valid values: a scene, an output it can write, a last
 * bounce for --split. 0, or 1 after printing why. */
static int parse_render_args(render_args *a, int argc, char **argv)
{
    cli_flag t[RENDER_NFLAGS];
    const cli_flag *tables[2];
    const char *words[1];
    int nwords;
    render_args_init(a);
    render_flag_table(a, t);
    tables[0] = t;
    tables[1] = NULL;
    if (cli_parse("render", argc, argv, tables, a, words, 1, &nwords)) return 1;
    a->scene = nwords ? words[0] : NULL;
    if (!a->scene) { fprintf(stderr, "pathlab render: needs a scene: pathlab render SCENE.obj -o FILE\n"); return 1; }
    if (!a->out) { fprintf(stderr, "pathlab render: needs an output: -o FILE.pfm, -o FILE.ppm or -o FILE.png\n"); return 1; }
    if (img_format_of(a->out) == IMG_UNKNOWN) {
        fprintf(stderr, "pathlab render: -o %s: unknown image format (use .pfm, .ppm or .png)\n", a->out);
        return 1;
    }
    if (a->variance && img_format_of(a->variance) != IMG_PFM) {
        fprintf(stderr, "pathlab render: --variance %s: the variance is written as .pfm\n", a->variance);
        return 1;
    }
    if (a->ro.split && a->ro.io.bmax == BOUNCES_INF) {
        fprintf(stderr, "pathlab render: --split needs a last bounce, e.g. --bounces 0:8\n");
        return 1;
    }
    return 0;
}

/* out.pfm -> out_L3.pfm */
static void bounce_path(char *dst, size_t cap, const char *out, int k)
{
    const char *e = img_extension(out);
    snprintf(dst, cap, "%.*s_L%d%s", (int)(strlen(out) - strlen(e)), out, k, e);
}

static int write_outputs(const render_args *a, const render_result *r)
{
    char path[4096];
    int k, err = img_write(&r->mean[0], a->out, a->exposure);
    for (k = 1; k < r->nlayers && !err; k++) {
        bounce_path(path, sizeof path, a->out, a->ro.io.bmin + k - 1);
        err = img_write(&r->mean[k], path, a->exposure);
    }
    if (a->variance && !err) err = img_write(&r->var[0], a->variance, 0.0f);
    for (k = 1; k < r->nlayers && a->variance && !err; k++) {
        bounce_path(path, sizeof path, a->variance, a->ro.io.bmin + k - 1);
        err = img_write(&r->var[k], path, 0.0f);
    }
    return err;
}

int render_main(int argc, char **argv)
{
    render_args a;
    scene s;
    camera cam;
    render_result r;
    int err;
    if (parse_render_args(&a, argc, argv)) return 2;
    if (scene_load(&s, a.scene, a.ro.threads, a.ro.quiet)) return 2;
    if (!a.ro.quiet)
        fprintf(stderr, "%s: %d triangles (%d degenerate dropped), %d emitting, %d materials; loaded in %.0f ms, BVH in %.0f ms\n",
                a.scene, s.m.ntris, s.m.ndegenerate, s.lights.n, s.m.nmats - 1, 1e3 * s.load_seconds, 1e3 * s.bvh_seconds);
    if (render_make_camera(&a, &s, &cam)) { scene_free(&s); return 2; }
    if (s.lights.n == 0)
        fprintf(stderr, "pathlab render: warning: %s has no emitters (no material with Ke > 0): the image is black\n", a.scene);
    if (render(&s, &cam, &a.ro, &r)) { scene_free(&s); return 1; }
    if (!a.ro.quiet) render_print_stats(&r, a.ro.spp, cam.width * cam.height);
    err = write_outputs(&a, &r);
    render_result_free(&r);
    scene_free(&s);
    return err ? 1 : 0;
}
