/* compare_results.c — an estimator's errors and the reference's noise (compare_results.h). */
#include "compare/compare_results.h"
#include <math.h>
#include "stats/image_diff.h"

void compare_estimators_free(compare_estimator *est, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        img_free(&est[i].img);
        img_free(&est[i].var);
        img_free(&est[i].heat);
    }
}

void compare_reference_noise(compare_reference *ref)
{
    long i, n = 3L * ref->var.w * ref->var.h;
    double sum = 0.0;
    if (!ref->var.px) { ref->mean_var = 0.0; return; }
    for (i = 0; i < n; i++) sum += ref->var.px[i];
    ref->mean_var = sum / n;
}

void compare_measure(compare_row *r, const image *img, const compare_reference *ref)
{
    image_diff ds;
    image_diff_compute(&ds, img, &ref->img);
    r->rmse = ds.rmse;
    r->relmse = ds.relmse;
    r->mae = ds.mae;
    r->mse = ds.rmse * ds.rmse - ref->mean_var;
    /* below the reference's own noise: no MSE can be measured, nor an efficiency (NaN, said by compare;
     * a floor of 1e-30 ranked the estimators by their times) */
    if (!(r->mse > 0.0)) r->mse = NAN;
    r->eff = 1.0 / (r->mse * fmax(r->secs, 1e-9));
}
