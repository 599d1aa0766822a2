/* orbiter.h — gKit's camera files ("orbiter" files, written by Orbiter::write_orbiter), read as-is
 * and turned into a pathlab view. One line per key, in any order, '#' starts a comment:
 *   c cx cy cz (centre)  p px py (pan)  r rx ry (rotation, degrees)  s size [radius]
 *   f fov width height   (full vertical fov in degrees, pixels; older gKit files have no f line)
 * Lines are read whole whatever their length, but only a comment may pass 1023 characters; a NUL
 * byte, or a number beyond 1e30 in size (the camera is made of floats), is an error with its line.
 * gKit's view is T(-px,-py,-size) Rx(rx) Ry(ry) T(-c): the camera sits at c + M (px, py, size),
 * M = Ry(-ry) Rx(-rx), and looks down M's -z with M's +y up. docs/grading.md says what matches gKit. */
#ifndef PATHLAB_ORBITER_H
#define PATHLAB_ORBITER_H
#include "scene/camera.h"

typedef struct {
    double c[3], p[2], r[2], size, radius;
    double fov;            /* from the f line, if has_f */
    int width, height;     /* from the f line, if has_f */
    int has_f;
} orbiter;

/* Reads an orbiter file; 0, or 1 after printing "FILE:LINE: what is wrong" (also for a missing
 * c, p, r or s line). Without radius on the s line, radius = size (as gKit's lookat sets it). */
int orbiter_read(orbiter *o, const char *path);
/* Sets the eye, target and up of vw (and has_eye, has_target), and with an f line its fov and size;
 * without one, vw's fov and size are left as they were. */
void orbiter_view(const orbiter *o, view *vw);
/* gKit's near plane distance: max(0.1, |c - (px, py, size)| - radius) (Orbiter::znear, which mixes
 * the world centre with a camera-space point); gKit rays that start on it miss closer geometry. */
double orbiter_znear(const orbiter *o);
#endif
