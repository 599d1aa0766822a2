/* main.c — pathlab's command line: `pathlab render SCENE.obj [flags] -o FILE`, `pathlab bench-rays`. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "cmd/bench_rays.h"
#include "check/command.h"
#include "util/cli.h"
#include "cmd/compare.h"
#include "cmd/diff.h"
#include "cmd/grade.h"
#include "tracer/render.h"

static const char *USAGE =
    "pathlab — a teaching path tracer (see README.md)\n"
    "\n"
    "usage:\n"
    "  pathlab render SCENE.obj [flags] -o FILE.pfm|FILE.ppm|FILE.png\n"
    "  pathlab bench-rays MESH.obj [-r RES] [-t THREADS]\n"
    "  pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]\n"
    "  pathlab diff A.pfm REF.pfm [--heatmap OUT.ppm|OUT.png] [--scale S]\n"
    "                heatmap of |A - REF|: black 0 to white S (default: the largest difference, so\n"
    "                give the same --scale to compare two heatmaps)\n"
    "  pathlab grade IMAGE.pfm --ref REF.pfm [--alpha A] [--block B] [--heatmap OUT.ppm|OUT.png]\n"
    "                [--spp N] [--var REF_VAR.pfm --ref-spp M]   is IMAGE - REF noise or bias? (below)\n"
    COMPARE_USAGE
    "  pathlab convert IN.pfm OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS]   view a PFM (e.g. a --split layer);\n"
    "                prints the size and each channel's mean, min and max\n"
    "  pathlab help\n"
    "\n"
    "render flags:\n"
    "  -o FILE              output image; .pfm (linear float), .ppm or .png (8-bit sRGB)\n"
    "  --spp N              samples per pixel (default 16)\n"
    "  --seed S             random seed (default 1); same seed, same image, any thread count\n"
    "  --threads N          worker threads (default: every core)\n"
    "  --quiet              no progress bar and no stats line\n"
    "  --exposure STOPS     PPM and PNG: multiply by 2^STOPS before the sRGB curve (default 0)\n"
    "camera (defaults from SCENE.view, else framing the whole scene):\n"
    "  --eye X,Y,Z  --target X,Y,Z  --up X,Y,Z  --fov DEGREES (vertical)  --size WxH\n"
    "  --pixel-center       shoot through pixel centres instead of jittering in the pixel\n"
    "light transport (L_k = light that reached the eye after exactly k reflections):\n"
    "  --bounces A:B        render L_A + ... + L_B; B may be inf (default 0:inf)\n"
    "  --bounce K           the same as --bounces K:K\n"
    "  --split              also write one image per bounce: FILE_L0.pfm, FILE_L1.pfm, ...\n"
    "  --light area|triangle|power|solid-angle   how a point s on a light is chosen (default area)\n"
    "  --dir uniform|cosine|brdf        how a direction is chosen at a surface (default brdf)\n"
    "  --direct light|brdf|mis-balance|mis-power   the estimator of direct light (default mis-power)\n"
    "  --rr D|off           Russian roulette after D bounces (default 3)\n"
    "  --variance FILE.pfm  also write the variance of each pixel's mean (with --split, one per bounce too)\n";

/* C99 compilers need only take string literals of 4095 characters: the help is in two parts. */
static const char *USAGE_TOOLS =
    "grade (exit 0 pass, 1 fail, 2 bad input), on d = IMAGE - REF per pixel-channel, at family-wise level alpha\n"
    "(default 0.01; alpha/2 to each family, Sidak within it); the noise is estimated from the scatter of d:\n"
    "  whole image  z of the mean of d, per channel: catches a bias spread everywhere (all 2 percent too bright)\n"
    "  blocks       Student t of the mean of d over each B x B block (default max(8, min(w,h)/16)), per channel:\n"
    "               averaging shrinks noise, not bias; prints where the significant blocks are, brighter or darker\n"
    "  --var        with --spp and --ref-spp, a per-pixel Z-test assuming the reference's estimator (information only)\n"
    "  --heatmap    the reference in grey, significantly brighter blocks red, darker blue\n"
    COMPARE_HELP;

static int image_extension_ok(const char *path, int pfm_only)
{
    const char *e = path_extension(path);
    return !strcmp(e, ".pfm") || !strcmp(e, ".PFM")
           || (!pfm_only && (!strcmp(e, ".ppm") || !strcmp(e, ".PPM") || !strcmp(e, ".png") || !strcmp(e, ".PNG")));
}

static int parse_render_args(render_args *a, int argc, char **argv)
{
    int i;
    render_args_init(a);
    for (i = 1; i < argc; i++)
        if (render_parse_flag(a, argc, argv, &i)) return 1;
    if (!a->scene) { fprintf(stderr, "pathlab: render needs a scene: pathlab render SCENE.obj -o FILE\n"); return 1; }
    if (!a->out) { fprintf(stderr, "pathlab: render needs an output: -o FILE.pfm or -o FILE.ppm\n"); return 1; }
    if (!image_extension_ok(a->out, 0)) { fprintf(stderr, "pathlab: -o %s: unknown image format (use .pfm, .ppm or .png)\n", a->out); return 1; }
    if (a->variance && !image_extension_ok(a->variance, 1)) { fprintf(stderr, "pathlab: --variance %s: the variance is written as .pfm\n", a->variance); return 1; }
    if (a->ro.io.split && a->ro.io.bmax == BOUNCES_INF) {
        fprintf(stderr, "pathlab: --split needs a last bounce, e.g. --bounces 0:8\n");
        return 1;
    }
    if (a->ro.threads < 1) a->ro.threads = 1;
    return 0;
}

/* out.pfm -> out_L3.pfm */
static void bounce_path(char *dst, size_t cap, const char *out, int k)
{
    const char *e = path_extension(out);
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

/* pathlab convert IN.pfm OUT [--exposure S]: a PFM made viewable, and its figures. */
static int cmd_convert(int argc, char **argv)
{
    image im;
    float exposure = 0.0f;
    double sum[3] = {0, 0, 0}, lo[3], hi[3];
    size_t i, n;
    int ch, err;
    char *end;
    if (argc != 3 && !(argc == 5 && !strcmp(argv[3], "--exposure"))) {
        fprintf(stderr, "usage: pathlab convert IN.pfm OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS]\n");
        return 2;
    }
    if (argc == 5) {
        exposure = strtof(argv[4], &end);
        if (end == argv[4] || *end || !(exposure > -100.0f && exposure < 100.0f)) {
            fprintf(stderr, "pathlab: convert: --exposure %s: expected a number of stops\n", argv[4]);
            return 2;
        }
    }
    if (!image_extension_ok(argv[2], 0)) { fprintf(stderr, "pathlab: convert: %s: unknown image format (use .png, .ppm or .pfm)\n", argv[2]); return 2; }
    if (img_read_pfm(&im, argv[1])) return 2;
    n = (size_t)im.w * im.h;
    for (ch = 0; ch < 3; ch++) lo[ch] = HUGE_VAL, hi[ch] = -HUGE_VAL;
    for (i = 0; i < 3 * n; i++) {
        double v = im.px[i];
        sum[i % 3] += v;
        if (v < lo[i % 3]) lo[i % 3] = v;
        if (v > hi[i % 3]) hi[i % 3] = v;
    }
    printf("%s: %d x %d\n", argv[1], im.w, im.h);
    for (ch = 0; ch < 3; ch++)
        printf("  %-5s mean %.6g  min %.6g  max %.6g\n", ch == 0 ? "red" : ch == 1 ? "green" : "blue", sum[ch] / (double)n, lo[ch], hi[ch]);
    err = img_write(&im, argv[2], exposure);
    img_free(&im);
    return err ? 1 : 0;
}

static int cmd_render(int argc, char **argv)
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
        fprintf(stderr, "pathlab: warning: %s has no emitters (no material with Ke > 0): the image is black\n", a.scene);
    if (render(&s, &cam, &a.ro, &r)) { scene_free(&s); return 1; }
    if (!a.ro.quiet) render_print_stats(&r, a.ro.spp, cam.width * cam.height);
    err = write_outputs(&a, &r);
    render_result_free(&r);
    scene_free(&s);
    return err ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) { fputs(USAGE, stderr); fputs(USAGE_TOOLS, stderr); return 2; }
    if (!strcmp(argv[1], "render")) return cmd_render(argc - 1, argv + 1);
    if (!strcmp(argv[1], "bench-rays")) return bench_rays_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "check-sampling")) return check_sampling_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "diff")) return diff_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "grade")) return grade_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compare")) return compare_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "convert")) return cmd_convert(argc - 1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) { fputs(USAGE, stdout); fputs(USAGE_TOOLS, stdout); return 0; }
    fprintf(stderr, "pathlab: unknown command '%s'\n\n%s%s", argv[1], USAGE, USAGE_TOOLS);
    return 2;
}
