/* grid3.h - layer 1 of the 3-D engine (includes solve3.h): the 3-D grid
 * and the start.
 *
 * Owns: the choice of the g x g x g grid (g a multiple of 3, cells wider
 * than Delta3(n), g^3 closest to n / 1.5), the smallest n (39, a 3x3x3
 * grid), and the start: a jittered h^3 grid, h = floor(cbrt n), one uniform
 * point in each start cell and the n - h^3 others in distinct start cells
 * chosen by a keyed permutation; every coordinate a pure function of
 * (seed, start cell, k) (docs/method.md, "Three dimensions"). */
#ifndef CFPO_GRID3_H
#define CFPO_GRID3_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int64_t n;
    int g;          /* cells per side, a multiple of 3 */
    double L;       /* cell side 1/g, > delta3 */
    double delta3;  /* Delta3(n) */
} cfpo3_grid;

/* The smallest n for which a 3x3x3 grid has cells wider than Delta3(n). */
int64_t cfpo3_grid_min_n(void);
/* 0, or -1 with one line in err (n too small). */
int cfpo3_grid_choose(int64_t n, cfpo3_grid *G, char *err, size_t errlen);
/* The start (3n doubles, ids in start-cell order); OpenMP threads. 0, or
 * -1 when out of memory. */
int cfpo3_start(int64_t n, uint64_t seed, double *pos);
/* floor(cbrt(n)) exactly. */
int64_t cfpo3_icbrt(int64_t n);

#endif
