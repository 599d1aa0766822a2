/* view_setup.h — the camera of a render from its flags and files: a gKit orbiter file (--orbiter),
 * a view file (--view, or SCENE.view beside the scene), then the camera flags on top, then framing
 * of the scene for what is left; the view written back with --write-view. */
#ifndef PATHLAB_VIEW_SETUP_H
#define PATHLAB_VIEW_SETUP_H
#include "scene/camera.h"
#include "scene/mesh.h"

typedef struct {
    view vw;                          /* the view made (view_setup_camera) */
    view flags;                       /* the camera flags' values */
    int eye, target, up, fov, size;   /* which camera flags were given */
    const char *orbiter, *view_file, *write_view;   /* --orbiter, --view, --write-view (NULL if not given) */
} view_setup;

/* The camera flags that cannot make a camera whatever the scene (--fov out of (0, 180), --up 0,0,0,
 * --eye equal to --target, --up along the view): checked before the scene loads. 0, or 1 after
 * printing "pathlab CMD: ..." naming the flag. */
int view_setup_check(const view_setup *v, const char *cmd);
/* v->vw and the camera *cam made of it for the scene at scene_path of mesh m. 0, or 1 after printing why. */
int view_setup_camera(view_setup *v, const char *cmd, const char *scene_path, const mesh *m, camera *cam);
/* Writes v->vw to --write-view (nothing if not given), once the render's images are written (a render
 * that fails leaves no view file behind). 0, or 1 after printing why. */
int view_setup_write(const view_setup *v, const char *cmd, const char *scene_path);
#endif
