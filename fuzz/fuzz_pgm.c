/* fuzz_pgm.c - libFuzzer harness: the PGM reader (src/density/pgm.c). Any input
 * is read or refused with one line; what is read has its announced size
 * and no value above maxval. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "pgm.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512];
    grey_image g;
    if (pgm_parse(data, size, "fuzz", &g, err, sizeof err) != 0) {
        if (!err[0] || strchr(err, '\n')) abort();
        return 0;
    }
    if (g.w < 1 || g.h < 1 || g.w * g.h > GREY_MAX_PIXELS) abort();
    for (int64_t p = 0; p < g.w * g.h; p++)
        if (g.v[p] > g.maxval) abort();
    free(g.v);
    return 0;
}
