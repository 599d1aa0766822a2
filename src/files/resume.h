/* resume.h — render --resume: the render already at -o read back and checked to be this same
 * render, then combined with the new samples (means and variances exactly). */
#ifndef PATHLAB_RESUME_H
#define PATHLAB_RESUME_H
#include "files/render_files.h"
#include "render/render.h"

/* Reads the render at `out` into *prev (its sidecar in *had), checking that it exists, that it and
 * this render (of sampler `sampler`) have independent samples, that it is the render `now`
 * describes (sidecar_check_same), that it has a variance if with_variance, and that it has layers
 * if and only if split. 0, or 1 after printing why. */
int resume_read(render_files *prev, sidecar *had, const char *out, const sidecar *now, sampler_kind sampler,
                int with_variance, int split);
/* The variance that --resume rewrites when no --variance is given: the one the command line implies,
 * STEM_var.pfm beside -o out (into dst[cap]), and only when the sidecar `had` of out names that very
 * file: a name read from a sidecar is never a file to write. 0, or 1 after printing why. */
int resume_variance_out(char *dst, size_t cap, const char *out, const sidecar *had);
/* The samples --resume adds to the render whose sidecar is `had` (of -o out) to hold `total` (1 ..
 * 2^30, --spp) in all: from *first, the index after its last, *spp of them. 0; 1 if it holds `total`
 * already (nothing printed); 2 after printing why: the new indices would pass SIDECAR_INDEX_MAX. */
int resume_samples(const sidecar *had, int64_t total, const char *out, int64_t *first, int *spp);
/* r := prev (n samples) combined with r, layer by layer; 0, or 1 if out of memory (said so). */
int resume_combine(const render_files *prev, int64_t n, render_result *r);
#endif
