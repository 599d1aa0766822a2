/* compare_report.h — the table of pathlab compare, one row per estimator: spp, time, RMSE, relMSE,
 * MAE, MSE, efficiency 1/(MSE x time) and its ratio to the best; as aligned columns (the terminal),
 * Markdown with notes under it (table.md) and CSV (table.csv). */
#ifndef PATHLAB_COMPARE_REPORT_H
#define PATHLAB_COMPARE_REPORT_H
#include <stdio.h>

typedef struct {
    const char *label, *flags;
    int spp;
    double secs;                  /* the render's wall-clock time */
    double rmse, relmse, mae;     /* against the reference, as pathlab diff prints them */
    double mse;                   /* RMSE^2 less the reference's own noise, when known */
    double eff;                   /* 1 / (MSE x time) */
} compare_row;

/* The best efficiency, to which each row's is compared (its ratio column). */
double compare_best_eff(const compare_row *rows, int n);
/* The table as aligned columns into f. */
void compare_print_table(FILE *f, const compare_row *rows, int n);
/* Write path atomically (a temporary file renamed at the end); 0, or 1 after printing why.
 * md: the table in Markdown, then "Notes:" and the text of notes. csv: a header line, then one line
 * per row, label and flags quoted. */
int compare_write_md(const char *path, const compare_row *rows, int n, const char *notes);
int compare_write_csv(const char *path, const compare_row *rows, int n);
#endif
