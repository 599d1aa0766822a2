/* compare_report.c — the table of pathlab compare in three forms (see compare_report.h). */
#include "compare/compare_report.h"
#include <math.h>
#include <errno.h>
#include <string.h>
#include "sys/output_path.h"
#include "util/textfile.h"
#include "util/report_text.h"
#include "sys/shown.h"

double compare_best_eff(const compare_row *rows, int n)
{
    double best = 0.0;
    int i;
    for (i = 0; i < n; i++)
        if (rows[i].eff > best) best = rows[i].eff;
    return best;
}

void compare_print_table(FILE *f, const compare_row *rows, int n)
{
    double best = compare_best_eff(rows, n);
    int i, wl = 9, wf = 5;
    for (i = 0; i < n; i++) {   /* labels and flags are the user's: shown escaped (a newline broke a row) */
        if ((int)strlen(shown(rows[i].label)) > wl) wl = (int)strlen(shown(rows[i].label));
        if ((int)strlen(shown(rows[i].flags)) > wf) wf = (int)strlen(shown(rows[i].flags));
    }
    fprintf(f, "%-*s  %-*s %7s %8s %10s %10s %10s %10s %11s %6s\n", wl, "estimator", wf, "flags", "spp", "time(s)",
            "RMSE", "relMSE", "MAE", "MSE", "efficiency", "ratio");
    for (i = 0; i < n; i++) {
        const compare_row *r = &rows[i];
        fprintf(f, "%-*s  %-*s %7d %8.3f %10.4g %10.4g %10.4g %10.4g %11.4g %6.3f\n", wl, shown(r->label), wf, shown(r->flags),
                r->spp, r->secs, r->rmse, r->relmse, r->mae, r->mse, r->eff, best > 0.0 ? r->eff / best : NAN);
    }
}

static void print_md(FILE *f, const compare_row *rows, int n, const char *notes)
{
    double best = compare_best_eff(rows, n);
    int i;
    fprintf(f, "| estimator | flags | spp | time (s) | RMSE | relMSE | MAE | MSE | efficiency 1/(MSE*time) | ratio to best |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < n; i++) {
        const compare_row *r = &rows[i];
        fputs("| ", f);   /* the label and flags as text: a | or a newline in a label made columns or rows */
        md_put_text(f, r->label);
        fputs(" | ", f);
        md_put_text(f, r->flags);
        fprintf(f, " | %d | %.3f | %.4g | %.4g | %.4g | %.4g | %.4g | %.3f |\n",
                r->spp, r->secs, r->rmse, r->relmse, r->mae, r->mse, r->eff, best > 0.0 ? r->eff / best : NAN);
    }
    fprintf(f, "\nNotes:\n\n%s", notes);
}

/* A CSV field in quotes, its quotes doubled (RFC 4180: a line break inside stays in the field). */
static void csv_field(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static void print_csv(FILE *f, const compare_row *rows, int n)
{
    double best = compare_best_eff(rows, n);
    int i;
    fprintf(f, "estimator,flags,spp,time_s,rmse,relmse,mae,mse,efficiency,ratio_to_best\n");
    for (i = 0; i < n; i++) {
        const compare_row *r = &rows[i];
        csv_field(f, r->label);
        fputc(',', f);
        csv_field(f, r->flags);
        fprintf(f, ",%d,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f\n", r->spp, r->secs, r->rmse, r->relmse, r->mae, r->mse,
                r->eff, best > 0.0 ? r->eff / best : NAN);
    }
}

int compare_write_md(const char *path, const compare_row *rows, int n, const char *notes)
{
    char tmp[PATH_CAP];
    FILE *f = textfile_open(path, tmp, sizeof tmp);
    if (!f) return 1;
    print_md(f, rows, n, notes);
    return textfile_close(f, tmp, path);
}

int compare_write_csv(const char *path, const compare_row *rows, int n)
{
    char tmp[PATH_CAP];
    FILE *f = textfile_open(path, tmp, sizeof tmp);
    if (!f) return 1;
    print_csv(f, rows, n);
    return textfile_close(f, tmp, path);
}
