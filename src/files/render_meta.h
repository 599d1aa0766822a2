/* render_meta.h — the sidecar of a render from what it runs: the keys that must match for pieces
 * of one render to merge (scene, flags in one canonical form, camera, seed, sampler). */
#ifndef PATHLAB_RENDER_META_H
#define PATHLAB_RENDER_META_H
#include "files/sidecar.h"
#include "render/adaptive.h"
#include "scene/camera.h"

/* *m: a "mean", "total" sidecar of the render of scene `scene_path` (fingerprint scene_id) under o
 * from view v, by pathlab `revision`; its sample range and its adaptive keys left empty. */
void render_meta_describe(sidecar *m, const render_opts *o, const char *scene_path, uint64_t scene_id, const view *v,
                          const char *revision);
/* The fingerprint of what a render lights and sees: the scene's triangles, materials and textures
 * (mesh_fingerprint), and the pixels of an image given as --sky (a sky file changed under the same
 * name must not merge with renders of the old one). */
uint64_t render_meta_scene_id(const scene *s, const sky_spec *sky);
/* The flags of the material and the scene's loading appended to m->flags, each when not its default:
 * --material, --normals, --texture-filter, --texture-decode, --mtl FILE. */
void render_meta_describe_scene(sidecar *m, const integrator_opts *io, const scene_opts *so);
/* The adaptive keys of m: the flags in one canonical form (--target-error if target_given, --time
 * if time_limit > 0, --pilot, --min-spp) into m->adaptive. */
void render_meta_describe_adaptive(sidecar *m, const adaptive_opts *ao, int target_given, double time_limit);
#endif
