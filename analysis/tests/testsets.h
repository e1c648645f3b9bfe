/* testsets.h - small point sets for the analysis tests: a counter-based
 * generator (the same numbers on every machine), uniform sets, square
 * lattices, jitter and a dart-throwing generator. Header-only. */
#ifndef AN_TESTSETS_H
#define AN_TESTSETS_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "geom.h"
#include "rng.h"

/* The project's SplitMix64 finaliser. */
#define ts_mix cfpo_mix64

/* Uniform in [0, 1). */
static inline double ts_u(uint64_t *state) { return (double)(ts_mix((*state)++) >> 11) * 0x1.0p-53; }

static inline double *ts_uniform(size_t n, uint64_t seed)
{
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < 2 * n; i++) xy[i] = ts_u(&seed);
    return xy;
}

/* m x m square lattice shifted by (ox, oy) (in lattice units). */
static inline double *ts_lattice(int m, double ox, double oy)
{
    double *xy = malloc(2 * (size_t)m * m * sizeof *xy);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < m; i++) {
            xy[2 * (j * m + i)] = cfpo_wrap01((i + ox) / m);
            xy[2 * (j * m + i) + 1] = cfpo_wrap01((j + oy) / m);
        }
    return xy;
}

/* Every coordinate moved by a uniform amount in [-a/2, a/2). */
static inline void ts_jitter(double *xy, size_t n, double a, uint64_t seed)
{
    for (size_t i = 0; i < 2 * n; i++) xy[i] = cfpo_wrap01(xy[i] + a * (ts_u(&seed) - 0.5));
}

/* Dart throwing: `trials` uniform candidates, each kept if no earlier kept
 * point is within r (torus distance). Returns the count in *n. */
static inline double *ts_dart(double r, size_t trials, uint64_t seed, size_t *n)
{
    double *xy = malloc(2 * trials * sizeof *xy);
    size_t m = 0;
    for (size_t t = 0; t < trials; t++) {
        double x = ts_u(&seed), y = ts_u(&seed);
        int ok = 1;
        for (size_t j = 0; j < m && ok; j++) ok = cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]) >= r * r;
        if (ok) { xy[2 * m] = x; xy[2 * m + 1] = y; m++; }
    }
    *n = m;
    return xy;
}

#endif
