/* fuzz_ppm.c — libFuzzer harness: one PPM file decoded from memory by img_decode_ppm.
 * A decode that succeeds has a size >= 1, all its pixels, and values that are finite and >= 0
 * (integers / maxval: also <= 1). */
#include <math.h>
#include <stdlib.h>
#include "fuzz_common.h"
#include "image/decode.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image im;
    img_decoded info;
    size_t i;
    (void)info;
    if (img_decode_ppm(&im, data, size, "f.ppm", &info, IMG_DECODE_MAX_PIXELS) == 0) {
        if (im.w < 1 || im.h < 1 || !im.px) abort();
        for (i = 0; i < (size_t)im.w * im.h * 3; i++)
            if (!(im.px[i] >= 0.0f) || !isfinite(im.px[i]) || im.px[i] > 1.0f) abort();
        img_free(&im);
    }
    return 0;
}
