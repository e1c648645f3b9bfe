/* testdensity.h - a random piecewise-constant density for the tests of the
 * measures under a density: w x h pixels of values 0.05 + U[0, 1)
 * (cfpo_rand01(seed, 7, pixel)), loaded by cfpo_density_from_values; the
 * test exits with the message when loading fails. */
#ifndef CFPO_TESTDENSITY_H
#define CFPO_TESTDENSITY_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "density.h"
#include "rng.h"

static inline void test_density_random(cfpo_density *d, int w, int h, uint64_t seed)
{
    double *v = malloc((size_t)(w * h) * sizeof *v);
    if (!v) { printf("out of memory\n"); exit(1); }
    for (int i = 0; i < w * h; i++) v[i] = 0.05 + cfpo_rand01(seed, 7, (uint64_t)i);
    char err[256];
    if (cfpo_density_from_values(v, w, h, "test", d, err, sizeof err) != 0) { printf("%s\n", err); exit(1); }
    free(v);
}

#endif
