/* html_page.c — STAND-IN for the branch `reports` only: a plain HTML page with the title, before_html,
 * one <figure> per image (its name, linked when link is set), the marks as a list and after_html, so
 * that compare's and grade's pages can be built and tested before the viewer (branch `viewer`) is
 * merged. No pixels, no script: the real html_page.c replaces this file at merge time. */
#include "image/html_page.h"
#include "sys/atomic_file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *html_escape(const char *text)
{
    size_t n = 1;
    const char *s;
    char *out, *o;
    for (s = text; *s; s++) n += strchr("&<>\"'", *s) ? 6 : 1;
    if (!(out = malloc(n))) return NULL;
    for (o = out, s = text; *s; s++) {
        const char *e = *s == '&' ? "&amp;" : *s == '<' ? "&lt;" : *s == '>' ? "&gt;" : *s == '"' ? "&quot;" : *s == '\'' ? "&#39;" : NULL;
        if (e) { strcpy(o, e); o += strlen(e); }
        else *o++ = *s;
    }
    *o = '\0';
    return out;
}

/* text escaped into f; 1 when out of memory */
static int put_escaped(FILE *f, const char *text)
{
    char *e = html_escape(text ? text : "");
    if (!e) return 1;
    fputs(e, f);
    free(e);
    return 0;
}

static int put_figure(FILE *f, const html_image *im, const char *role)
{
    int err;
    fprintf(f, "<figure><figcaption>%s", role);
    if (im->link) { fputs("<a href=\"", f); put_escaped(f, im->link); fputs("\">", f); }
    err = put_escaped(f, im->name);
    fprintf(f, "%s (%dx%d%s)</figcaption></figure>\n", im->link ? "</a>" : "", im->img->w, im->img->h, im->var ? ", with variance" : "");
    return err;
}

static int put_body(FILE *f, const html_page *p)
{
    int k, err = 0;
    fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>", f);
    err |= put_escaped(f, p->title);
    fputs("</title></head><body>\n<h1>", f);
    err |= put_escaped(f, p->title);
    fprintf(f, "</h1>\n%s\n", p->before_html ? p->before_html : "");
    for (k = 0; k < p->nimages; k++) err |= put_figure(f, &p->images[k], "");
    if (p->ref) err |= put_figure(f, p->ref, "reference: ");
    for (k = 0; k < p->nstrip; k++) err |= put_figure(f, &p->strip[k], "layer: ");
    if (p->nmarks) fputs("<ul class=\"marks\">\n", f);
    for (k = 0; k < p->nmarks; k++) {
        const html_mark *m = &p->marks[k];
        fprintf(f, "<li>x %d, y %d, %dx%d: ", m->x, m->y, m->w, m->h);
        err |= put_escaped(f, m->label);
        fputs("</li>\n", f);
    }
    if (p->nmarks) fputs("</ul>\n", f);
    fprintf(f, "%s\n</body></html>\n", p->after_html ? p->after_html : "");
    return err;
}

int html_page_write(const char *path, const html_page *page)
{
    char *tmp;
    FILE *f;
    int err;
    if (page->nimages < 1) { fprintf(stderr, "%s: a page needs at least one image\n", path); return 1; }
    if (!(f = atomic_file_open(path, &tmp))) return 1;
    err = put_body(f, page);
    if (err) fprintf(stderr, "%s: out of memory\n", path);
    return atomic_file_close(f, tmp, path, !err) || err;
}
