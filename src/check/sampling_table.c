/* sampling_table.c — check-sampling's table and legend (sampling_table.h). */
#include "check/sampling_table.h"
#include <stdio.h>
#include <string.h>
#include "check/verdict.h"

#define NAME_WIDTH 47

static const char *group_title(sampling_case_kind k)
{
    switch (k) {
    case CASE_WARP: return "sampling.c: directions about the normal (cos_power: Blinn's half vector); cells in (1 - cos theta, phi)";
    case CASE_BRDF: return "brdf.c: brdf_sample (glossy: the reflected direction; mixed: both lobes); cells of the half vector";
    case CASE_TRIANGLE: return "sampling.c: a uniform point on a triangle; 16 x 16 sub-triangles";
    case CASE_LIGHT_CHOICE: return "light.c: the choice of an emitter among 5; one cell per emitter";
    case CASE_LIGHT_POINT: return "light.c: the point on the emitter; sub-triangles, or Arvo's (u1, u2) for solid-angle";
    case CASE_SKY: return "sky.c: a direction toward the sky, by luminance x solid angle; 2 x 2 cells in (cos theta, phi) per pixel";
    }
    return "";
}

static void print_row(const sampling_result *r, double alpha_case)
{
    char p[16], integral[32], gap[16], verdict[48] = "pass", why[40] = "";
    int k, ok_integrals = 1;
    for (k = 0; k < r->nintegrals; k++) ok_integrals &= sampling_integral_pass(r, k);
    snprintf(p, sizeof p, r->chi2.p >= 1e-3 ? "%.3f" : "%.1e", r->chi2.p);
    if (r->nintegrals) snprintf(integral, sizeof integral, "%8.5f %8.5f", r->integral[0], r->integral_want[0]);
    else snprintf(integral, sizeof integral, "%8s %8s", "-", "-");
    if (r->has_formula) snprintf(gap, sizeof gap, "%.1e", r->formula_gap);
    else snprintf(gap, sizeof gap, "-");
    if (!sampling_chi2_pass(r, alpha_case)) strcat(why, ", chi2");
    if (!ok_integrals) strcat(why, ", integral");
    if (!sampling_pdf_pass(r)) strcat(why, ", pdf");
    if (!sampling_samples_pass(r)) strcat(why, ", samples");
    if (*why) snprintf(verdict, sizeof verdict, "FAIL (%s)", why + 2);
    printf("  %-*.*s %9.1f %5d %8s %s %8s  %s\n", NAME_WIDTH, NAME_WIDTH, r->routine, r->chi2.chi2, r->chi2.dof, p,
           integral, gap, verdict);
}

void sampling_print_table(const sampling_case *c, const sampling_result *r, int n, double alpha_case, int quiet)
{
    int i, header = 0;
    for (i = 0; i < n; i++) {
        if (quiet && sampling_result_pass(&r[i], alpha_case)) continue;
        if (!header++)
            printf("  %-*s %9s %5s %8s %8s %8s %8s  %s\n", NAME_WIDTH, "routine", "chi2", "dof", "p-value", "integral",
                   "want", "pdf err", "verdict");
        if (!quiet && (i == 0 || c[i].kind != c[i - 1].kind)) printf("%s\n", group_title(c[i].kind));
        print_row(&r[i], alpha_case);
    }
}

void sampling_print_legend(int n, double alpha_case)
{
    printf("chi2: Pearson's statistic over the cells (those expected under 5 pooled into one); p-value:\n"
           "the chance of a chi2 this large if the samples follow the pdf. FAIL below %.3g, so that all\n"
           "%d cases together pass with probability 1 - %g (Sidak: 1 - (1 - %g)^(1/%d)).\n"
           "integral: the pdf integrated numerically over its domain, to %g of want (want < 1: that share\n"
           "of the reflected directions goes below the surface).\n"
           "pdf err: worst relative gap between the pdf function and the course's formula in double. Also\n"
           "checked: the pdf a sampler returns is the function's; the samples are where they belong (unit\n"
           "directions above the surface, points on their triangle).\n",
           alpha_case, n, CHECK_ALPHA, CHECK_ALPHA, n, CHECK_INTEGRAL_TOL);
}
