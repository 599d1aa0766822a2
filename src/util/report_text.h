/* report_text.h — text from outside (a file name, a folder, a mistake naming them) written into a
 * cell of a Markdown table or of a CSV file so that it stays one inert cell:
 * Markdown: control characters first shown as escapes (sys/shown.h: a newline is "\x0a", no row can
 *   be forged), then & < > " ' and the backslash as HTML entities (no raw HTML), | as &#124; (no
 *   column), [ ] as entities (no link or image: `[x](javascript:...)` stays text), the @, the colon
 *   of "://" and the dot of "www." each in a code span (no autolink, even from renderers that find
 *   them after decoding entities, as cmark-gfm does for e-mail addresses), and ` * ~ and a _ not
 *   inside a word escaped with a backslash (no code span, emphasis or strike-through of our own).
 * CSV (RFC 4180): always in double quotes, a " doubled, control characters shown as escapes (a field
 *   never holds a line break: one line per row); a field that would start with = + - @, a tab or a
 *   carriage return gets a ' before it (OWASP's advice against formula injection: a spreadsheet shows
 *   it as text). */
#ifndef PATHLAB_REPORT_TEXT_H
#define PATHLAB_REPORT_TEXT_H
#include <stdio.h>

void md_put_text(FILE *f, const char *text);
void csv_put_field(FILE *f, const char *text);
#endif
