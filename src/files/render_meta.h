/* render_meta.h — the sidecar of a render from what it runs: the keys that must match for pieces
 * of one render to merge (scene, flags in one canonical form, camera, seed, sampler). */
#ifndef PATHLAB_RENDER_META_H
#define PATHLAB_RENDER_META_H
#include "files/sidecar.h"
#include "render/render.h"
#include "scene/camera.h"

/* *m: a "mean", "total" sidecar of the render of scene `scene_path` (fingerprint scene_id) under o
 * from view v, by pathlab `revision`; its sample range and its adaptive keys left empty. */
void render_meta_describe(sidecar *m, const render_opts *o, const char *scene_path, uint64_t scene_id, const view *v,
                          const char *revision);
#endif
