/* view_setup.c — the view of a render: --orbiter, --view or SCENE.view, the camera flags on top,
 * framing for the rest; the camera made of it; --write-view. */
#include "files/view_setup.h"
#include "sys/shown.h"
#include "image/image.h"
#include "scene/orbiter.h"
#include "sys/input_file.h"
#include "sys/output_path.h"
#include "util/cli.h"
#include "util/textfile.h"
#include <stdio.h>
#include <string.h>
#include <errno.h>
#include <sys/stat.h>

/* --orbiter FILE into v->vw; 0, or 1 after printing why. An old file without an f line leaves fov
 * and size to the flags or the defaults, which may not be what the student's program used. */
static int read_orbiter(view_setup *v, const char *cmd)
{
    orbiter o;
    if (orbiter_read(&o, v->orbiter)) return 1;
    orbiter_view(&o, &v->vw);
    if (!o.has_f && !(v->fov && v->size))
        fprintf(stderr, "pathlab %s: note: %s has no 'f fov width height' line (an older gKit file): rendering %dx%d "
                        "with a %g degree vertical fov; give the student's with --size and --fov\n",
                cmd, shown(v->orbiter), v->size ? v->flags.width : v->vw.width, v->size ? v->flags.height : v->vw.height,
                v->fov ? v->flags.fov : v->vw.fov);
    return 0;
}

/* The view before the camera flags: --orbiter, --view, or SCENE.view if it exists; 0 or 1 after printing why. */
static int base_view(view_setup *v, const char *cmd, const char *scene_path)
{
    char path[PATH_CAP];
    struct stat st;
    size_t n = strlen(scene_path) - strlen(img_extension(scene_path));
    int rc;
    view_defaults(&v->vw);
    if (v->orbiter) return read_orbiter(v, cmd);
    if (v->view_file) {
        rc = view_read(&v->vw, v->view_file);
        if (rc < 0) fprintf(stderr, "pathlab %s: --view %s: no such file\n", cmd, shown(v->view_file));
        return rc != 0;
    }
    if (n + 6 < sizeof path) {
        memcpy(path, scene_path, n);
        strcpy(path + n, ".view");
        if (!stat(path, &st) && !S_ISREG(st.st_mode)) {   /* found beside a student's scene: a FIFO there reads as empty */
            fprintf(stderr, "%s: cannot open: %s\n", shown(path), input_file_why(S_ISDIR(st.st_mode) ? EISDIR : ENODEV));
            return 1;
        }
        if (input_file_link_out(path)) {   /* confined to the scene's folder, as its MTL and textures are */
            fprintf(stderr, "%s: %s (the view file beside a scene must lie in its folder; give another with --view)\n", shown(path),
                    input_file_link_out(path));
            return 1;
        }
        if (view_read(&v->vw, path) > 0) return 1;
    }
    return 0;
}

/* --write-view FILE: the view the camera was made of, written atomically: a half-written file would
 * read back as another camera without a word */
int view_setup_write(const view_setup *v, const char *cmd, const char *scene_path)
{
    char tmp[PATH_CAP];
    FILE *f;
    if (!v->write_view) return 0;
    if (!(f = textfile_open(v->write_view, tmp, sizeof tmp))) return 1;
    /* the names escaped: a newline in one would start a line of keys */
    fprintf(f, "# the camera of pathlab %s %s%s%s: read it back with --view\n", cmd, shown(scene_path),
            v->orbiter ? " --orbiter " : "", v->orbiter ? shown(v->orbiter) : "");
    view_print(f, &v->vw);
    return textfile_close(f, tmp, v->write_view);
}

int view_setup_check(const view_setup *v, const char *cmd)
{
    const view *f = &v->flags;
    char value[64];
    if (v->fov && !(f->fov >= (float)VIEW_FOV_MIN && f->fov < 180.0f)) {
        snprintf(value, sizeof value, "%g", f->fov);
        return cli_fail(cmd, "--fov", "a vertical field of view in degrees, from 0.01 to less than 180 (e.g. 40)", value);
    }
    if (v->up && !(v3_length(f->up) > 0.0f)) return cli_fail(cmd, "--up", "a direction, not 0,0,0", "0,0,0");
    if (v->eye && v->target && !(v3_length(v3_sub(f->target, f->eye)) > 0.0f)) {
        fprintf(stderr, "pathlab %s: --eye and --target are the same point: the camera would look nowhere\n", cmd);
        return 1;
    }
    if (v->eye && v->target && v->up
        && !(v3_length(v3_cross(v3_sub(f->target, f->eye), f->up)) > 1e-6f * v3_length(v3_sub(f->target, f->eye)) * v3_length(f->up))) {
        fprintf(stderr, "pathlab %s: --up is parallel to the view direction (--target minus --eye): the image's up is undefined\n", cmd);
        return 1;
    }
    return 0;
}

int view_setup_camera(view_setup *v, const char *cmd, const char *scene_path, const mesh *m, camera *cam)
{
    vec3 lo, hi;
    if (base_view(v, cmd, scene_path)) return 1;
    /* a flag overrides its key: camera errors then name the flag's value, not the view file's line */
    if (v->eye) { v->vw.eye = v->flags.eye; v->vw.has_eye = 1; v->vw.line_eye = 0; }
    if (v->target) { v->vw.target = v->flags.target; v->vw.has_target = 1; v->vw.line_target = 0; }
    if (v->up) { v->vw.up = v->flags.up; v->vw.line_up = 0; }
    if (v->fov) { v->vw.fov = v->flags.fov; v->vw.line_fov = 0; }
    if (v->size) { v->vw.width = v->flags.width; v->vw.height = v->flags.height; v->vw.line_size = 0; }
    mesh_framing_bounds(m, &lo, &hi);   /* a large floor is not framed: it would make the object tiny */
    view_frame_bounds(&v->vw, lo, hi);
    return camera_init(cam, &v->vw) != 0;
}
