/* fuzz_orbiter.c — libFuzzer harness: one gKit orbiter file alone, then the view it describes, its
 * near plane and a camera. A file orbiter_read accepts gives a finite view (its numbers are at most
 * 1e30 in size), and a camera that camera_init accepts is finite. */
#include <math.h>
#include <stdlib.h>
#include "fuzz_common.h"
#include "scene/orbiter.h"

static int finite3(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    orbiter o;
    view vw;
    camera cam;
    const char *path = fuzz_write(0, "f.orbiter", data, size);
    if (orbiter_read(&o, path)) return 0;
    view_defaults(&vw);
    orbiter_view(&o, &vw);
    if (!(finite3(vw.eye) && finite3(vw.target) && finite3(vw.up) && isfinite(orbiter_znear(&o)))) abort();
    if (camera_init(&cam, &vw) == 0 && !(finite3(cam.eye) && finite3(cam.w) && finite3(cam.u) && finite3(cam.v)))
        abort();
    return 0;
}
