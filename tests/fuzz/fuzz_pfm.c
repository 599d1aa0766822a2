/* fuzz_pfm.c — libFuzzer harness: one PFM file read by img_read_pfm_info (the reader of
 * pathlab's diff, compare, grade and --resume). A read that succeeds has a sane size and facts. */
#include <stdlib.h>
#include "fuzz_common.h"
#include "image/image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image im;
    img_pfm_info info;
    const char *path = fuzz_write(0, "f.pfm", data, size);
    if (img_read_pfm_info(&im, path, &info) == 0) {
        if (im.w < 1 || im.h < 1 || !im.px || (info.channels != 1 && info.channels != 3)) abort();
        im.px[(size_t)im.w * im.h * 3 - 1] += 0.0f;   /* the last pixel is there (ASan checks) */
        img_free(&im);
    }
    return 0;
}
