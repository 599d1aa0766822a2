/* compare_render.c — one estimator rendered, and its speed measured (compare_render.h). */
#include "compare/compare_render.h"

int compare_render_image(const scene *s, const camera *cam, const render_opts *ro, image *mean, image *var, int *dof, double *secs)
{
    render_result r;
    if (render(s, cam, ro, &r)) return 1;
    *mean = r.mean[0];
    r.mean[0].px = NULL;
    if (var) { *var = r.var[0]; r.var[0].px = NULL; }
    if (dof) *dof = r.variance_dof;
    *secs = r.seconds;
    render_result_free(&r);
    return 0;
}

int compare_calibrate(const scene *s, const camera *cam, render_opts ro, double target, double *sec_per_spp)
{
    image im;
    double t = 0.0;
    for (ro.spp = 1;; ro.spp *= 2) {
        if (compare_render_image(s, cam, &ro, &im, NULL, NULL, &t)) return 1;
        img_free(&im);
        if (t >= target || ro.spp >= (1 << 20)) break;
    }
    *sec_per_spp = t / ro.spp;
    return 0;
}
