/* fuzz_d3ckpt.c - libFuzzer harness: the 3-D checkpoint reader
 * (src/d3/engine3_ckpt.c). The input is a checkpoint file; it is read as
 * it is, then once more with its checksum made right, so the fuzzer gets
 * past the checksum to the header fields and the points. Every answer must
 * be an engine whose n and caller's block (version 3) fill the file and
 * whose points lie in [0,1)^3, or NULL with one line naming the file. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine3.h"

static void check(const uint8_t *data, size_t size)
{
    char err[512] = "";
    cfpo3_engine *e = cfpo3_checkpoint_parse(data, size, "fuzz.ck", 1, err, sizeof err);
    if (e) {
        const int64_t n = cfpo3_n(e);
        size_t tl;
        const unsigned char *tail = cfpo3_checkpoint_tail(e, &tl);
        if (n < 1 || (tail == NULL) != (tl == 0) || 64 + 24 * (uint64_t)n + tl != size) abort();
        const double *p = cfpo3_points(e);
        for (int64_t i = 0; i < 3 * n; i++)
            if (!(p[i] >= 0.0 && p[i] < 1.0)) abort();
        cfpo3_free(e);
    } else if (strncmp(err, "fuzz.ck: ", 9) != 0 || strchr(err, '\n')) {
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    check(data, size);
    if (size >= 64) {
        uint8_t *fixed = malloc(size);
        if (!fixed) return 0;
        memcpy(fixed, data, size);
        const uint32_t crc = cfpo3_checkpoint_crc(fixed, size);
        for (int i = 0; i < 4; i++) fixed[60 + i] = (uint8_t)(crc >> (8 * i));
        check(fixed, size);
        free(fixed);
    }
    return 0;
}
