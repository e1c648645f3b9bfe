/* fuzz_png.c - libFuzzer harness: the PNG reader (src/density/png_read.c, over
 * libpng's simplified API). Any input is read or refused with one line. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "png_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512];
    grey_image g;
    if (png_parse(data, size, "fuzz", &g, err, sizeof err) != 0) {
        if (!err[0] || strchr(err, '\n')) abort();
        return 0;
    }
    if (g.w < 1 || g.h < 1 || g.w * g.h > GREY_MAX_PIXELS || g.maxval != 255) abort();
    free(g.v);
    return 0;
}
