/* render_cmd.c — pathlab render: flags, scene, camera, render (resumed or not), image files with
 * their sidecars, and what a stop by Ctrl-C or --time wrote. */
#include "cmd/render_cmd.h"
#include "sys/shown.h"
#include "util/path.h"
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "cmd/render_args.h"
#include "cmd/render_adaptive.h"
#include "files/render_meta.h"
#include "image/exposure.h"
#include "cmd/render_resume.h"
#include "files/resume.h"
#include "render/plan.h"
#include "cmd/version.h"
#include "sys/interrupt.h"
#include "sys/output_path.h"
#include "sys/progress.h"

/* 1 if the render needs independent samples: a variance (--variance), more samples added later
 * (--resume) or merged (--samples), or the adaptive allocation (render_plan_default_sampler). */
static int needs_independent(const render_args *a)
{
    return a->variance || a->resume || a->samples_given || a->adaptive || a->target_given;
}

/* The files a render reads that its command line names: no output may be one of them. Their count.
 * A view file (--view, SCENE.view) may be --write-view's: it is then updated with the camera flags,
 * a camera in the same form (an orbiter file is not: --write-view over it replaced the student's). */
static int render_inputs(const render_args *a, render_input in[RENDER_MAX_INPUTS])
{
    int k = 0;
    in[k].what = "the scene", in[k++].path = a->scene;
    in[k].what = "--orbiter", in[k++].path = a->cam.orbiter;
    in[k].what = "--sky", in[k++].path = a->ro.sky.kind == SKY_IMAGE ? a->ro.sky.path : NULL;
    in[k].what = "--mtl", in[k++].path = a->so.obj.mtl;
    return k;
}

/* 1 (said) if an output is a texture or an MTL file of the scene (render_files_scene_clash). */
static int writes_over_scene(const render_args *a, const scene *s)
{
    const char *outs[4];
    outs[0] = a->out, outs[1] = a->variance, outs[2] = a->sample_count, outs[3] = a->cam.write_view;
    return render_files_scene_clash("render", outs, 4, &s->m);
}

/* What render needs beyond valid flag values: a scene, an output it can write, a last bounce for
 * --split, sample flags that go together. 0, or 1 after printing why. */
static int check_render_args(render_args *a)
{
    render_input in[RENDER_MAX_INPUTS];
    if (!a->scene) { fprintf(stderr, "pathlab render: needs a scene: pathlab render SCENE.obj -o FILE\n"); return 1; }
    if (!a->out) { fprintf(stderr, "pathlab render: needs an output: -o FILE.pfm, -o FILE.ppm or -o FILE.png\n"); return 1; }
    if (render_files_check_outputs(in, render_inputs(a, in), a->out, a->variance, a->sample_count,
                                   a->cam.write_view, a->ro.split, a->ro.io.bmin, a->ro.io.bmax))
        return 1;
    if (a->ro.split && a->ro.io.bmax == BOUNCES_NO_END) {
        fprintf(stderr, "pathlab render: --split needs a last bounce, e.g. --bounces 0:8\n");
        return 1;
    }
    if (a->samples_given && (a->spp_given || a->resume)) {
        fprintf(stderr, "pathlab render: --samples A:B says which samples to render: not with %s\n", a->resume ? "--resume" : "--spp");
        return 1;
    }
    if (a->resume && img_format_of(a->out) != IMG_PFM) {
        fprintf(stderr, "pathlab render: --resume adds samples to a .pfm image, not to %s\n", shown(a->out));
        return 1;
    }
    if (a->resume && !a->spp_given && a->ro.time_limit <= 0) {
        fprintf(stderr, "pathlab render: --resume needs --spp N (the samples wanted in all) or --time SEC\n");
        return 1;
    }
    return render_adaptive_check(a) || render_check_camera_flags(a);
}

/* The plan of the render the valid flags a ask for (before --resume adds what the image had). */
static void make_plan(const render_args *a, render_plan *p)
{
    p->ro = a->ro;
    p->ro.sampler = a->sampler_given ? a->ro.sampler : render_plan_default_sampler(needs_independent(a));
    p->ro.io.rr_below = render_rr_below(a->ro.io.rr_below, p->ro.sampler);
    p->ro.first = a->samples_given ? a->samples[0] : 0;
    if (a->samples_given) p->ro.spp = (int)(a->samples[1] - a->samples[0]);
    else if (a->spp_given) p->ro.spp = a->spp;
    else if (a->target_given) p->ro.spp = RENDER_ADAPTIVE_DEFAULT_CAP;
    else if (a->ro.time_limit > 0) p->ro.spp = RENDER_SPP_UNTIL_TIME;
    else p->ro.spp = a->spp;
    p->had = 0;
    p->total = p->ro.spp;
    p->adaptive = a->adaptive;
    p->ao = a->ao;
    p->ao.time_limit = a->ro.time_limit;
    p->ao.pilot_rr_below = render_rr_below(a->ro.io.rr_below, SAMPLER_INDEPENDENT);
}

static int parse_render_args(render_args *a, render_plan *p, int argc, char **argv)
{
    cli_flag t[RENDER_NFLAGS], ta[RENDER_ADAPTIVE_NFLAGS];
    const cli_flag *tables[3];
    const char *words[1];
    int nwords;
    render_args_init(a);
    render_flag_table(a, t);
    render_adaptive_flag_table(a, ta);
    tables[0] = t;
    tables[1] = ta;
    tables[2] = NULL;
    if (cli_parse("render", argc, argv, tables, a, words, 1, &nwords)) return 1;
    a->scene = nwords ? words[0] : NULL;
    if (check_render_args(a)) return 1;
    make_plan(a, p);
    return render_plan_check_sampler(p, a->variance);
}

/* The sidecar of this render, its sample range aside: what must match for pieces to merge. */
static void describe_render(const render_args *a, const render_plan *p, const scene *s, sidecar *m)
{
    render_meta_describe(m, &p->ro, a->scene, s, &a->cam.vw, pathlab_revision());
    render_meta_describe_scene(m, &p->ro.io, &a->so);
    render_adaptive_describe(a, m);
}

/* --resume: reads the render at -o, checks it is this render, and sets the plan's samples: those
 * it had, and the rest up to --spp in all from the end of its samples. 1 if done already (prints
 * so), 2 on error. */
static int prepare_resume(render_args *a, render_plan *p, const sidecar *now, render_files *prev, char *var_out, size_t cap)
{
    sidecar had;
    int64_t have;
    /* a flag that disagrees with the sidecar, named (a Sobol or adaptive render: resume_read says why not) */
    if (sidecar_read(&had, a->out) == 0 && p->ro.sampler == SAMPLER_INDEPENDENT && !sidecar_is_sobol(&had) && !had.adaptive[0]
        && render_resume_check(now, &had, a->out))
        return 2;
    if (resume_read(prev, &had, a->out, now, p->ro.sampler, a->variance != NULL, a->ro.split)) return 2;
    if (had.variance[0] && !a->variance) {   /* keep its variance up to date: STEM_var.pfm beside -o */
        if (resume_variance_out(var_out, cap, a->out, &had)) return 2;
        a->variance = var_out;
    }
    have = sidecar_spp(&had);
    switch (resume_samples(&had, p->total, a->out, &p->ro.first, &p->ro.spp)) {
    case 1:
        fprintf(stderr, "pathlab render: %s already has %" PRId64 " spp (--spp %" PRId64 "): nothing to add\n", a->out, have, p->total);
        return 1;
    case 2: return 2;
    }
    p->had = have;
    return 0;
}

/* What was rendered, into the sidecar: the samples (with those of the resumed render), and why it
 * stopped; adaptive: the range of the pixels with the most samples, and the counts' cap and mean. */
static int finish_meta(sidecar *m, const render_args *a, const render_plan *p, const render_result *r, const render_files *prev,
                       const adaptive_result *ar)
{
    m->nranges = 1;
    m->range[0][0] = p->ro.first;
    m->range[0][1] = p->ro.first + r->spp;
    m->spp_cap = p->ro.spp;
    m->spp_mean = ar->mean_spp;
    m->pilot_seed = ar->pilot_seed;
    m->variance_dof = r->variance_dof;
    if (r->interrupted) snprintf(m->stopped, sizeof m->stopped, "%s", interrupt_name(r->interrupted));
    else if (p->adaptive && a->target_given && r->spp < ar->max_spp) snprintf(m->stopped, sizeof m->stopped, "time");
    else if (!p->adaptive && r->spp < p->ro.spp && p->ro.time_limit > 0 && a->spp_given) snprintf(m->stopped, sizeof m->stopped, "time");
    return prev->nlayers ? sidecar_add_ranges(m, &prev->meta, "this render", a->out) : 0;
}

/* After a stop by a signal or --time: what was written, and how to go on. */
static void report_stop(const render_args *a, const render_plan *p, const render_result *r, const sidecar *m, const adaptive_result *ar)
{
    char el[32];
    int64_t spp = sidecar_spp(m), asked = p->total;
    progress_duration(el, sizeof el, r->seconds);
    if (r->interrupted && a->adaptive)
        fprintf(stderr, "pathlab render: interrupted (%s) after %s at sample %d of the %d the noisiest pixels wanted "
                "(a mean of %.1f spp per pixel, see the sample count): written %s\n", interrupt_name(r->interrupted), el, r->spp,
                ar->max_spp, ar->mean_spp, shown(a->out));
    else if (r->interrupted)
        fprintf(stderr, "pathlab render: interrupted (%s) at %" PRId64 " of %" PRId64 " spp after %s: written %s%s%s "
                "(add samples with --resume)\n", interrupt_name(r->interrupted), spp, asked, el, a->out,
                a->variance ? " and " : "", a->variance ? a->variance : "");
    else if (a->adaptive && !strcmp(m->stopped, "time"))
        fprintf(stderr, "pathlab render: --time %.9g s: stopped at sample %d of the %d the noisiest pixels wanted: those pixels "
                        "have fewer samples than --target-error asks (see the sample count), written %s\n", a->ro.time_limit, r->spp,
                ar->max_spp, shown(a->out));
    else if (!a->adaptive && r->spp < p->ro.spp && a->spp_given)
        fprintf(stderr, "pathlab render: --time %.9g s: %" PRId64 " of %" PRId64 " spp fitted, written %s\n", a->ro.time_limit, spp, asked, a->out);
}

/* "pathlab render: wrote FILE (and its variance, layers, sidecars)". */
static void say_written(const render_args *a, const render_plan *p)
{
    int nl = a->ro.split ? p->ro.io.bmax - p->ro.io.bmin + 1 : 0;
    fprintf(stderr, "pathlab render: wrote %s", a->out);
    if (a->variance) fprintf(stderr, ", its variance %s", a->variance);
    if (nl > 0) fprintf(stderr, ", %d layer%s (L%d..L%d)", nl, nl > 1 ? "s" : "", p->ro.io.bmin, p->ro.io.bmax);
    if (a->sample_count) fprintf(stderr, ", the sample counts %s", a->sample_count);
    fprintf(stderr, "%s\n", img_format_of(a->out) == IMG_PFM ? ", each PFM with its sidecar .meta" : "");
}

static int render_and_write(render_args *a, render_plan *p, const scene *s, const camera *cam)
{
    render_files prev;
    render_result r;
    adaptive_result ar;
    sidecar m;
    char var_out[PATH_CAP];
    int rc = 0, err;
    memset(&prev, 0, sizeof prev);
    memset(&ar, 0, sizeof ar);
    describe_render(a, p, s, &m);
    if (a->resume && (rc = prepare_resume(a, p, &m, &prev, var_out, sizeof var_out)) != 0) {
        render_files_free(&prev);   /* 1: nothing to add, the files as they are (and the camera asked for) */
        return rc == 1 ? 2 * view_setup_write(&a->cam, a->cmd, a->scene) : 2;
    }
    interrupt_install();   /* from here, a first Ctrl-C stops after the pass and writes what it reached */
    if (p->adaptive ? adaptive_render(s, cam, &p->ro, &p->ao, &r, &ar) : render(s, cam, &p->ro, &r)) { render_files_free(&prev); return 2; }   /* out of memory: said */
    if (!p->ro.quiet && p->adaptive) adaptive_print_summary(&ar, r.seconds);
    else if (!p->ro.quiet) render_print_stats(&r, r.spp, p->had, cam->width * cam->height);
    err = finish_meta(&m, a, p, &r, &prev, &ar) || (prev.nlayers && resume_combine(&prev, sidecar_spp(&prev.meta), &r));
    if (isnan(a->exposure)) {   /* --exposure auto: of the image written (image/exposure.h) */
        a->exposure = img_auto_exposure(&r.mean[0]);
        if (!p->ro.quiet) fprintf(stderr, "exposure auto: %+.1f stops (the median luminance of the pixels that are not black to mid-grey)\n", a->exposure);
    }
    err = err || render_files_write_all(a->out, a->variance, a->sample_count, &ar.count, a->exposure, &m, r.mean, r.var,
                                        r.nlayers, p->ro.io.bmin)
              || view_setup_write(&a->cam, a->cmd, a->scene);
    if (!err) report_stop(a, p, &r, &m, &ar);
    if (!err && !p->ro.quiet && !r.interrupted && !m.stopped[0]) say_written(a, p);   /* else report_stop said it */
    if (!err && r.interrupted) rc = 128 + r.interrupted;
    render_result_free(&r);
    render_files_free(&prev);
    adaptive_result_free(&ar);
    return err ? 2 : rc;   /* a write failed: said, with the file and the system's reason */
}

int render_main(int argc, char **argv)
{
    render_args a;
    render_plan p;
    scene s;
    camera cam;
    int rc, nargs;
    char *args[RESUME_MAX_ARGS], words[6 * SIDECAR_TEXT + 64];
    /* --resume -o FILE: what the command line leaves out is FILE's sidecar's (cmd/render_resume.h) */
    if (render_resume_args(argc, argv, args, &nargs, words, sizeof words)) return 2;
    if (parse_render_args(&a, &p, nargs, args)) return 2;
    if (scene_load(&s, a.scene, &a.so, a.ro.threads, a.ro.quiet)) return 2;
    if (scene_add_sky(&s, &a.ro.sky)) { scene_free(&s); return 2; }
    if (!a.ro.quiet) {
        char tex[48] = "", pairs[96] = "";
        if (s.m.ntextures > 0) snprintf(tex, sizeof tex, ", %d texture%s", s.m.ntextures, s.m.ntextures > 1 ? "s" : "");
        if (s.wholly_seen.bits)   /* the table was made: a small scene with lights */
            snprintf(pairs, sizeof pairs, "; %ld of %ld triangle-emitter pairs need no shadow ray (%.0f ms)", s.wholly_seen.npairs,
                     (long)s.m.ntris * s.wholly_seen.nemitters, 1e3 * s.pairs_seconds);
        fprintf(stderr, "%s: %d triangles (%d degenerate dropped), %d emitting, %d materials%s; loaded in %.0f ms, BVH in %.0f ms%s\n",
                shown(a.scene), s.m.ntris, s.m.ndegenerate, s.lights.n, s.m.nmats - 1, tex, 1e3 * s.load_seconds, 1e3 * s.bvh_seconds, pairs);
    }
    if (writes_over_scene(&a, &s) || render_make_camera(&a, &s, &cam)) { scene_free(&s); return 2; }
    if (!scene_has_light(&s))
        fprintf(stderr, "pathlab render: warning: %s has no emitters (no material with Ke > 0) and %s: the image is black\n", shown(a.scene),
                a.ro.sky.kind == SKY_NONE ? "no --sky" : "the --sky given is black (every pixel 0)");
    rc = render_and_write(&a, &p, &s, &cam);
    scene_free(&s);
    return rc;
}
