/* fuzz_ckpt.c - libFuzzer harness: the checkpoint reader (ckpt.h), the
 * one format of both engines (versions 1 to 4, a density's hash in 4). The
 * input is a checkpoint file; it is checked as it is, then once more with
 * its checksum made right, so the fuzzer gets past the checksum to the
 * header fields and the points. Every answer must be 0 with a header
 * whose fields are in range and points in [0,1)^2, or -1 with one line
 * naming the file. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "ckpt.h"

static void check(const uint8_t *data, size_t size)
{
    ckpt_header c;
    char err[512] = "";
    int rc = ckpt_check_buffer("fuzz.ck", data, size, &c, err, sizeof err);
    if (rc == 0) {
        if (c.n < 1 || (uint64_t)c.n != (size - (size_t)c.bytes) / 16 ||
            (c.bytes != CKPT_HEADER && c.bytes != CKPT_HEADER_V3) || (c.version != CKPT_VERSION && c.hash != 0) || c.converged < 0 || c.converged > 1 ||
            !(c.tol >= 0 && c.tol <= CFPO_TOL_MAX) || c.iteration < 0 || c.iteration > CKPT_ITER_MAX ||
            (c.variant != CFPO_VARIANT_PAPER && c.variant != CFPO_VARIANT_SIMPLIFIED &&
             c.variant != CFPO_VARIANT_ADAPTIVE && c.variant != CFPO_VARIANT_HYPERUNIFORM))
            abort();
    } else if (rc != -1 || strncmp(err, "fuzz.ck: ", 9) != 0 || strchr(err, '\n')) {
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    check(data, size);
    /* the header's size as its version says (80 for version 4, else 64) */
    const size_t hb = size >= 12 && data[8] == CKPT_VERSION && !data[9] && !data[10] && !data[11] ? CKPT_HEADER
                                                                                                : CKPT_HEADER_V3;
    if (size >= hb) {
        uint8_t *fixed = malloc(size);
        if (!fixed) return 0;
        memcpy(fixed, data, size);
        uint32_t crc = ckpt_crc_more(ckpt_crc_header(fixed, (int)hb), fixed + hb, size - hb);
        for (int i = 0; i < 4; i++) fixed[60 + i] = (uint8_t)(crc >> (8 * i));
        check(fixed, size);
        free(fixed);
    }
    (void)ckpt_cell_bound(1.0 / 3, size ? data[0] / 256.0 : 0);
    return 0;
}
