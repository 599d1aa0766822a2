/* render_meta.c — a render's options written as its sidecar's keys. */
#include "files/render_meta.h"
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

/* --sky, at the end of the flags, only when given: the sidecars of renders without a sky stay comparable */
static void describe_sky(char *flags, size_t cap, const sky_spec *sky)
{
    size_t n = strlen(flags);
    if (sky->kind == SKY_CONSTANT)
        snprintf(flags + n, cap - n, " --sky %.9g,%.9g,%.9g", sky->rgb.x, sky->rgb.y, sky->rgb.z);
    else if (sky->kind == SKY_IMAGE) {
        char path[4 * SIDECAR_TEXT];
        sidecar_escape(path, sizeof path, sky->path, 1);
        snprintf(flags + n, cap - n, " --sky %s", path);
    }
}

/* m->sky_id: the fingerprint of the --sky image's pixels (a sky file changed under the same name
 * merged and resumed with renders of the old one); none for a constant sky (in the flags) or none. */
static void describe_sky_id(sidecar *m, const scene *s, const sky_spec *sky)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    if (sky->kind != SKY_IMAGE || !s->sky.L) return;
    h = fingerprint_bytes(h, &s->sky.w, sizeof s->sky.w);
    h = fingerprint_bytes(h, &s->sky.h, sizeof s->sky.h);
    h = fingerprint_bytes(h, s->sky.L, 3 * sizeof(float) * (size_t)s->sky.w * (size_t)s->sky.h);
    snprintf(m->sky_id, sizeof m->sky_id, "fnv1a64:%016" PRIx64, h);
}

void render_meta_describe(sidecar *m, const render_opts *o, const char *scene_path, const scene *s, const view *v,
                          const char *revision)
{
    const integrator_opts *io = &o->io;
    char bmax[16], rr[48];
    memset(m, 0, sizeof *m);
    strcpy(m->kind, "mean");
    strcpy(m->layer, "total");
    m->seed = o->seed;
    snprintf(m->scene, sizeof m->scene, "%s", scene_path);
    snprintf(m->scene_id, sizeof m->scene_id, "fnv1a64:%016" PRIx64, mesh_fingerprint(&s->m));
    describe_sky_id(m, s, &o->sky);
    snprintf(bmax, sizeof bmax, io->bmax == BOUNCES_NO_END ? "inf" : "%d", io->bmax);
    /* --rr-below only when it is not 1 (the classic rule): sidecars written before it stay comparable */
    if (io->rr_depth < 0) snprintf(rr, sizeof rr, "off");
    else snprintf(rr, sizeof rr, io->rr_below == 1.0f ? "%d" : "%d --rr-below %.6g", io->rr_depth, (double)io->rr_below);
    /* --sampler only when not independent (whatever the default): the sidecars written before it
     * existed stay comparable, and a sidecar without it is independent */
    snprintf(m->flags, sizeof m->flags, "--bounces %d:%s --light %s --dir %s --direct %s --rr %s --pixel-offset %.9g%s%s%s",
             io->bmin, bmax, LIGHT_STRATEGY_NAMES[io->light], DIR_STRATEGY_NAMES[io->dir], DIRECT_STRATEGY_NAMES[io->direct],
             rr, o->pixel_offset, o->pixel_center ? " --pixel-center" : "", o->sampler != SAMPLER_INDEPENDENT ? " --sampler " : "",
             o->sampler != SAMPLER_INDEPENDENT ? SAMPLER_NAMES[o->sampler] : "");
    describe_sky(m->flags, sizeof m->flags, &o->sky);
    snprintf(m->camera, sizeof m->camera, "eye %.9g,%.9g,%.9g target %.9g,%.9g,%.9g up %.9g,%.9g,%.9g fov %.9g size %dx%d",
             v->eye.x, v->eye.y, v->eye.z, v->target.x, v->target.y, v->target.z, v->up.x, v->up.y, v->up.z, v->fov,
             v->width, v->height);
    snprintf(m->revision, sizeof m->revision, "%s", revision);
    if (o->sampler != SAMPLER_INDEPENDENT) snprintf(m->sampler, sizeof m->sampler, "%s", SAMPLER_NAMES[o->sampler]);
}

void render_meta_describe_scene(sidecar *m, const integrator_opts *io, const scene_opts *so)
{
    size_t n = strlen(m->flags);
    /* each only when not the default: the sidecars written before these flags stay comparable */
    if (io->material != BRDF_BLINN) n += (size_t)snprintf(m->flags + n, sizeof m->flags - n, " --material %s", BRDF_MODEL_NAMES[io->material]);
    if (n < sizeof m->flags && io->normals != NORMALS_SHADING)
        n += (size_t)snprintf(m->flags + n, sizeof m->flags - n, " --normals %s", NORMALS_MODE_NAMES[io->normals]);
    if (n < sizeof m->flags && io->filter != TEXTURE_NEAREST)
        n += (size_t)snprintf(m->flags + n, sizeof m->flags - n, " --texture-filter %s", TEXTURE_FILTER_NAMES[io->filter]);
    if (n < sizeof m->flags && so->obj.decode != TEXTURE_RAW)
        n += (size_t)snprintf(m->flags + n, sizeof m->flags - n, " --texture-decode %s", TEXTURE_DECODE_NAMES[so->obj.decode]);
    if (n < sizeof m->flags && so->obj.mtl) {
        char path[4 * SIDECAR_TEXT];
        sidecar_escape(path, sizeof path, so->obj.mtl, 1);
        snprintf(m->flags + n, sizeof m->flags - n, " --mtl %.*s", (int)(sizeof m->flags - n), path);
    }
}

void render_meta_describe_adaptive(sidecar *m, const adaptive_opts *ao, int target_given, double time_limit)
{
    char target[48] = "", time[48] = "";
    if (target_given) snprintf(target, sizeof target, " --target-error %.9g", ao->target_error);
    if (time_limit > 0) snprintf(time, sizeof time, " --time %.9g", time_limit);   /* it shapes n(x) */
    snprintf(m->adaptive, sizeof m->adaptive, "--adaptive%s%s --pilot %d --min-spp %d", target, time, ao->pilot, ao->min_spp);
}
