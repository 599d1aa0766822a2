/* camera.h — pinhole camera and the scene's view file.
 * A view file (SCENE.view beside SCENE.obj) has one key per line, '#' starts a comment:
 *   eye X Y Z / target X Y Z / up X Y Z / fov DEGREES (vertical) / size W H
 * Missing keys keep their defaults; without eye and target the camera frames the scene bounds. */
#ifndef PATHLAB_CAMERA_H
#define PATHLAB_CAMERA_H
#include <stdio.h>
#include "geometry/ray.h"
#include "sys/output_path.h"

#define VIEW_SIZE_MAX 65536    /* pixels on a side */
#define VIEW_PIXELS_MAX 1e9     /* pixels in all */
#define VIEW_FOV_MIN 0.01       /* degrees: below it, neighbouring pixels' rays are one float direction */

typedef struct {
    vec3 eye, target, up;
    float fov;                 /* vertical field of view, degrees */
    int width, height;
    int has_eye, has_target;   /* set by a view file or a flag */
    /* where each key came from, for camera_init's errors: the view file's line, 0 for a default or
     * a flag (whoever overrides a key from a file sets its line to 0) */
    char file[PATH_CAP];       /* the view file read, for messages */
    int line_eye, line_target, line_up, line_fov, line_size;
} view;

typedef struct {
    vec3 eye, w, u, v;         /* w forward; u, v span the image plane at distance 1 */
    int width, height;
} camera;

/* Defaults: up (0,1,0), fov 40, 512x512, no eye nor target. */
void view_defaults(view *vw);
/* Reads a view file into vw. Returns 0 on success, -1 if the file does not exist (not an error),
 * 1 after printing "file:line: message" for a malformed file. Lines may be of any length: comments
 * are skipped as they are read; the part before a comment may have up to 1 MiB. A NUL
 * byte, a number beyond the float range, fov outside (0, 180) and a size outside 1..65536 (at most
 * 1e9 pixels) are errors at their line. Records the file and the line of each key in vw. */
int view_read(view *vw, const char *path);
/* The line reader of view and orbiter files. Reads one line of fp into *buf (malloc'ed, grown as
 * needed: *cap bytes, up to VIEW_LINE_MAX) without its '#' comment, NUL-terminated; comments may
 * be of any length. Returns 0 at the end of the file, 1 for a line, 6 at a NUL byte (reading
 * stops), 7 when the part before the comment is longer than VIEW_LINE_MAX - 1 (the rest of the
 * line is skipped), 8 when out of memory. */
#define VIEW_LINE_MAX (1 << 20)
int view_read_line(FILE *fp, char **buf, size_t *cap);
/* Prints vw as a view file (every key, %.9g: view_read gives back the same floats, bit for bit). */
void view_print(FILE *f, const view *vw);
/* Fills in eye and target from the scene bounds where no file or flag gave them. */
void view_frame_bounds(view *vw, vec3 lo, vec3 hi);
/* Checks a view and makes the camera; 1 after printing an error (e.g. eye == target) that names
 * the view file and line of the keys at fault, or "camera:" for values from flags or defaults. */
int camera_init(camera *c, const view *vw);
/* The ray through image position (x, y) in pixels, (0,0) the top-left corner of the image. */
ray camera_ray(const camera *c, float x, float y);
#endif
