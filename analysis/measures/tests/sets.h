/* sets.h - the point sets the measures' tests use: white noise, jittered
 * (one uniform point per cell of a g x g grid), the first n points of the
 * two-dimensional Sobol' sequence (x: van der Corput in base 2; y: the
 * second Sobol' dimension, direction numbers m = 1, 3, 5, 15, 17, 51, ...,
 * m_k = 2 m_{k-1} xor m_{k-1}: the Pascal-matrix net) and the golden-ratio
 * lattice x_i = frac(i phi), y_i = frac(i sqrt 2) (no randomness, so Python
 * computes the same points). */
#ifndef AN_MEASURES_TEST_SETS_H
#define AN_MEASURES_TEST_SETS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "rng.h"

static inline void set_white(double *xy, size_t n, uint64_t seed)
{
    for (size_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(seed, 1, i);
}

static inline void set_jittered(double *xy, size_t g, uint64_t seed)
{
    for (size_t i = 0; i < g * g; i++) {
        xy[2 * i] = ((double)(i % g) + cfpo_rand01(seed, 2, 2 * i)) / (double)g;
        xy[2 * i + 1] = ((double)(i / g) + cfpo_rand01(seed, 2, 2 * i + 1)) / (double)g;
    }
}

static inline void set_sobol(double *xy, size_t n)
{
    uint32_t m[32], v[32];
    m[0] = 1;
    for (int k = 1; k < 32; k++) m[k] = (m[k - 1] << 1) ^ m[k - 1];
    for (int k = 0; k < 32; k++) v[k] = m[k] << (31 - k);
    for (size_t i = 0; i < n; i++) {
        uint32_t x = 0, y = 0;
        for (int k = 0; k < 32; k++)
            if ((i >> k) & 1) { x ^= 1u << (31 - k); y ^= v[k]; }
        xy[2 * i] = x * 0x1.0p-32;
        xy[2 * i + 1] = y * 0x1.0p-32;
    }
}

static inline void set_golden(double *xy, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = fmod((double)i * 0.6180339887498949, 1.0);
        xy[2 * i + 1] = fmod((double)i * 1.4142135623730951, 1.0);
    }
}

#endif
