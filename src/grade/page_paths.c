/* page_paths.c — the pages' folder, names and links (page_paths.h). */
#include "grade/page_paths.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "math/sha256.h"
#include "sys/shown.h"
#include "util/path.h"

/* dir/file (file NULL: dir alone) as an absolute path: the working folder before it when relative. */
static void absolute(char *out, size_t cap, const char *dir, const char *file)
{
    char cwd[PATH_CAP];
    int n;
    if (dir[0] != '/' && getcwd(cwd, sizeof cwd)) n = snprintf(out, cap, "%s/%s%s%s", cwd, dir, file ? "/" : "", file ? file : "");
    else n = snprintf(out, cap, "%s%s%s", dir, file ? "/" : "", file ? file : "");
    if (n < 0 || (size_t)n >= cap) out[0] = '\0';   /* too long: no link rather than a wrong one */
}

/* Made if missing, once the reference has been read (bad input writes nothing). */
int grade_pages_setup(grade_pages *p, const char *pages, const char *report)
{
    const char *base = report ? path_file_name(report) : "";
    size_t stem = strrchr(base, '.') ? (size_t)(strrchr(base, '.') - base) : strlen(base);
    char dir[PATH_CAP];
    p->report = report;
    p->dir[0] = p->back[0] = '\0';
    if (pages) snprintf(p->dir, sizeof p->dir, "%s", pages);
    else if (report) snprintf(p->dir, sizeof p->dir, "%.*s-pages", (int)(base - report + stem), report);
    else return 0;
    if (mkdir(p->dir, 0777) && errno != EEXIST) {
        fprintf(stderr, "pathlab grade: cannot create the folder %s for the pages: %s\n", shown(p->dir), strerror(errno));
        return 1;
    }
    if (!path_is_dir(p->dir)) { fprintf(stderr, "pathlab grade: --pages %s is not a folder\n", shown(p->dir)); return 1; }
    snprintf(dir, sizeof dir, "%.*s", base > report ? (int)(base - report) : 1, base > report ? report : ".");
    if (!report) p->back[0] = '\0';
    else if (!pages) snprintf(p->back, sizeof p->back, "../%s", base);
    else absolute(p->back, sizeof p->back, dir, base);
    return 0;
}

/* The escape of a byte: "_" and two lowercase hex digits. */
static size_t put_escape(char *out, unsigned char c) { return (size_t)sprintf(out, "_%02x", c); }

void grade_output_name(char out[GRADE_NAME_CAP], const char *image, int skip)
{
    const char *name = path_file_name(image);
    size_t stem, k, n = 0;
    int pfm;
    if (skip >= 0) name = image + skip;   /* by its path past the shared folders: ana/render.pfm */
    pfm = path_ends_with(name, ".pfm");
    stem = pfm ? strlen(name) - 4 : strlen(name);
    for (k = 0; k < stem && n < GRADE_NAME_LONG; k++) {
        unsigned char c = (unsigned char)name[k];
        /* capitals escaped too: Ana.pfm and ana.pfm keep two pages on a case-insensitive disk (macOS) */
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || (c == '.' && k > 0)) out[n++] = (char)c;
        else n += put_escape(out + n, c);
    }
    if (k < stem) {   /* too long for a file name: cut, with the hash of the whole name */
        unsigned char d[32];
        int i;
        sha256(name, strlen(name), d);
        n += (size_t)sprintf(out + n, "_h");
        for (i = 0; i < 12; i++) n += (size_t)sprintf(out + n, "%02x", d[i]);
    }
    if (!pfm) out[n++] = '_';   /* a name without .pfm: "x" is x_, "x.pfm" is x */
    out[n] = '\0';
}

int grade_page_path(char *out, size_t cap, const grade_pages *p, const char *image, int skip)
{
    char name[GRADE_NAME_CAP];
    grade_output_name(name, image, skip);
    if (snprintf(out, cap, "%s/%s.html", p->dir, name) >= (int)cap) {
        fprintf(stderr, "pathlab grade: the page of %s would have a path over %d characters\n", shown(image), (int)cap - 1);
        return 1;
    }
    return 0;
}

void grade_page_link(char *out, size_t cap, const grade_pages *p, const char *page)
{
    const char *report = p->report, *slash = report ? strrchr(report, '/') : NULL;
    size_t n = slash ? (size_t)(slash - report) + 1 : 0;
    if (n && !strncmp(page, report, n)) snprintf(out, cap, "%s", page + n);
    else if (page[0] == '/' || !report || (n == 0 && strncmp(page, "../", 3))) snprintf(out, cap, "%s", page);
    else absolute(out, cap, page, NULL);
}

static int by_file_name(const void *a, const void *b)
{
    return strcmp(path_file_name(**(const char *const *const *)a), path_file_name(**(const char *const *const *)b));
}

/* The folders that paths a[0..n) all begin with: the length of their common prefix, cut after its
 * last '/' and before any file name. */
static int shared_folders(const char *const *const *a, int n)
{
    size_t len = strlen(**a), k;
    int i;
    for (i = 1; i < n; i++) {
        for (k = 0; k < len && (*a[i])[k] == (**a)[k]; k++) continue;
        len = k;
    }
    for (i = 0; i < n; i++)
        if (len > (size_t)(path_file_name(*a[i]) - *a[i])) len = (size_t)(path_file_name(*a[i]) - *a[i]);
    while (len > 0 && (**a)[len - 1] != '/') len--;
    return (int)len;
}

int grade_mark_same_names(const char *const *images, int n, int *skip)
{
    const char *const **order = malloc((size_t)n * sizeof *order);
    int k, e, i;
    if (!order) return 1;
    for (k = 0; k < n; k++) order[k] = &images[k], skip[k] = -1;
    qsort(order, (size_t)n, sizeof *order, by_file_name);
    for (k = 0; k < n; k = e) {   /* each run of one file name */
        for (e = k + 1; e < n && !strcmp(path_file_name(*order[k]), path_file_name(*order[e])); e++) continue;
        for (i = k; e - k > 1 && i < e; i++) skip[order[i] - images] = shared_folders(order + k, e - k);
    }
    free(order);
    return 0;
}
