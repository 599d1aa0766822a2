/* grade_class.h — grading a class: each student's image read and checked before any statistics
 * (input mistakes are input errors, status 2; a wrong size is a fail with the command that renders
 * a reference at that size), the class's header and summary lines, and the report file (Markdown
 * or CSV: image, verdict, bias +- error, where, likely mistake, its page; or an HTML page). */
#ifndef PATHLAB_GRADE_CLASS_H
#define PATHLAB_GRADE_CLASS_H
#include "grade/grade_diagnose.h"
#include "grade/grade_print.h"

/* The reference, its variance and layers must be finite (variance >= 0): 0, or 2 after saying where. */
int grade_check_reference(const grade_refs *refs, const char *ref_path, const char *var_path);
/* Reads row->path into img and checks it against the reference: 0 (img to be freed), 2 (could not be
 * read: the cause on stderr and in row->mistake), or 1 (wrong size: row->mistake says so, with the
 * command that renders a reference at the image's size; img freed). */
int grade_read_image(image *img, grade_row *row, const grade_refs *refs, const char *ref_path);
void grade_print_class_header(const grade_opts *o, const char *ref_path, int nimages, const grade_refs *refs,
                              const char *var_path, const char *layer_prefix);
void grade_print_summary(const grade_row *rows, int n, const grade_opts *o);
/* Writes the report, by the name's extension (.md, .csv, or .html: a page with the graded images
 * imgs[k] (px NULL: none) against the reference), atomically; 0 or 1 (said why). Rows with a page link
 * to it (Markdown: a last column "page"). */
int grade_write_report(const char *path, const grade_row *rows, int n, const grade_opts *o, const char *ref_path,
                       const grade_refs *refs, const image *imgs);
#endif
