/* fuzz_d3points.c - libFuzzer harness: the 3-D point-file reader
 * (src/d3/points3.c). The first byte picks the format (text, CSV, .npy,
 * raw), the rest is the file. Every answer must be n >= 1 points in
 * [0,1)^3, or -1 with one line naming the file. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "points3.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    static const p3_format fmts[4] = {P3F_TEXT, P3F_CSV, P3F_NPY, P3F_RAW};
    const p3_format f = fmts[data[0] & 3];
    double *p = NULL;
    size_t n = 0;
    char err[512] = "";
    const int rc = p3_read_buffer(f, "fuzz.pts", data + 1, size - 1, &p, &n, err, sizeof err);
    if (rc == 0) {
        if (n < 1 || !p) abort();
        for (size_t i = 0; i < 3 * n; i++)
            if (!(p[i] >= 0.0 && p[i] < 1.0)) abort();
    } else if (rc != -1 || strncmp(err, "fuzz.pts: ", 10) != 0 || strchr(err, '\n')) {
        abort();
    }
    free(p);
    return 0;
}
