/* test_spread.h - a spread test set: n points jittered off a square grid
 * (0.3 of a grid cell), like a relaxed set; the same points for a seed. */
#ifndef CFPO_TEST_SPREAD_H
#define CFPO_TEST_SPREAD_H

#include <math.h>
#include <stdint.h>

#include "rng.h"

static inline void tu_spread(double *xy, int64_t n, uint64_t seed)
{
    const int64_t g = (int64_t)ceil(sqrt((double)n));
    for (int64_t i = 0; i < n; i++) {
        xy[2 * i] = fmod(((double)(i % g) + 0.5 + 0.3 * (cfpo_rand01(seed, 1, (uint64_t)i) - 0.5)) / (double)g + 1, 1);
        xy[2 * i + 1] = fmod(((double)(i / g) + 0.5 + 0.3 * (cfpo_rand01(seed, 2, (uint64_t)i) - 0.5)) / (double)g + 1, 1);
    }
}

#endif
