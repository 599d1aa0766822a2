/* fuzz_view.c — libFuzzer harness: one view file alone, framed on a box as a scene without eye or
 * target would be. A view that camera_init accepts must give a finite camera, and view_print's text
 * of it (what --write-view writes) must read back the same view. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "scene/camera.h"

static int finite3(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    view vw, back;
    camera cam;
    FILE *f;
    const char *path = fuzz_write(0, "f.view", data, size), *again;
    view_defaults(&vw);
    if (view_read(&vw, path) != 0) return 0;
    view_frame_bounds(&vw, v3(-1, -1, -1), v3(1, 1, 1));
    if (camera_init(&cam, &vw) != 0) return 0;
    if (!(finite3(cam.eye) && finite3(cam.w) && finite3(cam.u) && finite3(cam.v))) abort();
    again = fuzz_absent(1, "again.view");
    f = fopen(again, "w");
    if (!f) abort();
    view_print(f, &vw);
    if (fclose(f)) abort();
    view_defaults(&back);
    if (view_read(&back, again) != 0 || memcmp(&back.eye, &vw.eye, sizeof vw.eye) || back.fov != vw.fov ||
        back.width != vw.width || back.height != vw.height)
        abort();   /* view_print promises a file that reads back the same view */
    return 0;
}
