/* class_run.c — one grading run: the reference, then each image in turn, then the class (class_run.h). */
#include "grade/class_run.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "grade/grade_class.h"
#include "grade/grade_diagnose.h"
#include "grade/grade_page.h"
#include "grade/grade_print.h"
#include "grade/integrity.h"
#include "grade/page_paths.h"
#include "grade/reference.h"
#include "sys/atomic_file.h"
#include "sys/shown.h"
#include "image/linear_file.h"
#include "util/path.h"

#define GRADE_MAX_HYP 6

/* What every image of the run shares. */
typedef struct {
    grade_job job;          /* the job, with the reference's variance-dof once read */
    grade_reference R;
    grade_pages pages;
    int loud;              /* each image's tests in full: one image, or --details */
} run;

/* The heatmap's path for an image: the --heatmap file itself, or FOLDER/NAME.png (several images, or
 * a folder that exists; NAME as its page's, page_paths.h: one-to-one with the image's name). */
static void heatmap_path(char *out, size_t cap, const grade_job *j, const char *image, int skip)
{
    char name[GRADE_NAME_CAP];
    grade_output_name(name, image, skip);
    if (!j->heatmap_folder) snprintf(out, cap, "%s", j->heatmap);
    else snprintf(out, cap, "%s/%s.png", j->heatmap, name);
}

/* The likely mistakes of a failing image: printed in full (one image, or --details) and joined into
 * the row. */
static int diagnose(grade_row *row, const image *img, const run *s, const grade_opts *o, double excess, grade_hypothesis *h, int *nh)
{
    const grade_reference *R = &s->R;
    int n = *nh = grade_diagnose(img, &R->refs, o, excess, h, GRADE_MAX_HYP), k;
    size_t used = 0;
    if (n < 0) { fprintf(stderr, "pathlab grade: out of memory\n"); *nh = 0; return 2; }
    if (s->loud) grade_print_hypotheses(h, n);
    if (n == 0) snprintf(row->mistake, sizeof row->mistake, "none of the catalogue%s", R->refs.nlayers ? "" :
                         " (no layers REF_split_L0.pfm ... beside the reference: the bounce mistakes were not tried)");
    if (s->loud && n == 0 && !R->refs.nlayers)
        printf("    (no layers %s_L0.pfm ... beside the reference: the bounce mistakes were not tried; docs/grading.md)\n", shown(R->layer_prefix));
    for (k = 0; k < n && k < 3 && used < sizeof row->mistake; k++)   /* one difference: the others are other guesses for it */
        used += (size_t)snprintf(row->mistake + used, sizeof row->mistake - used, "%s%s%s", k ? "; or instead, a secondary guess: " : "",
                                 h[k].what, h[k].passes ? (k ? " (passes too)" : "") : " (nearly passes)");
    return 0;
}

/* Adds "its WHAT PATH was not written: the reason" to the row (the report says why it is missing). */
static void output_failed(grade_row *row, const char *what, const char *path);

/* The heatmap of one graded image, if asked; a failure said in the row. */
static void write_heatmap(grade_row *row, const grade_report *r, const run *s, int skip)
{
    char path[PATH_CAP];
    image heat;
    int err;
    if (!s->job.heatmap) return;
    heatmap_path(path, sizeof path, &s->job, row->path, skip);
    err = grade_heatmap(&heat, r, &s->R.ref) || img_write(&heat, path, 0.0f);
    if (!err && s->loud)
        printf("heatmap: %s (each %dx%d block tinted by its signed t: red brighter, blue darker, light below the limit |t| %.2f, "
               "full colour at %.2f; grey: the reference, its mean luminance %.3g at mid-grey)\n", shown(path), r->block, r->block,
               r->block_tcrit, 2.0 * r->block_tcrit, grade_heatmap_mid(&s->R.ref));
    img_free(&heat);
    if (err) output_failed(row, "heatmap", path);
}

/* The page of one graded image, if there is a pages folder; the row's link to it, or why it is missing. */
static void write_page(grade_row *row, const grade_report *r, const image *img, const run *s, const grade_hypothesis *h,
                       int nh, int skip)
{
    char path[PATH_CAP];
    grade_page p;
    if (!s->pages.dir[0]) return;
    if (grade_page_path(path, sizeof path, &s->pages, row->path, skip)) { output_failed(row, "page", "(its name)"); return; }
    p.path = path, p.ref_path = s->job.ref, p.var_path = s->R.var_path, p.img = img, p.refs = &s->R.refs, p.r = r, p.row = row;
    p.h = h, p.nh = nh, p.back = s->pages.back[0] ? s->pages.back : NULL;
    if (grade_write_page(&p)) { output_failed(row, "page", path); return; }
    grade_page_link(row->page, sizeof row->page, &s->pages, path);
    if (s->loud) printf("page: %s\n", shown(path));
}

/* Adds text to the row's remark, "; " after the one before (cut to fit). */
static void add_remark(grade_row *row, const char *text)
{
    size_t used = strlen(row->remark);
    snprintf(row->remark + used, sizeof row->remark - used, "%s%s", used ? "; " : "", text);
}

static void output_failed(grade_row *row, const char *what, const char *path)
{
    char text[sizeof row->remark];
    const char *why = atomic_file_why();
    snprintf(text, sizeof text, "its %s %.400s was not written: %s", what, path, why[0] ? why : "its path is too long, or out of memory "
             "(the message above says which)");
    add_remark(row, text);
    row->output_failed = 1;
}

/* The image's hash, and its remark against the reference (a copy; made from it), printed in full for
 * one image. */
static void check_integrity(grade_row *row, const image *img, const run *s)
{
    const grade_reference *R = &s->R;
    char text[sizeof row->remark];
    grade_pixel_hash(img, row->sha);
    row->hashed = 1;
    if (s->loud && R->refs.var) {
        grade_scatter sc;
        grade_scatter_test(&sc, img, R->refs.ref, R->refs.var);
        printf("scatter against the reference's own noise (REF_var.pfm): mean d^2 / var %.3g over %ld pixel-channels, t %+.1f "
               "(a copy or an image made from the reference: below %g with t < -%.2f, level %g)\n", sc.ratio, sc.n, sc.z,
               GRADE_SCATTER_RATIO, GRADE_SCATTER_Z, GRADE_SCATTER_ALPHA);
    }
    if (!grade_integrity_remark(text, sizeof text, img, R->refs.ref, R->refs.var)) return;
    add_remark(row, text);
    row->flagged = 1;
    if (s->loud) printf("FLAGGED: %s\n", text);
}

/* An image with the same pixels as an earlier one of the run: its row names the first such image,
 * and that image's row names it (if it names no copy yet). */
static void mark_copies(grade_row *rows, int k)
{
    char text[sizeof rows->remark];
    const char *said = "identical to ";
    int j;
    for (j = 0; j < k && rows[k].hashed; j++) {
        if (!rows[j].hashed || memcmp(rows[j].sha, rows[k].sha, sizeof rows[k].sha)) continue;
        snprintf(text, sizeof text, "%s%s, pixel for pixel (the SHA-256 of the pixels)", said, rows[j].path);
        add_remark(&rows[k], text);
        rows[k].flagged = 1;
        snprintf(text, sizeof text, "%s%s, pixel for pixel (the SHA-256 of the pixels)", said, rows[k].path);
        if (!strstr(rows[j].remark, said)) add_remark(&rows[j], text), rows[j].flagged = 1;
        return;
    }
}

/* Grades one image into its row, rows[index] (an earlier row with the same pixels is marked, and
 * marks it): 0 pass, 1 fail, 2 could not be read or graded. keep (or NULL) receives the graded image,
 * for the class's page. */
static int grade_one(grade_row *rows, int index, const run *s, const char *path, int skip, image *keep)
{
    grade_row *row = &rows[index];
    const grade_job *j = &s->job;
    grade_hypothesis h[GRADE_MAX_HYP];
    image img, steps = {0, 0, NULL};
    grade_report r;
    grade_opts o = j->o;
    int rc, nh = 0;
    memset(row, 0, sizeof *row);
    row->path = path;
    rc = grade_read_image(&img, row, &s->R.refs, j->ref);
    if (rc && s->loud && j->nimages == 1) grade_print_row(row);
    if (rc) return row->status = rc;
    if (img_is_rgbe(path)) o.step = &steps;   /* RGBE: its quantisation is part of its noise */
    if ((o.step && grade_rgbe_steps(&steps, &img)) || grade_compute(&r, &img, &s->R.ref, s->R.refs.var, &o)) {
        fprintf(stderr, "pathlab grade: out of memory\n");
        img_free(&img);
        img_free(&steps);
        return row->status = 2;
    }
    if (s->loud) grade_print_report(&r, row->path, j->ref, &o);
    check_integrity(row, &img, s);
    mark_copies(rows, index);
    grade_fill_row(row, &r);
    row->status = grade_failed(&r);
    if (row->status == 1 && grade_biased(&r) && diagnose(row, &img, s, &o, grade_excess(&r), h, &nh)) row->status = 2;
    img_free(&steps);
    write_heatmap(row, &r, s, skip);
    write_page(row, &r, &img, s, h, nh, skip);
    grade_free(&r);
    if (keep && row->status < 2) { *keep = img; img.px = NULL; }
    img_free(&img);
    return row->status;
}

/* Each image in turn, its row printed; the worst status. */
static int grade_all(run *s, grade_row *rows, image *kept, const int *skip)
{
    const grade_job *j = &s->job;
    int k, rc = 0;
    for (k = 0; k < j->nimages; k++) {
        if (s->loud && k) printf("\n");
        grade_one(rows, k, s, j->images[k], skip[k], kept ? &kept[k] : NULL);
        if (!s->loud || j->nimages > 1) grade_print_row(&rows[k]);
        if (rows[k].status > rc) rc = rows[k].status;
        if (rows[k].output_failed) rc = 2;
    }
    return rc;
}

/* The reference, then the pages' folder: bad input writes nothing. 0, or 2 (said). */
static int start(run *s)
{
    const grade_job *j = &s->job;
    if (grade_reference_read(&s->R, j->ref, j->var, j->layers) || grade_pages_setup(&s->pages, j->pages, j->report)) return 2;
    s->loud = j->nimages == 1 || j->details;
    if (s->R.has_meta) grade_reference_print_provenance(&s->R, j->ref);
    if (s->R.has_meta) s->job.o.ref_var_dof = s->R.meta.variance_dof;   /* a sobol reference's variance: 3 dof */
    if (!s->loud) grade_print_class_header(&j->o, j->ref, j->nimages, &s->R.refs, s->R.var_path, s->R.layer_prefix);
    return 0;
}

/* 1 after saying so when an image's page would be the report itself (--pages the report's folder,
 * a student named like the report: index.pfm beside --report out/index.html): the report, written
 * last, would replace that page, and link the student to the class's table. */
static int page_is_report(const run *s, const int *skip)
{
    const grade_job *j = &s->job;
    char page[PATH_CAP], report_dir[PATH_CAP];
    const char *name = j->report ? path_file_name(j->report) : NULL;
    int k;
    if (!name || !s->pages.dir[0]) return 0;
    snprintf(report_dir, sizeof report_dir, "%.*s", name > j->report ? (int)(name - j->report) : 1, name > j->report ? j->report : ".");
    if (!path_same_file(report_dir, s->pages.dir)) return 0;
    for (k = 0; k < j->nimages; k++) {
        if (grade_page_path(page, sizeof page, &s->pages, j->images[k], skip[k]) || strcmp(path_file_name(page), name)) continue;
        fprintf(stderr, "pathlab grade: the page of %s would be %s, the --report itself: give --pages another folder, or the report "
                "another name\n", shown(j->images[k]), shown(page));
        return 1;
    }
    return 0;
}

int grade_run(const grade_job *job)
{
    int n = job->nimages, k, rc = 0, started;
    run *s = calloc(1, sizeof *s);
    grade_row *rows = calloc((size_t)n + 1, sizeof *rows);
    image *kept = NULL;    /* the graded images, kept for the class's page (--report X.html) */
    int *skip = calloc((size_t)n + 1, sizeof *skip);   /* the name of each image's outputs (page_paths.h) */
    if (job->report && path_ends_with(job->report, ".html") && !(kept = calloc((size_t)n, sizeof *kept))) rc = 2;
    if (!s || !rows || !skip || grade_mark_same_names(job->images, n, skip)) rc = 2;
    if (s) s->job = *job;
    if (!rc) rc = start(s);
    if (!rc && page_is_report(s, skip)) rc = 2;
    started = !rc;
    if (started) rc = grade_all(s, rows, kept, skip);
    if (started && n > 1) grade_print_summary(rows, n, &s->job.o);
    if (started && job->report && grade_write_report(job->report, rows, n, &s->job.o, job->ref, &s->R.refs, kept)) rc = 2;
    else if (started && job->report) printf("report: %s\n", shown(job->report));
    for (k = 0; kept && k < n; k++) img_free(&kept[k]);
    if (s) grade_reference_free(&s->R);
    free(kept);
    free(skip);
    free(rows);
    free(s);
    return rc;
}
