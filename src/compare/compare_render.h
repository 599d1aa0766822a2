/* compare_render.h — an estimator rendered for pathlab compare: the total image (and the variance of
 * each pixel's mean), and its speed for equal time: rendered at 1, 2, 4 ... spp until one render
 * lasts the target, its seconds per sample are that render's time over its spp. Fixed costs
 * (threads, tiles) and a cold cache make the estimate pessimistic. */
#ifndef PATHLAB_COMPARE_RENDER_H
#define PATHLAB_COMPARE_RENDER_H
#include "render/render.h"

/* Renders with options ro into mean, and the variance into var if not NULL (its degrees of freedom
 * into *dof if not NULL: 0 many, render.h); *secs its time. 0, or 1. */
int compare_render_image(const scene *s, const camera *cam, const render_opts *ro, image *mean, image *var, int *dof, double *secs);
/* Seconds per sample with options ro (ro.spp aside): renders until one lasts target seconds (or 2^20 spp). */
int compare_calibrate(const scene *s, const camera *cam, render_opts ro, double target, double *sec_per_spp);
#endif
