/* main.c — pathlab's command line: the commands, each with its help, handed to its own file
 * (render_cmd.c, convert.c, diff.c, cmd/grade.c, compare.c, merge.c, bench_rays.c,
 * check_sampling.c, check_sampler.c).
 * A new command is one entry of COMMANDS: its name, its main, the lines of the overview
 * (`pathlab help`) and the parts of its own help (`pathlab NAME --help`, `pathlab help NAME`);
 * util/commands.c dispatches and prints the helps. */
#include <stdio.h>
#include <string.h>
#include "cmd/check_sampler.h"
#include "cmd/check_sampling.h"
#include "cmd/bench_rays.h"
#include "cmd/compare.h"
#include "cmd/convert.h"
#include "cmd/diff.h"
#include "cmd/grade.h"
#include "cmd/help.h"
#include "cmd/merge.h"
#include "cmd/render_cmd.h"
#include "cmd/version.h"
#include "cmd/view.h"
#include "geometry/bvh.h"
#include "sys/interrupt.h"
#include "util/commands.h"

static const char HEADER[] = "pathlab — a teaching path tracer (see README.md)\n\nusage:\n";
static const char FOOTER[] =
    "  pathlab help [COMMAND] | COMMAND --help | --version\n"
    "  pathlab completion bash   the bash completion script (make install puts it in place)\n"
    "\n"
    "  Any command takes --isa NAME: the instruction set of the ray traversal (avx512, avx2, sse2 on\n"
    "  x86-64; default: the best this CPU runs; every one gives the same images; --version lists them).\n"
    "\n";
static const char SYN_RENDER[] = "  pathlab render SCENE.obj [flags] -o FILE.pfm|FILE.ppm|FILE.png\n";
static const char SYN_BENCH[] = "  pathlab bench-rays MESH.obj [-r RES] [-t THREADS]   rays per second of the BVH on a mesh\n";
static const char SYN_CHECK_SAMPLING[] =
    "  pathlab check-sampling [--samples N] [--seed S] [--threads T] [--quiet]   chi-square tests of pathlab's own samplers\n";
static const char SYN_DIFF[] =
    "  pathlab diff A.pfm REF.pfm [--heatmap OUT.ppm|OUT.png] [--scale S]   (or A.pfm [B.pfm ...] --ref REF.pfm)\n"
    "                heatmap of |A - REF|: black 0 to white S (default: the largest difference, so\n"
    "                give the same --scale to compare two heatmaps)\n";
static const char SYN_GRADE[] =
    "  pathlab grade IMAGE.pfm... | FOLDER --ref REF.pfm [--alpha A] [--report FILE.md|FILE.csv|FILE.html]\n"
    "                [--pages DIR] [--heatmap OUT.png|FOLDER] [--block B] [--var REF_VAR.pfm] [--layers PREFIX] [--details]\n"
    "                is each IMAGE - REF noise or bias, and if bias, the likely mistake (pathlab grade --help; docs/grading.md)\n";
static const char SYN_CONVERT[] =
    "  pathlab convert IN.pfm|IN.hdr OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS|auto]   view a PFM or a Radiance .hdr;\n"
    "                prints the size and each channel's mean, min and max\n";
static const char MORE_BENCH[] =
    "  -r RES        the rays: a RES x RES grid of camera rays (default 1024)\n"
    "  -t THREADS    worker threads (default 1)\n"
    "  --cpu-time    time with the process's CPU clock (all threads' seconds together), not the wall\n"
    "                clock: on a machine loaded by other processes it does not count their time slices\n"
    "  --bvh-quality default|split   split: cut the triangles that fill least of their boxes into\n"
    "                pieces first (a quarter more primitives, a slower build; the same hits)\n";
static const char MORE_DIFF[] =
    "  prints RMSE, relMSE, MAE, max, PSNR and the mean difference (with its standard error)\n"
    "  --heatmap OUT.ppm|OUT.png   also write the heatmap of |A - REF|\n"
    "  --scale S     the heatmap's white (default: the largest difference)\n"
    "  --ref REF.pfm the reference, for several images (one line each)\n";
static const char MORE_MERGE[] =
    "  --variance OUT_var.pfm   also write the variance of the merged mean (the inputs' variances, found beside them)\n";
static const char MORE_CONVERT[] =
    "  --exposure STOPS   PPM and PNG: multiply by 2^STOPS before the sRGB curve (default 0); auto: the\n"
    "                     median luminance of the pixels that are not black to mid-grey (it prints the stops)\n"
    "  OUT.pfm gets IN.pfm's sidecar, if it has one\n";
static const char MORE_VIEW[] =
    "  --ref REF.pfm   the reference: split view, signed difference, its value under the mouse\n"
    "  --var VAR.pfm   the first image's variance (for the z-score; else STEM_var.pfm or its sidecar's)\n"
    "  --layers PREFIX a strip of PREFIX_L0.pfm, PREFIX_L1.pfm... (default: the first image's --split layers)\n"
    "  --title T       the page's title\n"
    "  in the page: left/right or n/p cycle the images, 1-9 pick one; i, s, d: image, split, difference;\n"
    "  r, g, b: the channels; + and -: exposure, a: automatic; f: fit, 0: one pixel a pixel. No network needed\n";
static const char SYN_VERSION[] = "  pathlab version   the version (the git revision it was built from), as --version\n";

/* in parts: ISO C99 promises string literals of 4095 characters only */
static const char USAGE_RENDER[] =
    "render flags:\n"
    "  -o FILE              output image; .pfm (linear float), .ppm or .png (8-bit sRGB)\n"
    "  --spp N              samples per pixel (default 16), rendered in passes: every pixel gets sample i\n"
    "                       before any gets i+1; Ctrl-C writes the image at the spp reached, a 2nd quits;\n"
    "                       with adaptive sampling (below), the most a pixel gets (default 65536 with\n"
    "                       --target-error, none with --time alone)\n"
    "  --time SEC           as many passes as fit in SEC seconds (up to --spp if given)\n"
    "  --samples A:B        only the sample indices A..B-1 (pieces for pathlab merge)\n"
    "  --resume             add samples to the render at -o (up to --spp in all, or for --time); the scene,\n"
    "                       camera, size, flags and seed are those of its sidecar (a flag given must agree)\n"
    "  --seed S             random seed (default 1); same seed, same image, any thread count\n"
    "  --threads N          worker threads (default: every core)\n"
    "  --quiet              no progress bar and no stats line\n"
    "  --exposure STOPS     PPM and PNG: multiply by 2^STOPS before the sRGB curve (default 0); auto: the\n"
    "                       median luminance of the pixels that are not black to mid-grey (it prints the stops)\n"
    "camera (defaults from SCENE.view, else framing the whole scene):\n"
    "  --eye X,Y,Z  --target X,Y,Z  --up X,Y,Z  --fov DEGREES (vertical)  --size WxH\n"
    "  --view FILE          the camera of a view file instead of SCENE.view\n"
    "  --orbiter FILE       the camera of a gKit orbiter file; its f line gives the fov and size (rays\n"
    "                       start at the eye, gKit's on its near plane: docs/grading.md, section 1)\n"
    "  --write-view FILE    also write the camera used (after framing and flags) as a view file for --view\n"
    "  --pixel-offset O     pixel (x, y) is centred at (x + O, y + O), y up from the bottom row as in gKit:\n"
    "                       0.5 (default; gKit's Point(x + .5f, y + .5f, 0), pbrt, Mitsuba) or 0 (Point(x, y, 0))\n"
    "  --pixel-center       shoot through (x + O, y + O) exactly instead of jittering in the pixel\n"
    "light transport (L_k = light that reached the eye after exactly k reflections):\n"
    "  --bounces A:B        render L_A + ... + L_B; B may be inf (default 0:inf)\n"
    "  --bounce K           the same as --bounces K:K\n"
    "  --split              also write one image per bounce: FILE_L0.pfm, FILE_L1.pfm, ...\n"
    "  --light {light|}   how a point s on a light is chosen (default area)\n"
    "  --sky R,G,B|FILE     a sky: a constant radiance, or an equirectangular FILE.pfm or FILE.hdr (+Y up,\n"
    "                       top row the zenith); sampled by luminance, chosen against emitters by power (docs/sky.md)\n"
    "  --dir {dir|}        how a direction is chosen at a surface (default brdf)\n"
    "  --direct {direct|}   the estimator of direct light (default mis-power)\n"
    "  --rr D|off           Russian roulette after D bounces (default 3)\n"
    "  --rr-below T         the roulette thins paths whose throughput is below T: p_survive = max(beta)/T\n"
    "                       (default 1 with --sampler independent, 1/3 with sobol and sobol1)\n"
    "  --sampler S          independent (the slides' Monte Carlo), sobol (4 scrambled Sobol sets a pixel: less\n"
    "                       noise, --variance with 3 dof) or sobol1 (1 set: the least noise, no --variance;\n"
    "                       docs/sampler.md). Sobol renders cannot be resumed or merged. Default: sobol1, but\n"
    "                       independent with --variance, --resume, --samples or adaptive sampling\n"
    "  --variance FILE.pfm  also write the variance of each pixel's mean (with --split, one per bounce too)\n";

/* The materials, normals and textures, as gKit's (docs/gkit.md). */
static const char USAGE_MATERIALS[] =
    "materials and textures, as gKit reads them (docs/gkit.md):\n"
    "  --material M         blinn: Kd/pi + Ks (Ns+8)/(8 pi) cos^Ns(theta_h), the course's (default); diffuse:\n"
    "                       Kd/pi alone, as gKit's Monte Carlo tutorials (Ks ignored)\n"
    "  --normals N          shading: normals interpolated from the OBJ's vn, where a triangle has them (default);\n"
    "                       geometric: each triangle's own. Either way emission, shadows and offsets use the triangle's\n"
    "  --texture-filter F   nearest: the texel under (u, v), as gKit samples it (default); bilinear: the 4 around it\n"
    "  --texture-decode D   raw: an 8-bit texel / 255, as gKit reads it (default); srgb: through the sRGB curve\n"
    "  --mtl FILE           the materials of FILE instead of the OBJ's mtllib (a teacher's MTL on a student's OBJ);\n"
    "                       its map_Kd, map_Ks, map_Ke files are relative to FILE's folder\n";

/* The third part: adaptive sampling (docs/adaptive.md). */
static const char USAGE_ADAPTIVE[] =
    "adaptive sampling (docs/adaptive.md): a pilot of --pilot samples per pixel, from another seed and never kept,\n"
    "decides each pixel's count n(x); pixel x then gets the samples 0..n(x)-1 of the uniform render (unbiased)\n"
    "  --target-error E     n(x) for a relative standard error E of each pixel's mean (e.g. 0.01; the largest of\n"
    "                       R, G, B; pixels darker than 0.1x the image's mean are held to that level); implies --adaptive\n"
    "  --adaptive           with --time SEC alone: the time after the pilot is shared out, n(x) proportional to the\n"
    "                       pilot's relative standard deviation; with --target-error, --time stops it early\n"
    "  --pilot P            pilot samples per pixel (default 16)     --min-spp N   the fewest per pixel (default 4)\n"
    "  --sample-count F.pfm also write each pixel's number of samples (counts are multiples of 4)\n"
    "  not with --samples, --resume or merge: pixels with different counts do not combine\n";

/* C99 compilers need only take string literals of 4095 characters: the help is in two parts. */
static const char USAGE_TOOLS[] =
    "grade (exit 0 all pass, 1 a fail, 2 an input error), on d = IMAGE - REF per pixel-channel, at family-wise level\n"
    "alpha per image (default 0.01; alpha/3 to each family below, Sidak within it); the noise is measured on d:\n"
    "  exact pixels where REF_var.pfm (found beside REF) is 0 (black ones only where light is proven absent): as numbers\n"
    "  whole image  relative bias fitted to the block means, per channel: a bias spread everywhere (2 percent too bright)\n"
    "  blocks       Student t of the mean of d over each B x B block (default max(8, min(w,h)/16)): a bias in a region\n"
    "  levels       the same over the pixels of one octave of the reference's luminance: the lamp seen directly, highlights\n"
    "  likely mistake  a failing image is graded again with each mistake of a catalogue undone (flipped, grey, sRGB,\n"
    "               clamped, 8 bits, a factor pi, no L0, direct only, stopped after k bounces...: layers REF_split_L0.pfm...)\n"
    "  several images or a FOLDER: one line each, a summary; --report writes them as a Markdown or CSV table;\n"
    "               --details prints each image's tests in full; --heatmap FOLDER writes one heatmap per image\n"
    "  --heatmap    the reference in grey, each block tinted by its t: red brighter, blue darker (its scale printed)\n"
    "  IMAGE        a PFM or an .hdr (RGBE: its quantisation added to the noise); negative values explained, exit 2\n"
    "  --spp N --ref-spp M (with the variance) a per-pixel Z-test assuming the reference's estimator (information only)\n";
static const char COMPARE_MORE[] = COMPARE_HELP "  render flags (pathlab render --help) apply to every estimator\n";

static int version_main(int argc, char **argv)
{
    char names[128];
    (void)argv;
    if (argc > 1) { fprintf(stderr, "pathlab version: takes no arguments\n"); return 2; }
    bvh_isa_names(names, sizeof names);
    printf("pathlab %s\nray traversal: %s (compiled for %s; --isa NAME picks one)\n", pathlab_revision(), bvh_isa(), names);
    return 0;
}

/* The commands, by name (util/commands.h). */
static const command COMMANDS[] = {
    {"render", render_main, SYN_RENDER, {USAGE_RENDER, USAGE_MATERIALS, USAGE_ADAPTIVE, NULL}, 0},
    {"bench-rays", bench_rays_main, SYN_BENCH, {MORE_BENCH, NULL}, 0},
    {"check-sampling", check_sampling_main, SYN_CHECK_SAMPLING, {NULL}, 1},
    {"check-sampler", check_sampler_main, CHECK_SAMPLER_USAGE, {NULL}, 1},
    {"diff", diff_main, SYN_DIFF, {MORE_DIFF, NULL}, 0},
    {"grade", grade_main, SYN_GRADE, {USAGE_TOOLS, NULL}, 0},
    {"compare", compare_main, COMPARE_USAGE, {COMPARE_MORE, NULL}, 0},
    {"merge", merge_main, MERGE_USAGE, {MORE_MERGE, NULL}, 0},
    {"convert", convert_main, SYN_CONVERT, {MORE_CONVERT, NULL}, 0},
    {"view", view_main, VIEW_USAGE, {MORE_VIEW, NULL}, 0},
    {"version", version_main, SYN_VERSION, {NULL}, 0},
    {NULL, NULL, NULL, {NULL}, 0}};

static const command_table PATHLAB = {"pathlab", COMMANDS, HEADER, FOOTER, help_print};

/* Takes "--isa NAME" (or --isa=NAME) out of argv, wherever it is, and forces that copy of the ray
 * traversal (geometry/bvh.h). 0, or 2 after saying why. */
static int take_isa_flag(int *argc, char **argv)
{
    int i, j, rc;
    for (i = 1; i < *argc; i++) {
        const char *name = NULL;
        int used = 1;
        char names[128];
        if (!strcmp(argv[i], "--isa")) {
            if (i + 1 >= *argc) { fprintf(stderr, "pathlab: --isa needs a name (pathlab --version lists them)\n"); return 2; }
            name = argv[i + 1], used = 2;
        } else if (!strncmp(argv[i], "--isa=", 6)) name = argv[i] + 6;
        if (!name) continue;
        if ((rc = bvh_isa_force(name)) != 0) {
            bvh_isa_names(names, sizeof names);
            fprintf(stderr, "pathlab: --isa %.100s: %s (compiled for %s)\n", name,
                    rc == -2 ? "this CPU cannot run it" : "no such instruction set", names);
            return 2;
        }
        for (j = i; j + used <= *argc; j++) argv[j] = argv[j + used];   /* argv[argc] is NULL */
        *argc -= used, i--;
    }
    return 0;
}

int main(int argc, char **argv)
{
    interrupt_quit_on_signal();   /* Ctrl-C at any moment leaves no temporary file (render: two steps) */
    if (take_isa_flag(&argc, argv)) return 2;
    return commands_main(&PATHLAB, argc, argv);
}
