/* fuzz_hdr.c — libFuzzer harness: one Radiance .hdr file read by img_read_hdr (a file: the reader checks its size before reading it).
 * A decode that succeeds has a size >= 1, all its pixels, and values that are finite and >= 0
 * (radiance). */
#include <math.h>
#include <stdlib.h>
#include "fuzz_common.h"
#include "image/decode.h"
#include "image/rgbe.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image im;
    img_decoded info;
    size_t i;
    (void)info;
    if (img_read_hdr(&im, fuzz_write(0, "f.hdr", data, size)) == 0) {
        if (im.w < 1 || im.h < 1 || !im.px) abort();
        for (i = 0; i < (size_t)im.w * im.h * 3; i++)
            if (!(im.px[i] >= 0.0f) || !isfinite(im.px[i])) abort();
        img_free(&im);
    }
    return 0;
}
