/* grade_page.c — grade's pages (see grade_page.h). The HTML around the viewer is built in memory
 * streams (open_memstream); paths, mistakes and evidence are escaped. */
#include "grade/grade_page.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sys/output_path.h"
#include "sys/shown.h"
#include "util/path.h"

static const char *const CHANNELS[3] = {"red", "green", "blue"};
/* A page larger than this in half floats goes compact (image/html_page.h): a 1024x768 grade page,
 * image and reference, is then 7.9 MB instead of 19 (the reference's variance left out). */
#define GRADE_PAGE_BYTES 7500000

/* ---- the marks ---- */

static int overlaps(const html_mark *m, int x0, int y0, int x1, int y1)
{
    return m->x < x1 && x0 < m->x + m->w && m->y < y1 && y0 < m->y + m->h;
}

/* A block's words: "too dark: -5.1 sigma, -3.2% in green", with its scale when coarse. */
static void block_label(char *s, size_t cap, const grade_block *b, int side)
{
    int ch = b->channel;
    double rel = b->ref[ch] != 0.0 ? b->diff[ch] / b->ref[ch] : 0.0;
    int n = snprintf(s, cap, "too %s: %+.1f sigma, %+.1f%% in %s", b->sign > 0 ? "bright" : "dark", b->t[ch], 100.0 * rel, CHANNELS[ch]);
    if (side && n > 0 && (size_t)n < cap) snprintf(s + n, cap - (size_t)n, " (%dx%d blocks)", side, side);
}

static void add_mark(grade_marks *out, int x0, int y0, int x1, int y1, const grade_block *b, int side)
{
    html_mark *m = &out->m[out->n];
    if (out->n == GRADE_MAX_MARKS) return;
    m->x = x0, m->y = y0, m->w = x1 - x0, m->h = y1 - y0;
    block_label(out->label[out->n], sizeof out->label[out->n], b, side);
    m->label = out->label[out->n++];
}

/* The finest blocks: runs of one sign along each row, a run joined to the mark above it when both
 * have the same columns, sign, and the label of the block with the largest |t|. */
static void finest_marks(grade_marks *out, const grade_report *r, const grade_block **worst)
{
    int bx, by, end, k, above;
    for (by = 0; by < r->nby; by++)
        for (bx = 0; bx < r->nbx; bx = end) {
            const grade_block *b = &r->blocks[by * r->nbx + bx], *w = b;
            for (end = bx + 1; b->sign && end < r->nbx && r->blocks[by * r->nbx + end].sign == b->sign; end++) {
                const grade_block *e = &r->blocks[by * r->nbx + end];
                if (fabs(e->t[e->channel]) > fabs(w->t[w->channel])) w = e;
            }
            if (!b->sign) continue;
            for (above = -1, k = 0; k < out->n; k++)
                if (out->m[k].x == b->x0 && out->m[k].x + out->m[k].w == r->blocks[by * r->nbx + end - 1].x1 &&
                    out->m[k].y + out->m[k].h == b->y0 && worst[k]->sign == b->sign) above = k;
            if (above >= 0) {
                out->m[above].h = b->y1 - out->m[above].y;
                if (fabs(w->t[w->channel]) > fabs(worst[above]->t[worst[above]->channel])) worst[above] = w;
                block_label(out->label[above], sizeof out->label[above], worst[above], 0);
            } else if (out->n < GRADE_MAX_MARKS) {
                worst[out->n] = w;
                add_mark(out, b->x0, b->y0, r->blocks[by * r->nbx + end - 1].x1, b->y1, w, 0);
            }
        }
}

/* The regions that failed: the finest significant blocks, adjacent ones of one sign merged (runs
 * along a row, then runs of equal extent in consecutive rows), each labelled with its largest t;
 * the coarser scales' significant blocks that overlap none of those; the missed exact pixels. */
static void grade_make_marks(grade_marks *out, const grade_report *r)
{
    static const grade_block *worst[GRADE_MAX_MARKS];
    int s, k, j, side, free_of_marks;
    out->n = 0;
    finest_marks(out, r, worst);
    for (s = 0; s < r->ncoarse; s++)
        for (k = 0; k < r->coarse[s].nblocks; k++) {
            const grade_block *b = &r->coarse[s].blocks[k];
            if (!b->sign) continue;
            for (free_of_marks = 1, j = 0; j < out->n; j++) free_of_marks &= !overlaps(&out->m[j], b->x0, b->y0, b->x1, b->y1);
            side = r->coarse[s].side;   /* in pixels already */
            if (free_of_marks) add_mark(out, b->x0, b->y0, b->x1, b->y1, b, side);
        }
    for (s = 0; s < 2 && out->n < GRADE_MAX_MARKS; s++) {
        const int *box = r->exact_box[s];
        if (!r->exact_side[s]) continue;
        snprintf(out->label[out->n], sizeof out->label[out->n], "%ld exact pixels missed, %s than the reference",
                 r->exact_side[s], s ? "brighter" : "darker");
        out->m[out->n].x = box[0], out->m[out->n].y = box[1], out->m[out->n].w = box[2] - box[0], out->m[out->n].h = box[3] - box[1];
        out->m[out->n].label = out->label[out->n];
        out->n++;
    }
}

/* ---- the pages ---- */

static const char *verdict_word(int status) { return status == 0 ? "PASS" : status == 1 ? "FAIL" : "UNREADABLE"; }

/* The verdict, the bias and where, the likely mistakes with their evidence, what the marks are. */
static int put_verdict(FILE *f, const grade_page *p)
{
    char bias[128];
    int k, err = 0;
    grade_bias_text(bias, sizeof bias, p->row);
    if (p->back) { fputs("<p><a href=\"", f); err |= html_put_escaped(f, p->back); fputs("\">the class report</a></p>\n", f); }
    fprintf(f, "<p class=\"verdict\"><b>%s</b> against ", verdict_word(p->row->status));
    err |= html_put_escaped(f, p->ref_path);
    fprintf(f, " at family-wise level alpha %g", p->r->alpha);
    if (bias[0]) { fputs("; bias ", f); err |= html_put_escaped(f, bias); }
    if (p->row->where[0]) { fputs("; significant in ", f); err |= html_put_escaped(f, p->row->where); }   /* its own scope */
    fputs(".</p>\n", f);
    if (p->row->remark[0]) {
        fprintf(f, "<p class=\"flagged\"><b>%s</b>: ", p->row->flagged ? "FLAGGED" : "Note");
        err |= html_put_escaped(f, p->row->remark);
        fputs("</p>\n", f);
    }
    if (p->row->status == 1) fputs(p->nh ? "<p>Likely mistake:</p>\n<ul class=\"mistakes\">\n" : "<p>None of the catalogue of mistakes explains "
                                   "the difference (pathlab grade; docs/grading.md).</p>\n", f);
    for (k = 0; k < p->nh; k++) {
        fputs("<li>", f);
        err |= html_put_escaped(f, p->h[k].what);
        fputs(": ", f);
        err |= html_put_escaped(f, p->h[k].evidence);
        fputs("</li>\n", f);
    }
    if (p->row->status == 1 && p->nh) fputs("</ul>\n", f);
    fprintf(f, "<p>Outlined: the blocks of %dx%d pixels (or larger) whose mean differs from the reference's beyond noise "
               "(sigma: Student's t of that difference), and the missed noise-free pixels.</p>\n", p->r->block, p->r->block);
    return err;
}

int grade_write_page(const grade_page *p)
{
    static grade_marks marks;
    html_image im, ref;
    html_page page;
    char *before = NULL;
    size_t nb;
    FILE *f = open_memstream(&before, &nb);
    int err = !f, nmarks;
    if (f) err |= put_verdict(f, p);
    if (f) err |= fclose(f) != 0;
    if (err) { fprintf(stderr, "%s: out of memory\n", shown(p->path)); free(before); return 1; }
    grade_make_marks(&marks, p->r);
    nmarks = marks.n;
    memset(&page, 0, sizeof page);
    im.name = path_file_name(p->row->path), im.img = p->img, im.var = NULL, im.link = NULL;
    ref.name = path_file_name(p->ref_path), ref.img = p->refs->ref, ref.var = p->refs->var, ref.link = NULL;
    page.title = p->row->path, page.images = &im, page.nimages = 1, page.ref = &ref;
    page.marks = marks.m, page.nmarks = nmarks, page.before_html = before, page.max_bytes = GRADE_PAGE_BYTES;
    err = html_page_write(p->path, &page);
    free(before);
    return err;
}

/* The class's table: image (linked to its page), verdict, bias, where, likely mistake. */
static int put_class_table(FILE *f, const grade_row *rows, int n)
{
    char bias[128];
    int k, err = 0;
    fputs("<table class=\"grades\">\n<tr><th>image</th><th>verdict</th><th>bias +- error</th><th>where</th><th>likely mistake</th><th>flagged</th></tr>\n", f);
    for (k = 0; k < n; k++) {
        const grade_row *r = &rows[k];
        grade_bias_text(bias, sizeof bias, r);
        fputs("<tr><td>", f);
        if (r->page[0]) { fputs("<a href=\"", f); err |= html_put_escaped(f, r->page); fputs("\">", f); }
        err |= html_put_escaped(f, r->path);
        fprintf(f, "%s</td><td>%s%s</td><td>", r->page[0] ? "</a>" : "", verdict_word(r->status), r->flagged ? " (FLAGGED)" : "");
        err |= html_put_escaped(f, bias);
        fputs("</td><td>", f);
        err |= html_put_escaped(f, r->where);
        fputs("</td><td>", f);
        err |= html_put_escaped(f, r->mistake);
        fputs("</td><td>", f);
        err |= html_put_escaped(f, r->remark);
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n", f);
    return err;
}

/* The graded images as the page's images, each linked to its page: how many. */
static int class_images(html_image *im, const grade_row *rows, int n, const image *imgs)
{
    int k, m = 0;
    for (k = 0; imgs && k < n; k++) {
        if (!imgs[k].px) continue;
        im[m].name = rows[k].path, im[m].img = &imgs[k], im[m].var = NULL;
        im[m++].link = rows[k].page[0] ? rows[k].page : NULL;
    }
    return m;
}

int grade_write_class_page(const char *path, const grade_row *rows, int n, const grade_opts *o, const char *ref_path,
                           const grade_refs *refs, const image *imgs)
{
    html_image ref, *im = malloc(((size_t)n + 1) * sizeof *im);
    html_page page;
    char *before = NULL, title[PATH_CAP];   /* "Grades against REF" */
    size_t nb;
    FILE *f = open_memstream(&before, &nb);
    int err = !f || !im;
    if (f) {
        fprintf(f, "<p>Each image graded at family-wise level alpha %g (pathlab grade; docs/grading.md); "
                   "below, the graded images against the reference.</p>\n", o->alpha);
        err |= put_class_table(f, rows, n);
        err |= fclose(f) != 0;
    }
    if (err) { fprintf(stderr, "%s: out of memory\n", shown(path)); free(before); free(im); return 1; }
    snprintf(title, sizeof title, "Grades against %s", ref_path);
    memset(&page, 0, sizeof page);
    ref.name = path_file_name(ref_path), ref.img = refs->ref, ref.var = refs->var, ref.link = NULL;
    page.title = title, page.images = im, page.nimages = class_images(im, rows, n, imgs), page.before_html = before;
    page.max_bytes = GRADE_PAGE_BYTES;
    if (page.nimages) page.ref = &ref;
    else page.images = &ref, page.nimages = 1;   /* nothing graded: the reference alone */
    err = html_page_write(path, &page);
    free(before);
    free(im);
    return err;
}
