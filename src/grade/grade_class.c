/* grade_class.c — a class's images read and checked, its lines and its report (see grade_class.h). */
#include "grade/grade_class.h"
#include "grade/grade_page.h"
#include "grade/negatives.h"
#include "files/sidecar.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "image/linear_file.h"
#include "image/rgbe.h"
#include "image/radiance.h"
#include "sys/input_file.h"
#include "sys/output_path.h"
#include "sys/shown.h"
#include "util/report_text.h"
#include "util/textfile.h"

#define COMMAND_CAP 8192   /* a render command: several paths and flags */

/* The first NaN, infinite or negative value of im, or -1; *what names it. */
static long first_bad(const image *im, int negative_too, const char **what)
{
    size_t i;
    for (i = 0; i < 3 * (size_t)im->w * im->h; i++) {
        float v = im->px[i];
        if (isnan(v)) { *what = "NaN"; return (long)i; }
        if (isinf(v)) { *what = "infinite"; return (long)i; }
        if (negative_too && v < 0.0f) { *what = "negative"; return (long)i; }
    }
    return -1;
}

int grade_check_reference(const grade_refs *refs, const char *ref_path, const char *var_path)
{
    const char *what;
    long i = first_bad(refs->ref, 0, &what);
    if (i < 0 && refs->var) {
        i = first_bad(refs->var, 1, &what);
        ref_path = var_path;
    }
    if (i < 0) return 0;
    fprintf(stderr, "pathlab grade: %s has a %s value at pixel x %ld, y %ld (y = 0 is the top row): not a reference\n",
            shown(ref_path), what, i / 3 % refs->ref->w, i / 3 / refs->ref->w);
    return 2;
}

/* The command that made ref_path, from the MANIFEST.md beside it ("| name | ... `command` |"), into
 * cmd[cap]; 0 if there is none. */
static int manifest_command(char *cmd, size_t cap, const char *ref_path)
{
    const char *slash = strrchr(ref_path, '/'), *name = slash ? slash + 1 : ref_path;
    char path[PATH_CAP], line[COMMAND_CAP], key[512];
    FILE *f;
    int found = 0;
    snprintf(path, sizeof path, "%.*sMANIFEST.md", slash ? (int)(slash - ref_path + 1) : 0, ref_path);
    snprintf(key, sizeof key, "| %s |", name);
    if (!(f = input_file_open(path, 1))) return 0;   /* a FIFO must not hang the grading */
    while (!found && fgets(line, sizeof line, f)) {
        char *a = strchr(line, '`'), *b = a ? strchr(a + 1, '`') : NULL;
        if (strncmp(line, key, strlen(key)) || !b) continue;
        snprintf(cmd, cap, "%.*s", (int)(b - a - 1), a + 1);
        found = 1;
    }
    fclose(f);
    return found;
}

/* The command's words with --size, -o and --variance made for a w x h reference named STEM-WxH. */
static void resize_command(char *out, size_t cap, const char *cmd, const char *ref_path, int w, int h)
{
    char words[COMMAND_CAP], stem[PATH_CAP], *tok, *save = NULL;
    size_t used = 0, n = strlen(ref_path) > 4 ? strlen(ref_path) - 4 : strlen(ref_path);
    int skip = 0, sized = 0;
    snprintf(words, sizeof words, "%s", cmd);
    snprintf(stem, sizeof stem, "%.*s-%dx%d", (int)n, ref_path, w, h);
    out[0] = '\0';
    for (tok = strtok_r(words, " ", &save); tok && used < cap; tok = strtok_r(NULL, " ", &save)) {
        const char *sep = used ? " " : "", *suffix = skip == 2 ? ".pfm" : "_var.pfm";
        if (skip == 1) used += (size_t)snprintf(out + used, cap - used, "%s%dx%d", sep, w, h), sized = 1;
        else if (skip) used += (size_t)snprintf(out + used, cap - used, "%s%s%s", sep, stem, suffix);
        else used += (size_t)snprintf(out + used, cap - used, "%s%s", sep, tok);
        skip = !strcmp(tok, "--size") ? 1 : !strcmp(tok, "-o") ? 2 : !strcmp(tok, "--variance") ? 3 : 0;
    }
    if (!sized && used < cap) snprintf(out + used, cap - used, " --size %dx%d", w, h);
}

/* The command of a w x h reference from the sidecar of ref_path (its own camera, flags and seed),
 * cut to cap; 0 if it has none. */
static int sidecar_command(char *out, size_t cap, const char *ref_path, int w, int h)
{
    sidecar m;
    char stem[PATH_CAP], cmd[COMMAND_CAP];
    size_t n = strlen(ref_path) > 4 ? strlen(ref_path) - 4 : strlen(ref_path);
    snprintf(stem, sizeof stem, "%.*s-%dx%d", (int)n, ref_path, w, h);
    if (sidecar_read(&m, ref_path) != 0 || sidecar_render_command(&m, w, h, stem, cmd, sizeof cmd)) return 0;
    if (snprintf(out, cap, "%s", cmd) >= (int)cap) out[cap - 1] = '\0';
    return 1;
}

/* A wrong size: a fail, with the command that renders a reference at the image's size. */
static int wrong_size(grade_row *row, int w, int h, const grade_refs *refs, const char *ref_path)
{
    char cmd[COMMAND_CAP] = "", fixed[640];   /* a command longer than 639 characters is cut */
    int rw = refs->ref->w, rh = refs->ref->h;
    int same_aspect = (long)w * rh == (long)h * rw;
    if (sidecar_command(fixed, sizeof fixed, ref_path, w, h)) cmd[0] = '\0';
    else if (manifest_command(cmd, sizeof cmd, ref_path)) resize_command(fixed, sizeof fixed, cmd, ref_path, w, h);
    else snprintf(fixed, sizeof fixed, "pathlab render SCENE.obj --size %dx%d --spp 4096 -o REF-%dx%d.pfm --variance REF-%dx%d_var.pfm "
                  "(the reference's scene, camera and flags)", w, h, w, h, w, h);
    snprintf(row->mistake, sizeof row->mistake, "the wrong image size: %dx%d, the reference is %dx%d (%s); a reference at this size: %s",
             w, h, rw, rh, same_aspect ? "same aspect, another resolution" : "another aspect ratio", fixed);
    row->w = w;
    row->h = h;
    return row->status = 1;
}

static int unreadable(grade_row *row)
{
    struct stat st;
    if (stat(row->path, &st) == 0 && !S_ISREG(st.st_mode))   /* a FIFO, a device, a folder: said in the row too */
        snprintf(row->mistake, sizeof row->mistake, "%s: not an image", input_file_why(S_ISDIR(st.st_mode) ? EISDIR : ENODEV));
    else
        snprintf(row->mistake, sizeof row->mistake, "not a readable %s (pathlab's message on stderr says why)",
                 img_is_rgbe(row->path) ? "Radiance .hdr: missing, header, resolution line, truncated or trailing bytes"
                 : "PFM: missing, byte order, header line ends, truncated or trailing bytes");
    return row->status = 2;
}

int grade_read_image(image *img, grade_row *row, const grade_refs *refs, const char *ref_path)
{
    img_pfm_info info;
    const char *link_out = input_file_link_out(row->path);
    img->w = img->h = 0;
    img->px = NULL;
    if (link_out) {   /* a student's link to the reference, to another's image or to the grader's files */
        snprintf(row->mistake, sizeof row->mistake, "%s (a planted link could show any file of the grader's in the class's "
                 "pages); copy the image in instead", link_out);
        fprintf(stderr, "pathlab grade: %s: %s\n", shown(row->path), row->mistake);
        return row->status = 2;
    }
    /* the header first: a file claiming gigabytes of the wrong kind or size is refused unread (an .hdr
     * is colour, its size from its resolution line: its run-length scanlines could hold 8192^2
     * pixels in 4 MB) */
    if (img_is_rgbe(row->path)) {
        if (img_read_hdr_size(row->path, &info.w, &info.h)) return unreadable(row);
        info.channels = 3;
    } else if (img_read_pfm_header(row->path, &info)) return unreadable(row);
    if (info.channels != refs->channels) {
        snprintf(row->mistake, sizeof row->mistake, "%s (\"%s\", %d channel%s) against a %s reference: write %s",
                 info.channels == 1 ? "greyscale" : "colour", info.channels == 1 ? "Pf" : "PF", info.channels,
                 info.channels == 1 ? "" : "s", refs->channels == 1 ? "greyscale" : "colour",
                 refs->channels == 1 ? "one channel (Pf)" : "the three channels R, G, B (PF)");
        fprintf(stderr, "pathlab grade: %s: %s\n", shown(row->path), shown(row->mistake));
        img_free(img);
        return row->status = 2;
    }
    if (info.w != refs->ref->w || info.h != refs->ref->h) {
        img_free(img);
        return wrong_size(row, info.w, info.h, refs, ref_path);
    }
    if (img_read_linear(img, row->path, &info)) return unreadable(row);
    if (img_check_radiance(img, row->path, 4)) {
        if (first_bad(img, 0, &(const char *){NULL}) >= 0 || !grade_explain_negatives(row->mistake, sizeof row->mistake, img, refs->ref))
            snprintf(row->mistake, sizeof row->mistake, "NaN, infinite or negative values (positions on stderr): radiance is finite and >= 0");
        img_free(img);
        return row->status = 2;
    }
    return 0;
}

void grade_print_class_header(const grade_opts *o, const char *ref_path, int nimages, const grade_refs *refs,
                              const char *var_path, const char *layer_prefix)
{
    printf("pathlab grade: %d images against %s (%dx%d)", nimages, shown(ref_path), refs->ref->w, refs->ref->h);
    printf(var_path ? ", its variance %s" : ", no variance beside it (exact pixels guessed)", var_path);
    if (refs->nlayers) printf(", layers %s_L0..L%d.pfm", shown(layer_prefix), refs->nlayers - 1);
    printf("\neach image is graded at family-wise level alpha %g: an unbiased image fails with probability at most %g, so %d "
           "honest images give about %.2g false alarms in all\n", o->alpha, o->alpha, nimages, o->alpha * nimages);
}

void grade_print_summary(const grade_row *rows, int n, const grade_opts *o)
{
    int k, count[3] = {0, 0, 0}, flagged = 0;
    for (k = 0; k < n; k++) count[rows[k].status]++, flagged += rows[k].flagged;
    printf("summary: %d images, %d pass, %d fail, %d could not be read (alpha %g per image)", n, count[0], count[1], count[2], o->alpha);
    if (flagged) printf("; %d FLAGGED:", flagged);
    for (k = 0; k < n; k++) if (rows[k].flagged) printf(" %s", shown(rows[k].path));
    printf("\n");
}

static const char *verdict_word(int status) { return status == 0 ? "PASS" : status == 1 ? "FAIL" : "UNREADABLE"; }

/* [NAME.html](LINK): the name escaped as any text, the link percent-encoded but for letters, digits
 * and - . _ ~ / (page names are made of those, page_paths.h; a --pages folder may not be). */
static void md_link(FILE *f, const char *link)
{
    const char *s, *base = strrchr(link, '/') ? strrchr(link, '/') + 1 : link;
    fputc('[', f);
    md_put_text(f, base);
    fputs("](", f);
    for (s = link; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || strchr("-._~/", c)) fputc(c, f);
        else fprintf(f, "%%%02X", c);
    }
    fputc(')', f);
}

/* Every text cell goes through md_put_text or csv_put_field (util/report_text.h): a name cannot add a
 * row, a column, a link or markup. */
static void write_md(FILE *f, const grade_row *rows, int n, const grade_opts *o, const char *ref_path)
{
    int k;
    fputs("# Grades against ", f);
    md_put_text(f, ref_path);
    fprintf(f, "\n\nEach image graded at family-wise level alpha %g (`pathlab grade`; see docs/grading.md).\n\n", o->alpha);
    fprintf(f, "| image | verdict | bias +- error | where | likely mistake | page | flagged |\n|---|---|---|---|---|---|---|\n");
    for (k = 0; k < n; k++) {
        const grade_row *r = &rows[k];
        char bias[128];
        grade_bias_text(bias, sizeof bias, r);
        fputs("| ", f);
        md_put_text(f, r->path);
        fprintf(f, " | %s%s | %s | ", verdict_word(r->status), r->flagged ? " (FLAGGED)" : "", bias);
        md_put_text(f, r->where);
        fputs(" | ", f);
        md_put_text(f, r->mistake);
        fputs(" | ", f);
        if (r->page[0]) md_link(f, r->page);
        fputs(" | ", f);
        md_put_text(f, r->remark);
        fprintf(f, " |\n");
    }
}

static void write_csv(FILE *f, const grade_row *rows, int n)
{
    int k;
    fprintf(f, "image,verdict,bias_percent,error_percent,channel,where,likely_mistake,page,flagged\n");
    for (k = 0; k < n; k++) {
        const grade_row *r = &rows[k];
        csv_put_field(f, r->path);
        fprintf(f, ",%s,", verdict_word(r->status));
        if (r->status < 2 && r->channel[0] && r->bias_se < 0.0) fprintf(f, "%.4f,,%s,", 100 * r->bias, r->channel);
        else if (r->status < 2 && r->channel[0]) fprintf(f, "%.4f,%.4f,%s,", 100 * r->bias, 100 * r->bias_se, r->channel);
        else fprintf(f, ",,,");
        csv_put_field(f, r->where);
        fputc(',', f);
        csv_put_field(f, r->mistake);
        fputc(',', f);
        csv_put_field(f, r->page);
        fputc(',', f);
        csv_put_field(f, r->remark);
        fputc('\n', f);
    }
}

int grade_write_report(const char *path, const grade_row *rows, int n, const grade_opts *o, const char *ref_path,
                       const grade_refs *refs, const image *imgs)
{
    char tmp[PATH_CAP];
    size_t len = strlen(path);
    FILE *f;
    if (len > 5 && !strcmp(path + len - 5, ".html")) return grade_write_class_page(path, rows, n, o, ref_path, refs, imgs);
    if (!(f = textfile_open(path, tmp, sizeof tmp))) return 1;
    if (len > 4 && !strcmp(path + len - 4, ".csv")) write_csv(f, rows, n);
    else write_md(f, rows, n, o, ref_path);
    return textfile_close(f, tmp, path);
}
