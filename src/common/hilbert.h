/* hilbert.h - layer 0: the index of a cell along the Hilbert curve,
 * CCVT's start (baselines/ccvt.c); the density engine's start walks the
 * same curve (src/density/dens_start.c, tested against this). */
#ifndef CFPO_HILBERT_H
#define CFPO_HILBERT_H

#include <stdint.h>

/* Index of cell (x, y) of an s x s grid (s a power of 2, x, y < s) along
 * the Hilbert curve that starts at (0, 0) and ends at (s - 1, 0): in
 * [0, s^2), each index once. */
static inline uint64_t cfpo_hilbert(uint64_t s, uint64_t x, uint64_t y)
{
    uint64_t d = 0;
    for (uint64_t q = s / 2; q > 0; q /= 2) {
        const uint64_t rx = (x & q) > 0, ry = (y & q) > 0;
        d += q * q * ((3 * rx) ^ ry);
        if (ry == 0) { /* rotate the quadrant */
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            const uint64_t t = x;
            x = y;
            y = t;
        }
    }
    return d;
}

#endif
