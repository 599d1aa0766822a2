/* render_meta.h — the sidecar of a render from what it runs: the keys that must match for pieces
 * of one render to merge (scene, flags in one canonical form, camera, seed, sampler). */
#ifndef PATHLAB_RENDER_META_H
#define PATHLAB_RENDER_META_H
#include "files/sidecar.h"
#include "render/adaptive.h"
#include "scene/camera.h"

/* *m: a "mean", "total" sidecar of the render of scene s (loaded from scene_path, its --sky put on)
 * under o from view v, by pathlab `revision`: scene-id the fingerprint of its triangles, materials
 * and textures, sky-id of its --sky image's pixels; its sample range and adaptive keys left empty. */
void render_meta_describe(sidecar *m, const render_opts *o, const char *scene_path, const scene *s, const view *v,
                          const char *revision);
/* The flags of the material and the scene's loading appended to m->flags, each when not its default:
 * --material, --normals, --texture-filter, --texture-decode, --mtl FILE. */
void render_meta_describe_scene(sidecar *m, const integrator_opts *io, const scene_opts *so);
/* The adaptive keys of m: the flags in one canonical form (--target-error if target_given, --time
 * if time_limit > 0, --pilot, --min-spp) into m->adaptive. */
void render_meta_describe_adaptive(sidecar *m, const adaptive_opts *ao, int target_given, double time_limit);
#endif
