/* estimators.h — the estimators of `pathlab compare --estimators LIST`, a small language:
 * - an estimator is a list of render flags and names, joined with '+' or spaces: "light+solid-angle",
 *   "mis-power --rr off". Each name of a strategy table stands for its flag: light brdf mis-balance
 *   mis-power = --direct X; uniform cosine dir-brdf = --dir X (dir-brdf, as brdf is --direct brdf);
 *   area triangle power solid-angle tree = --light X;
 * - "LABEL=FLAGS" names an estimator; otherwise its text is its label;
 * - estimators are separated by commas, except a comma followed by a number, which stays inside a
 *   value (--eye 0,1,5). */
#ifndef PATHLAB_ESTIMATORS_H
#define PATHLAB_ESTIMATORS_H
#include "cmd/render_args.h"

typedef struct {
    char label[600];     /* as long as the text it comes from */
    char slug[64];       /* the label as a file name: lower-case letters, digits and '-' */
    char flags[600];     /* the render flags, names expanded, separated by spaces */
    char words[600];     /* the estimator's text cut into words: its flags' values point into it */
    render_args a;       /* the shared flags, then the estimator's own */
} estimator_spec;

/* Parses LIST into est[0..*n-1] (at most max), each estimator's flags applied on top of base.
 * --spp, -o, --variance, --split and a scene are refused inside an estimator. 0, or 1 after
 * printing why. */
int estimators_parse(const char *list, const render_args *base, estimator_spec *est, int max, int *n);
#endif
