/* fuzz_scene.c — libFuzzer harness: an OBJ, its MTL and its view file, then a tiny render.
 * One input holds the three files, split on markers (the format of the inputs in
 * ../shared/data/hostile/, which stay valid seeds):
 *     OBJ text  "@@MTL@@"  MTL text  "@@VIEW@@"  view text
 * The OBJ part is everything before the first "@@MTL@@" (all of it without one); the MTL part runs
 * to the first "@@VIEW@@" after that, and is written as m.mtl beside scene.obj (the seeds say
 * "mtllib m.mtl"); the view part, if there is one, is scene.view. The view file is read whether or
 * not the scene loads, then a 4x4 image is rendered at 1 spp with at most 8 bounces: a bounded
 * render, so that a material whose roulette never stops (Kd >= 1) cannot hide other findings as a
 * timeout. The last byte of the input picks the light, direction, direct and sampler strategies.
 * The image must be finite: render drops (and counts) the samples that are not, and at 1 spp a
 * pixel's mean is one sample. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "scene/camera.h"
#include "render/render.h"
#include "tracer/scene.h"

static const uint8_t *find(const uint8_t *p, const uint8_t *end, const char *marker)
{
    size_t n = strlen(marker);
    for (; (size_t)(end - p) >= n; p++)
        if (*p == (uint8_t)marker[0] && !memcmp(p, marker, n)) return p;
    return NULL;
}

static void options(render_opts *o, uint8_t pick)
{
    memset(o, 0, sizeof *o);
    o->spp = 1;
    o->threads = 1;
    o->quiet = 1;
    o->pixel_offset = 0.5f;
    o->seed = 1;
    o->sampler = (sampler_kind)(pick % 3);
    o->io.light = (light_strategy)(pick / 3 % LIGHT_NSTRATEGIES);
    o->io.dir = (dir_strategy)(pick / 12 % 3);
    o->io.direct = (direct_strategy)(pick / 36 % 4);
    o->io.bmin = 0;
    o->io.bmax = 8;
    o->io.rr_depth = 3;
    o->io.rr_below = render_rr_below(0.0f, o->sampler);
}

static void render_tiny(const scene *sc, view *vw, uint8_t pick)
{
    vec3 lo, hi;
    camera cam;
    render_opts o;
    render_result r;
    int i;
    mesh_bounds(&sc->m, &lo, &hi);
    view_frame_bounds(vw, lo, hi);
    vw->width = vw->height = 4;
    if (camera_init(&cam, vw)) return;
    options(&o, pick);
    if (render(sc, &cam, &o, &r) != 0) return;
    for (i = 0; i < 4 * 4 * 3; i++)
        if (!isfinite(r.mean[0].px[i])) abort();
    render_result_free(&r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const uint8_t *end = data + size, *mtl = find(data, end, "@@MTL@@"), *vw_at = NULL;
    const char *obj_path, *view_path;
    scene sc;
    view vw;
    int vr;
    if (mtl) vw_at = find(mtl + 7, end, "@@VIEW@@");
    obj_path = fuzz_write(0, "scene.obj", data, (size_t)((mtl ? mtl : end) - data));
    if (mtl) fuzz_write(1, "m.mtl", mtl + 7, (size_t)((vw_at ? vw_at : end) - (mtl + 7)));
    else fuzz_absent(1, "m.mtl");
    view_path = vw_at ? fuzz_write(2, "scene.view", vw_at + 8, (size_t)(end - (vw_at + 8))) : fuzz_absent(2, "scene.view");
    view_defaults(&vw);
    vr = view_read(&vw, view_path);
    if (scene_load(&sc, obj_path, NULL, 1, 1) == 0) {
        if (vr <= 0) render_tiny(&sc, &vw, size ? data[size - 1] : 0);
        scene_free(&sc);
    }
    return 0;
}
