/* grade.c — the `pathlab grade` command: one image or a whole class against one reference.
 * Reads the reference and what lies beside it (REF_var.pfm, the layers REF_split_L0.pfm ..., or what
 * its sidecar REF.pfm.meta names: render --variance and --split outputs), grades
 * each image (grade.c), names the likely mistake of those that fail (grade_diagnose.c), prints
 * the verdicts (grade_print.c) and writes the class report (grade_class.c). */
#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <unistd.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "util/cli.h"
#include "cmd/grade.h"
#include "grade/grade.h"
#include "grade/grade_class.h"
#include "grade/grade_diagnose.h"
#include "grade/grade_page.h"
#include "grade/grade_print.h"
#include "files/render_files.h"
#include "sys/output_path.h"

#define GRADE_USAGE \
    "usage: pathlab grade IMAGE.pfm... | FOLDER --ref REF.pfm [--alpha A] [--report FILE.md|.csv|.html] [--pages DIR]\n" \
    "                     [--heatmap OUT.png|FOLDER] [--block B] [--var REF_VAR.pfm] [--layers PREFIX] [--details]\n" \
    "                     [--spp N --ref-spp M]\n"
#define GRADE_MAX_HYP 6

typedef struct {
    const char *ref, *var, *layers, *heatmap, *report, *pages;
    int details;
    char pages_dir[4096];  /* where the pages go: --pages, else REPORT-pages beside the report; "" none */
    char back[4300];       /* the pages' link to the report, or "" */
    int same_name;         /* 1: another image of the run has this one's file name (its page is named by its path) */
    grade_opts o;
    const char **images;   /* the images, folders expanded */
    int nimages;
    char **owned;          /* the paths made for a folder's images, freed at the end */
    int nowned;
} grade_args;

typedef struct {
    image ref, var, layer[GRADE_MAX_LAYERS];
    grade_refs refs;
    const char *var_path;
    char layer_prefix[4096];
    sidecar meta;          /* REF.pfm.meta, when pathlab render wrote the reference */
    int has_meta;
} reference;

/* --alpha A: a float strictly between 0 and 0.5 */
static int parse_alpha(void *ctx, const char *flag, const char *v)
{
    float *alpha = ctx;
    const cli_flag f = {flag, CLI_FLOAT, alpha, 0, 0, NULL, NULL, NULL};
    if (cli_parse_value("grade", &f, v, NULL)) return 1;
    if (*alpha > 0.0f && *alpha < 0.5f) return 0;
    return cli_fail("grade", flag, "a level in (0, 0.5)", v);
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static void free_args(grade_args *a)
{
    int k;
    for (k = 0; k < a->nowned; k++) free(a->owned[k]);
    free(a->owned);
    free((void *)a->images);
}

/* 1 if path is a file we can open */
static int access_ok(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f) fclose(f);
    return f != NULL && !is_dir(path);
}


/* 1 if name ends with suffix */
static int ends_with(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n >= k && !strcmp(name + n - k, suffix);
}

static int by_name(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

/* 1 if the two paths name the same file or folder */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* 1 if dir/name is the reference or a file made beside it (REF-64x64.pfm, REF_split.pfm, ...). */
static int is_reference(const char *dir, const char *name, const char *ref)
{
    const char *slash = strrchr(ref, '/'), *base = slash ? slash + 1 : ref;
    char path[4200], ref_dir[4200];
    size_t stem = ends_with(base, ".pfm") ? strlen(base) - 4 : strlen(base);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    snprintf(ref_dir, sizeof ref_dir, "%.*s", slash ? (int)(slash - ref) : 1, slash ? ref : ".");
    if (same_file(path, ref)) return 1;
    return same_file(dir, ref_dir) && !strncmp(name, base, stem) && (name[stem] == '_' || name[stem] == '-');
}

/* Appends the .pfm files of a folder (not variances, not layers, not the reference), sorted by
 * name; 0 or 1 (error said). */
static int add_folder(grade_args *a, const char *dir, int cap)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int first = a->nimages;
    if (!d) { fprintf(stderr, "pathlab grade: cannot open the folder %s\n", dir); return 1; }
    while ((e = readdir(d)) != NULL) {
        char *path;
        if (!ends_with(e->d_name, ".pfm") || ends_with(e->d_name, "_var.pfm") || strstr(e->d_name, "_split_L") ||
            is_reference(dir, e->d_name, a->ref)) continue;
        if (a->nimages >= cap) { fprintf(stderr, "pathlab grade: more than %d images\n", cap); closedir(d); return 1; }
        path = malloc(strlen(dir) + strlen(e->d_name) + 2);
        if (!path) { closedir(d); return 1; }
        sprintf(path, "%s/%s", dir, e->d_name);
        a->images[a->nimages++] = a->owned[a->nowned++] = path;
    }
    closedir(d);
    qsort(a->images + first, (size_t)(a->nimages - first), sizeof *a->images, by_name);
    if (a->nimages == first) fprintf(stderr, "pathlab grade: warning: no .pfm image to grade in the folder %s\n", dir);
    return 0;
}

static int check_outputs(const grade_args *a)
{
    static const char *const reports[] = {".md", ".csv", ".html", NULL};
    if (a->heatmap && !(a->nimages > 1 ? is_dir(a->heatmap) : img_format_of(a->heatmap) != IMG_UNKNOWN)) {
        fprintf(stderr, a->nimages > 1 ? "pathlab grade: --heatmap %s: with several images, give a folder that exists\n"
                                       : "pathlab grade: --heatmap %s: unknown image format (use .pfm, .ppm or .png)\n", a->heatmap);
        return 1;
    }
    if (a->report && !ends_with(a->report, ".md") && !ends_with(a->report, ".csv") && !ends_with(a->report, ".html")) {
        fprintf(stderr, "pathlab grade: --report %s: use a name ending in .md (Markdown), .csv or .html\n", a->report);
        return 1;
    }
    /* then where they go: the folder exists and can be written */
    if (a->heatmap && (a->nimages > 1 ? output_dir_check("grade", "--heatmap", a->heatmap)
                                      : output_path_check("grade", "--heatmap", a->heatmap, IMG_EXTENSIONS))) return 1;
    if (a->pages && output_dir_check("grade", "--pages", a->pages)) return 1;
    return a->report && output_path_check("grade", "--report", a->report, reports);
}

/* dir/file (file NULL: dir alone) as an absolute path: the working folder before it when relative. */
static void absolute(char *out, size_t cap, const char *dir, const char *file)
{
    char cwd[4096];
    int n;
    if (dir[0] != '/' && getcwd(cwd, sizeof cwd)) n = snprintf(out, cap, "%s/%s%s%s", cwd, dir, file ? "/" : "", file ? file : "");
    else n = snprintf(out, cap, "%s%s%s", dir, file ? "/" : "", file ? file : "");
    if (n < 0 || (size_t)n >= cap) out[0] = '\0';   /* too long: no link rather than a wrong one */
}

/* The pages' folder: --pages DIR, else with --report R.EXT the folder R-pages beside the report (the
 * report's links are then relative and survive moving both), else none. Made if missing, once the
 * reference has been read (bad input writes nothing); the pages' link back to the report is set
 * when it has a report. 0, or 1 (said). */
static int setup_pages(grade_args *a)
{
    const char *base = a->report ? (strrchr(a->report, '/') ? strrchr(a->report, '/') + 1 : a->report) : "";
    size_t stem = strrchr(base, '.') ? (size_t)(strrchr(base, '.') - base) : strlen(base);
    char dir[4096];
    if (a->pages) snprintf(a->pages_dir, sizeof a->pages_dir, "%s", a->pages);
    else if (a->report) snprintf(a->pages_dir, sizeof a->pages_dir, "%.*s-pages", (int)(base - a->report + stem), a->report);
    else return 0;
    if (mkdir(a->pages_dir, 0777) && errno != EEXIST) {
        fprintf(stderr, "pathlab grade: cannot create the folder %s for the pages: %s\n", a->pages_dir, strerror(errno));
        return 1;
    }
    if (!is_dir(a->pages_dir)) { fprintf(stderr, "pathlab grade: --pages %s is not a folder\n", a->pages_dir); return 1; }
    snprintf(dir, sizeof dir, "%.*s", base > a->report ? (int)(base - a->report) : 1, base > a->report ? a->report : ".");
    if (!a->report) a->back[0] = '\0';
    else if (!a->pages) snprintf(a->back, sizeof a->back, "../%s", base);
    else absolute(a->back, sizeof a->back, dir, base);
    return 0;
}

/* The link from the report to a page DIR/FILE: relative when DIR lies under the report's folder,
 * else absolute. */
static void page_link(char *out, size_t cap, const grade_args *a, const char *page)
{
    const char *slash = a->report ? strrchr(a->report, '/') : NULL;
    size_t n = slash ? (size_t)(slash - a->report) + 1 : 0;
    if (n && !strncmp(page, a->report, n)) snprintf(out, cap, "%s", page + n);
    else if (page[0] == '/' || !a->report || (n == 0 && strncmp(page, "../", 3))) snprintf(out, cap, "%s", page);
    else absolute(out, cap, page, NULL);
}

static int parse_args(grade_args *a, int argc, char **argv)
{
    float alpha = 0.01f;
    const cli_flag flags[] = {
        {"--ref", CLI_STRING, &a->ref, 0, 0, NULL, NULL, NULL},
        {"--var", CLI_STRING, &a->var, 0, 0, NULL, NULL, NULL},
        {"--layers", CLI_STRING, &a->layers, 0, 0, NULL, NULL, NULL},
        {"--heatmap", CLI_STRING, &a->heatmap, 0, 0, NULL, NULL, NULL},
        {"--report", CLI_STRING, &a->report, 0, 0, NULL, NULL, NULL},
        {"--pages", CLI_STRING, &a->pages, 0, 0, NULL, NULL, NULL},
        {"--details", CLI_SWITCH, &a->details, 0, 0, NULL, NULL, NULL},
        {"--spp", CLI_INT, &a->o.spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--ref-spp", CLI_INT, &a->o.ref_spp, 1, 1 << 30, NULL, NULL, NULL},
        {"--block", CLI_INT, &a->o.block, 2, 1 << 20, NULL, NULL, NULL},
        {"--alpha", CLI_CUSTOM, NULL, 0, 0, NULL, parse_alpha, NULL},
        {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    const char **words = calloc((size_t)argc + 1, sizeof *words);
    int n, k, cap = 100000;
    a->images = calloc((size_t)cap, sizeof *a->images);
    a->owned = calloc((size_t)cap, sizeof *a->owned);
    if (!words || !a->images || !a->owned || cli_parse("grade", argc, argv, tables, &alpha, words, argc, &n)) { free(words); return 1; }
    a->o.alpha = alpha;
    for (k = 0; k < n; k++) {
        if (is_dir(words[k])) { if (add_folder(a, words[k], cap)) { free(words); return 1; } }
        else if (a->nimages < cap) a->images[a->nimages++] = words[k];
    }
    free(words);
    if (!n || !a->ref) { fprintf(stderr, "pathlab grade: needs an image (or a folder of them) and --ref REF.pfm\n" GRADE_USAGE); return 1; }
    if (!a->nimages) { fprintf(stderr, "pathlab grade: no image to grade (the folder holds no .pfm besides the reference's files)\n"); return 1; }
    return check_outputs(a);
}

/* Reads the reference, its variance (--var, else REF_var.pfm if it exists) and its layers (--layers
 * PREFIX, else REF_split: PREFIX_L0.pfm, PREFIX_L1.pfm ... as far as they exist). 0, or 2 (said). */
static int read_reference(reference *R, const grade_args *a)
{
    static char var_path[4096];
    size_t stem = ends_with(a->ref, ".pfm") ? strlen(a->ref) - 4 : strlen(a->ref);
    int k;
    img_pfm_info info;
    memset(R, 0, sizeof *R);
    if (img_read_pfm_info(&R->ref, a->ref, &info)) return 2;
    R->refs.ref = &R->ref;
    R->refs.channels = info.channels;
    snprintf(var_path, sizeof var_path, "%.*s_var.pfm", (int)stem, a->ref);
    R->has_meta = sidecar_read(&R->meta, a->ref) == 0;
    if (!a->var && !access_ok(var_path) && R->has_meta && R->meta.variance[0])   /* the variance its sidecar names */
        render_files_variance_path(var_path, sizeof var_path, a->ref, R->meta.variance);
    R->var_path = a->var ? a->var : (access_ok(var_path) ? var_path : NULL);
    if (R->var_path) {
        if (img_read_pfm(&R->var, R->var_path)) return 2;
        if (R->var.w != R->ref.w || R->var.h != R->ref.h) {
            fprintf(stderr, "pathlab grade: %s is %dx%d, the reference %s %dx%d\n", R->var_path, R->var.w, R->var.h, a->ref, R->ref.w, R->ref.h);
            return 2;
        }
        R->refs.var = &R->var;
    }
    if (a->layers) snprintf(R->layer_prefix, sizeof R->layer_prefix, "%s", a->layers);
    else snprintf(R->layer_prefix, sizeof R->layer_prefix, "%.*s_split", (int)stem, a->ref);
    if (!a->layers && R->has_meta && R->meta.layers_n > 0 && R->meta.layers_first == 0) {   /* render --split's own REF_L0.pfm ... */
        char first[4200];
        snprintf(first, sizeof first, "%s_L0.pfm", R->layer_prefix);
        if (!access_ok(first)) snprintf(R->layer_prefix, sizeof R->layer_prefix, "%.*s", (int)stem, a->ref);
    }
    for (k = 0; k < GRADE_MAX_LAYERS; k++) {
        char path[4200];
        snprintf(path, sizeof path, "%s_L%d.pfm", R->layer_prefix, k);
        if (!access_ok(path)) break;
        if (img_read_pfm(&R->layer[k], path)) return 2;
        if (R->layer[k].w != R->ref.w || R->layer[k].h != R->ref.h) {
            fprintf(stderr, "pathlab grade: the layer %s is %dx%d, the reference %dx%d\n", path, R->layer[k].w, R->layer[k].h, R->ref.w, R->ref.h);
            return 2;
        }
        R->refs.layer[k] = &R->layer[k];
        R->refs.nlayers = k + 1;
    }
    return grade_check_reference(&R->refs, a->ref, R->var_path);
}

static void free_reference(reference *R)
{
    int k;
    img_free(&R->ref);
    img_free(&R->var);
    for (k = 0; k < GRADE_MAX_LAYERS; k++) img_free(&R->layer[k]);
}

/* The heatmap's path for an image: the --heatmap file itself, or FOLDER/NAME.png with several. */
static void heatmap_path(char *out, size_t cap, const grade_args *a, const char *image)
{
    const char *base = strrchr(image, '/') ? strrchr(image, '/') + 1 : image;
    size_t stem = ends_with(base, ".pfm") ? strlen(base) - 4 : strlen(base);
    if (a->nimages == 1) snprintf(out, cap, "%s", a->heatmap);
    else snprintf(out, cap, "%s/%.*s.png", a->heatmap, (int)stem, base);
}

/* The likely mistakes of a failing image: printed in full (one image, or --details) and joined into
 * the row. */
static int diagnose(grade_row *row, const image *img, const reference *R, const grade_args *a, double excess, int loud,
                    grade_hypothesis *h, int *nh)
{
    int n = *nh = grade_diagnose(img, &R->refs, &a->o, excess, h, GRADE_MAX_HYP), k;
    size_t used = 0;
    if (n < 0) { fprintf(stderr, "pathlab grade: out of memory\n"); *nh = 0; return 2; }
    if (loud) grade_print_hypotheses(h, n);
    if (n == 0) snprintf(row->mistake, sizeof row->mistake, "none of the catalogue%s", R->refs.nlayers ? "" :
                         " (no layers REF_split_L0.pfm ... beside the reference: the bounce mistakes were not tried)");
    if (loud && n == 0 && !R->refs.nlayers)
        printf("    (no layers %s_L0.pfm ... beside the reference: the bounce mistakes were not tried; docs/grading.md)\n", R->layer_prefix);
    for (k = 0; k < n && k < 3 && used < sizeof row->mistake; k++)
        used += (size_t)snprintf(row->mistake + used, sizeof row->mistake - used, "%s%s", k ? "; " : "", h[k].what);
    return 0;
}

/* The heatmap of one graded image, if asked: 0, or 2 (said). */
static int write_heatmap(const grade_report *r, const reference *R, const grade_args *a, const char *image_path, int loud)
{
    char path[4200];
    image heat;
    int err;
    if (!a->heatmap) return 0;
    heatmap_path(path, sizeof path, a, image_path);
    err = grade_heatmap(&heat, r, &R->ref) || img_write(&heat, path, 0.0f);
    if (!err && loud) printf("heatmap: %s (red: significantly brighter blocks, blue: darker, grey: the reference)\n", path);
    img_free(&heat);
    return err ? 2 : 0;
}

static const char *file_name(const char *path) { return strrchr(path, '/') ? strrchr(path, '/') + 1 : path; }

/* The page of one graded image, PAGES/STEM.html, if there is a pages folder; the row's link to it.
 * 0, or 2 (said). */
static int write_page(grade_row *row, const grade_report *r, const image *img, const reference *R, const grade_args *a,
                      const grade_hypothesis *h, int nh, int loud)
{
    const char *base = file_name(row->path);
    size_t stem, k, n;
    char path[8400];
    grade_page p;
    if (!a->pages_dir[0]) return 0;
    if (a->same_name && base > row->path) base--;   /* with its folder: ana/render.pfm */
    while (a->same_name && base > row->path && base[-1] != '/') base--;
    stem = ends_with(base, ".pfm") ? strlen(base) - 4 : strlen(base);
    n = (size_t)snprintf(path, sizeof path, "%s/", a->pages_dir);
    for (k = 0; k < stem && n + 6 < sizeof path; k++)   /* ana/render.pfm, when render.pfm is not alone: ana_render.html */
        path[n++] = (char)(isalnum((unsigned char)base[k]) || strchr("-.", base[k]) ? base[k] : '_');
    snprintf(path + n, sizeof path - n, ".html");
    p.path = path, p.ref_path = a->ref, p.var_path = R->var_path, p.img = img, p.refs = &R->refs, p.r = r, p.row = row;
    p.h = h, p.nh = nh, p.back = a->back[0] ? a->back : NULL;
    if (grade_write_page(&p)) return 2;
    page_link(row->page, sizeof row->page, a, path);
    if (loud) printf("page: %s\n", path);
    return 0;
}

static int by_file_name(const void *a, const void *b)
{
    return strcmp(file_name(**(const char *const *const *)a), file_name(**(const char *const *const *)b));
}

/* same[k] = 1 when another image has images[k]'s file name (students/NAME/render.pfm): their pages
 * are then named by their paths. 0, or 1 when out of memory. */
static int mark_same_names(const char **images, int n, unsigned char *same)
{
    const char ***order = malloc((size_t)n * sizeof *order);
    int k;
    if (!order) return 1;
    for (k = 0; k < n; k++) order[k] = &images[k];
    qsort(order, (size_t)n, sizeof *order, by_file_name);
    for (k = 0; k + 1 < n; k++)
        if (!strcmp(file_name(*order[k]), file_name(*order[k + 1]))) same[order[k] - images] = same[order[k + 1] - images] = 1;
    free(order);
    return 0;
}

/* Grades one image into its row: 0 pass, 1 fail, 2 could not be read or graded. keep (or NULL)
 * receives the graded image, for the class's page. */
static int grade_one(grade_row *row, const reference *R, const grade_args *a, int loud, image *keep)
{
    grade_hypothesis h[GRADE_MAX_HYP];
    image img;
    grade_report r;
    int rc, nh = 0;
    memset(row, 0, sizeof *row);
    row->path = a->images[0];
    rc = grade_read_image(&img, row, &R->refs, a->ref);
    if (rc && loud && a->nimages == 1) grade_print_row(row);
    if (rc) return row->status = rc;
    if (grade_compute(&r, &img, &R->ref, R->refs.var, &a->o)) {
        fprintf(stderr, "pathlab grade: out of memory\n");
        img_free(&img);
        return row->status = 2;
    }
    if (loud) grade_print_report(&r, row->path, a->ref, &a->o);
    grade_fill_row(row, &r);
    row->status = grade_failed(&r);
    if (row->status == 1 && diagnose(row, &img, R, a, grade_excess(&r), loud, h, &nh)) row->status = 2;
    if (write_heatmap(&r, R, a, row->path, loud) || write_page(row, &r, &img, R, a, h, nh, loud)) row->status = 2;
    grade_free(&r);
    if (keep && row->status < 2) { *keep = img; img.px = NULL; }
    img_free(&img);
    return row->status;
}

/* What made the reference, from its sidecar: a teacher checks the spp, seed and camera at a glance. */
static void print_provenance(const sidecar *m, const char *ref)
{
    char ranges[256], spp[96];
    sidecar_ranges_text(m, ranges, sizeof ranges);
    if (m->adaptive[0]) snprintf(spp, sizeof spp, "adaptive, a mean of %.1f spp per pixel", m->spp_mean);   /* not the range's width */
    else snprintf(spp, sizeof spp, "%lld spp", (long long)sidecar_spp(m));
    printf("reference %s: %s (samples %s), seed %llu, %s %s, camera %s, pathlab %s%s%s\n", ref,
           spp, ranges, (unsigned long long)m->seed, m->scene, m->flags, m->camera, m->revision,
           m->stopped[0] ? ", stopped by " : "", m->stopped);
}

int grade_main(int argc, char **argv)
{
    grade_args a;
    reference R;
    grade_row *rows;
    image *kept = NULL;    /* the graded images, kept for the class's page (--report X.html) */
    unsigned char *same = NULL;
    int k, rc = 0, loud;
    memset(&a, 0, sizeof a);
    memset(&R, 0, sizeof R);
    if (parse_args(&a, argc, argv)) { free_args(&a); return 2; }
    rows = calloc((size_t)a.nimages + 1, sizeof *rows);
    if (a.report && ends_with(a.report, ".html") && !(kept = calloc((size_t)a.nimages, sizeof *kept))) rc = 2;
    if (!(same = calloc((size_t)a.nimages, 1)) || mark_same_names(a.images, a.nimages, same)) rc = 2;
    if (rc || !rows || read_reference(&R, &a) || setup_pages(&a)) {
        free_reference(&R); free_args(&a); free(rows); free(kept); free(same);
        return 2;
    }
    loud = a.nimages == 1 || a.details;
    if (R.has_meta) print_provenance(&R.meta, a.ref);
    if (R.has_meta) a.o.ref_var_dof = R.meta.variance_dof;   /* a sobol reference's variance: 3 dof */
    if (!loud) grade_print_class_header(&a.o, a.ref, a.nimages, &R.refs, R.var_path, R.layer_prefix);
    for (k = 0; k < a.nimages; k++) {
        grade_args one = a;
        one.images = a.images + k, one.same_name = same[k];
        if (loud && k) printf("\n");
        grade_one(&rows[k], &R, &one, loud, kept ? &kept[k] : NULL);
        rows[k].path = a.images[k];
        if (!loud || a.nimages > 1) grade_print_row(&rows[k]);
        if (rows[k].status > rc) rc = rows[k].status;
    }
    if (a.nimages > 1) grade_print_summary(rows, a.nimages, &a.o);
    if (a.report && grade_write_report(a.report, rows, a.nimages, &a.o, a.ref, &R.refs, kept)) rc = 2;
    for (k = 0; kept && k < a.nimages; k++) img_free(&kept[k]);
    free(kept);
    free(same);
    free_reference(&R);
    free_args(&a);
    free(rows);
    return rc;
}
