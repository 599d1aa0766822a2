/* test_grade_stats.c — the statistics of `pathlab grade` on synthetic images, where the truth is
 * known: Student's t tails against tables; false alarms on many unbiased images with heavy-tailed
 * (firefly) noise; the fitted relative bias and its standard error calibrated on images 2% too
 * bright; a bias in one quadrant found there, with its sign; a small lamp missing found by its level;
 * the channel a failing row names. */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "grade/grade.h"
#include "grade/grade_print.h"
#include <string.h>
#include "stats/significance.h"
#include "math/rng.h"

/* The reference: a smooth picture from 0.05 to 1, exact (the truth). */
static void make_ref(image *ref, int w, int h)
{
    int x, y, c;
    img_alloc(ref, w, h);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            for (c = 0; c < 3; c++)
                ref->px[3 * (y * w + x) + c] = (float)(0.05 + 0.95 * (x + 2.0 * y + 5.0 * c) / (w + 2.0 * h + 10.0));
}

/* A Monte Carlo image of ref with spp samples per pixel, each sample ref / p with probability p
 * ("fireflies": the skewed noise of a path tracer), times gain where the mask says so. */
static void make_image(image *im, const image *ref, int spp, double p, double gain, int quadrant_only, pcg32 *rng)
{
    int x, y, c, k;
    img_alloc(im, ref->w, ref->h);
    for (y = 0; y < ref->h; y++)
        for (x = 0; x < ref->w; x++) {
            int biased = !quadrant_only || (x < ref->w / 2 && y < ref->h / 2);
            for (k = 0; k < spp; k++) {
                int hit = pcg32_double(rng) < p;   /* one path for the three channels */
                for (c = 0; c < 3; c++) {
                    size_t i = 3 * ((size_t)y * ref->w + x) + c;
                    im->px[i] += hit ? (float)(ref->px[i] / p / spp * (biased ? gain : 1.0)) : 0.0f;
                }
            }
        }
}

static void t_table(void)
{
    /* two-sided 5% and 1% points of Student's t, from tables */
    static const struct { int df; double t, p; } tab[] = {
        {1, 12.706, 0.05}, {2, 4.303, 0.05}, {3, 3.182, 0.05}, {10, 2.228, 0.05},
        {30, 2.750, 0.01}, {63, 2.656, 0.01}, {1000, 1.962, 0.05}, {1000000, 2.576, 0.01}};
    size_t i;
    for (i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        double p = student_t_tail(tab[i].t, tab[i].df);
        check(fabs(p - tab[i].p) < 0.002 * tab[i].p / 0.01, "t_tail_table", "df %d, t %.3f: P(|T| > t) = %.5f, table %.2f",
              tab[i].df, tab[i].t, p, tab[i].p);
    }
}

/* Unbiased images with skewed noise: the fraction that fails must stay near or below alpha. */
static void false_alarms(int spp, double p, int runs)
{
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    image ref, im;
    grade_report r;
    pcg32 rng;
    int k, fails = 0;
    double zmax = 0.0;
    make_ref(&ref, 64, 64);
    pcg32_init(&rng, 42 + spp, 7);
    for (k = 0; k < runs; k++) {
        make_image(&im, &ref, spp, p, 1.0, 0, &rng);
        grade_compute(&r, &im, &ref, NULL, &o);
        fails += grade_failed(&r);
        zmax = fmax(zmax, fmax(fabs(r.image_z[0]), fmax(fabs(r.image_z[1]), fabs(r.image_z[2]))));
        grade_free(&r);
        img_free(&im);
    }
    /* binomial(runs, 0.01): more than 3 + 3 sigma of the mean would be a broken test */
    check(fails <= runs * 0.01 + 3.0 * sqrt(runs * 0.01) + 3, "false_alarms_heavy_tails",
          "%d spp, a sample is 1/p = %.0f times the mean with probability p, else 0: %d of %d unbiased images fail "
          "(alpha 0.01); largest whole-image |z| %.2f", spp, 1.0 / p, fails, runs, zmax);
    img_free(&ref);
}

/* Images 2% too bright: always found, eps near 2%, and its standard error honest. */
static void two_percent(int runs)
{
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    image ref, im;
    grade_report r;
    pcg32 rng;
    int k, found = 0;
    double sum = 0.0, sum2 = 0.0, se = 0.0;
    make_ref(&ref, 64, 64);
    pcg32_init(&rng, 99, 3);
    for (k = 0; k < runs; k++) {
        make_image(&im, &ref, 64, 0.3, 1.02, 0, &rng);
        grade_compute(&r, &im, &ref, NULL, &o);
        found += r.image_fail && r.image_z[1] > 0;
        sum += r.image_eps[1];
        sum2 += r.image_eps[1] * r.image_eps[1];
        se += r.image_eps_se[1];
        grade_free(&r);
        img_free(&im);
    }
    {
        double mean = sum / runs, sd = sqrt(fmax(0.0, (sum2 - runs * mean * mean) / (runs - 1))), mse = se / runs;
        check(found == runs, "two_percent_found", "%d of %d images 2%% too bright fail the whole-image test", found, runs);
        check(fabs(mean - 0.02) < 4.0 * sd / sqrt(runs), "two_percent_eps_unbiased", "mean eps %.4f, expected 0.02 (sd %.4f)", mean, sd);
        /* the spread of eps over the runs against the standard error grade states */
        check(mse > 0.7 * sd && mse < 1.4 * sd, "two_percent_se_calibrated", "stated se %.5f, observed sd of eps %.5f", mse, sd);
    }
    img_free(&ref);
}

/* A bias in the top-left quadrant only: significant blocks there and nowhere else. */
static void quadrant(double gain, int sign)
{
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    image ref, im;
    grade_report r;
    pcg32 rng;
    int b, inside = 0, outside = 0, wrong_sign = 0;
    make_ref(&ref, 64, 64);
    pcg32_init(&rng, 5, 5);
    make_image(&im, &ref, 64, 0.5, gain, 1, &rng);
    grade_compute(&r, &im, &ref, NULL, &o);
    for (b = 0; b < r.nblocks; b++) {
        const grade_block *k = &r.blocks[b];
        if (!k->sign) continue;
        if (k->x1 <= 32 && k->y1 <= 32) inside++; else outside++;
        wrong_sign += k->sign != sign;
    }
    check(grade_failed(&r) && inside >= 8 && outside == 0 && wrong_sign == 0, sign > 0 ? "quadrant_brighter" : "quadrant_darker",
          "gain %.2f in the top-left quadrant: %d of its 16 blocks significant, %d elsewhere, %d of the wrong sign",
          gain, inside, outside, wrong_sign);
    grade_free(&r);
    img_free(&im);
    img_free(&ref);
}

/* The lamp seen directly: 20 bright pixels in a 64x64 image whose blocks mix them with darker ones.
 * Honest (the lamp's value with 1% noise) passes; the lamp missing (1% of its value left, "no L0")
 * fails, found by the level of the lamp's luminance and not by the blocks; also with the
 * reference's variance given (noise floor on). */
static void lamp(void)
{
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    image ref, im, var;
    grade_report r;
    pcg32 rng;
    int x, y, c, missing, with_var;
    make_ref(&ref, 64, 64);
    img_alloc(&var, 64, 64);
    for (y = 8; y < 10; y++)
        for (x = 27; x < 37; x++)
            for (c = 0; c < 3; c++) ref.px[3 * (y * 64 + x) + c] = 20.0f + 0.01f * x;   /* not flat: a flat region is exact */
    for (x = 0; x < 3 * 64 * 64; x++) var.px[x] = 1e-4f * ref.px[x] * ref.px[x];
    for (with_var = 0; with_var < 2; with_var++)
        for (missing = 0; missing < 2; missing++) {
            pcg32_init(&rng, 17, 2);
            make_image(&im, &ref, 64, 0.5, 1.0, 0, &rng);
            for (y = 8; y < 10; y++)
                for (x = 27; x < 37; x++)
                    for (c = 0; c < 3; c++)
                        im.px[3 * (y * 64 + x) + c] = (float)(ref.px[3 * (y * 64 + x) + c] * (missing ? 0.01 : 1.0) * (1.0 + 0.01 * (pcg32_double(&rng) - 0.5)));
            grade_compute(&r, &im, &ref, with_var ? &var : NULL, &o);
            check(grade_failed(&r) == missing && (!missing || r.level_darker >= 1), missing ? "lamp_missing_found" : "lamp_honest_passes",
                  "%s, %s the reference's variance: %s; %d level(s) darker, %d block(s) darker, largest level |t|/limit %.1f",
                  missing ? "the lamp missing" : "the lamp honest", with_var ? "with" : "without",
                  grade_failed(&r) ? "FAIL" : "PASS", r.level_darker, r.ndarker, r.level_excess);
            grade_free(&r);
            img_free(&im);
        }
    img_free(&var);
    img_free(&ref);
}

/* A deep penumbra: the right half black and of variance 0 in the reference, the left half lit by
 * a few hits per pixel (m^2 / var = 2) or, the second time, lit with no noise at all (a hard shadow
 * beside a deterministic region). An honest image that found the light once at x 36 in the black
 * half: in the penumbra that is a rare event, not a missed exact pixel (pass); beside the
 * noise-free region the black pixel is exact and the hit a miss (fail). */
static void penumbra(void)
{
    grade_opts o = {0.01, 0, 0, 0, 0, NULL};
    image ref, im, var;
    grade_report r;
    int p, hard;
    for (hard = 0; hard < 2; hard++) {
        img_alloc(&ref, 64, 64);
        img_alloc(&var, 64, 64);
        for (p = 0; p < 3 * 64 * 64; p++) {
            int x = p / 3 % 64;
            ref.px[p] = x < 32 ? 0.5f + 0.001f * x : 0.0f;
            var.px[p] = x < 32 ? (hard ? 1e-12f : 0.125f) : 0.0f;
        }
        img_alloc(&im, 64, 64);
        memcpy(im.px, ref.px, 3 * 64 * 64 * sizeof(float));
        for (p = 0; p < 3; p++) im.px[3 * (32 * 64 + 36) + p] = 0.3f;
        grade_compute(&r, &im, &ref, &var, &o);
        check(grade_failed(&r) == hard && (hard ? r.exact_fail == 1 : r.black_rare > 0),
              hard ? "a black pixel beside noise-free light is exact" : "a black pixel in a penumbra is not exact",
              "%s; %ld exact, %ld missed, %ld black flat pixels judged as rare events", grade_failed(&r) ? "FAIL" : "PASS",
              r.nexact, r.exact_fail, r.black_rare);
        grade_free(&r);
        img_free(&im);
        img_free(&var);
        img_free(&ref);
    }
}

/* The class row names the channel farthest past its own limit: limits differ by channel (each is
 * widened by its skewness), so the largest |z| (red: 4.5 < 4.82) is not the failing one (green:
 * 4.2 > 4.13). A regression: the row and the verdict line once followed the largest |z|. */
static void worst_channel(void)
{
    grade_report r;
    grade_row row;
    memset(&r, 0, sizeof r);
    memset(&row, 0, sizeof row);
    r.w = r.h = 8;
    r.image_nfit = 12;   /* a fit was made (without one the row shows the plain mean) */
    r.image_z[0] = 4.5, r.image_z[1] = 4.2, r.image_z[2] = 1.0;
    r.image_zlimit[0] = 4.82, r.image_zlimit[1] = 4.13, r.image_zlimit[2] = 4.0;
    r.image_eps[0] = 0.03, r.image_eps[1] = 0.015, r.image_eps[2] = 0.001;
    r.image_fail = 1;
    grade_fill_row(&row, &r);
    check(!strcmp(row.channel, "green") && row.bias == 0.015, "the class row names the channel past its limit (green), not the largest |z| (red)",
          "got %s %+.3f", row.channel, row.bias);
}

int main(void)
{
    worst_channel();
    t_table();
    false_alarms(4, 0.05, 200);
    false_alarms(64, 0.01, 100);
    two_percent(60);
    quadrant(1.2, 1);
    quadrant(0.8, -1);
    lamp();
    penumbra();
    return check_summary();
}
