/* grade.c — the `pathlab grade` command: its flags, their checks, and the run (grade/class_run.h):
 * one image or a whole class (a folder expanded by grade/folder.h) against one reference. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cmd/grade.h"
#include "grade/class_run.h"
#include "grade/folder.h"
#include "sys/output_path.h"
#include "sys/shown.h"
#include "util/cli.h"
#include "util/path.h"

#define GRADE_USAGE \
    "usage: pathlab grade IMAGE.pfm... | FOLDER --ref REF.pfm [--alpha A] [--report FILE.md|.csv|.html] [--pages DIR]\n" \
    "                     [--heatmap OUT.png|FOLDER] [--block B] [--var REF_VAR.pfm] [--layers PREFIX] [--details]\n" \
    "                     [--spp N --ref-spp M]\n"
#define GRADE_MAX_IMAGES 100000

/* --alpha A: a float strictly between 0 and 0.5 */
static int parse_alpha(void *ctx, const char *flag, const char *v)
{
    float *alpha = ctx;
    char *end;
    double a = strtod(v, &end);   /* nan, inf and 1e99 get this message too, not a float's range */
    if (end != v && !*end && a > 0.0 && a < 0.5 && (float)a > 0.0f && (float)a < 0.5f) { *alpha = (float)a; return 0; }
    return cli_fail("grade", flag, "a level in (0, 0.5), e.g. 0.01", v);
}

/* The outputs' names, then where they go: the folder exists and can be written. */
static int check_outputs(grade_job *j)
{
    static const char *const reports[] = {".md", ".csv", ".html", NULL};
    const char *r = j->report;
    int folder = j->heatmap_folder = j->heatmap && (j->nimages > 1 || path_is_dir(j->heatmap));   /* FOLDER/NAME.png, even for one image */
    if (j->heatmap && !(folder ? path_is_dir(j->heatmap) : img_is_picture(j->heatmap))) {
        fprintf(stderr, j->nimages > 1 ? "pathlab grade: --heatmap %s: with several images, give a folder that exists\n"
                                       : "pathlab grade: --heatmap %s: a heatmap is a picture: use .png or .ppm\n", shown(j->heatmap));
        return 1;
    }
    if (r && !path_ends_with(r, ".md") && !path_ends_with(r, ".csv") && !path_ends_with(r, ".html")) {
        fprintf(stderr, "pathlab grade: --report %s: use a name ending in .md (Markdown), .csv or .html\n", shown(r));
        return 1;
    }
    if (j->heatmap && (folder ? output_dir_check("grade", "--heatmap", j->heatmap)
                                      : output_path_check("grade", "--heatmap", j->heatmap, IMG_PICTURE_EXTENSIONS))) return 1;
    if (j->pages && output_dir_check("grade", "--pages", j->pages)) return 1;
    return r && output_path_check("grade", "--report", r, reports);
}

/* The images, each folder expanded: 0, or 1 after saying why. */
static int add_images(grade_list *l, const char **words, int n, const char *ref)
{
    int k;
    if (!n || !ref) { fprintf(stderr, "pathlab grade: needs an image (or a folder of them) and --ref REF.pfm\n" GRADE_USAGE); return 1; }
    for (k = 0; k < n; k++) {
        if (!path_is_dir(words[k])) grade_list_add(l, words[k]);
        else if (grade_list_add_folder(l, words[k], ref)) return 1;
    }
    if (!l->n) { fprintf(stderr, "pathlab grade: no image to grade (the folder holds no .pfm besides the reference's files)\n"); return 1; }
    return 0;
}

static int parse_args(grade_job *j, grade_list *l, int argc, char **argv)
{
    float alpha = 0.01f;
    const cli_flag flags[] = {
        {"--ref", CLI_STRING, &j->ref, 0, 0, NULL, NULL, NULL},
        {"--var", CLI_STRING, &j->var, 0, 0, NULL, NULL, NULL},
        {"--layers", CLI_STRING, &j->layers, 0, 0, NULL, NULL, NULL},
        {"--heatmap", CLI_STRING, &j->heatmap, 0, 0, NULL, NULL, NULL},
        {"--report", CLI_STRING, &j->report, 0, 0, NULL, NULL, NULL},
        {"--pages", CLI_STRING, &j->pages, 0, 0, NULL, NULL, NULL},
        {"--details", CLI_SWITCH, &j->details, 0, 0, NULL, NULL, NULL},
        {"--spp", CLI_INT, &j->o.spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--ref-spp", CLI_INT, &j->o.ref_spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--block", CLI_INT, &j->o.block, 2, 1 << 20, NULL, NULL, NULL},
        {"--alpha", CLI_CUSTOM, NULL, 0, 0, NULL, parse_alpha, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    const char **words = calloc((size_t)argc + 1, sizeof *words);
    int n, err;
    err = !words || grade_list_init(l, GRADE_MAX_IMAGES) || cli_parse_once("grade", argc, argv, tables, &alpha, words, argc, &n)
          || add_images(l, words, n, j->ref);
    free(words);
    j->o.alpha = alpha;
    j->images = l->images;
    j->nimages = l->n;
    return err || check_outputs(j);
}

int grade_main(int argc, char **argv)
{
    grade_job j;
    grade_list l;
    int rc;
    memset(&j, 0, sizeof j);
    memset(&l, 0, sizeof l);
    rc = parse_args(&j, &l, argc, argv) ? 2 : grade_run(&j);
    grade_list_free(&l);
    return rc;
}
