/* nn3.h - layer 1 of the 3-D engine (includes solve3.h): nearest
 * neighbours of any set on the unit 3-torus.
 *
 * Owns: the k nearest neighbours of every point (periodic, minimum image),
 * through a temporary uniform grid searched shell by shell; ties broken by
 * id, so the answer does not depend on threads. delta_min and delta_avg
 * over Delta3(n) (the mean summed in id order). Used by the engine, the
 * analysis (Q6) and the tests. */
#ifndef CFPO_NN3_H
#define CFPO_NN3_H

#include <stddef.h>
#include <stdint.h>

/* For every point i: its k nearest others, nearest first, ids into
 * idx[i k ...] and squared distances into d2[i k ...] (either may be
 * NULL... but not both). k < n. 0, or -1 when out of memory. */
int cfpo3_knn(const double *p, size_t n, int k, int64_t *idx, double *d2);

/* Nearest-neighbour distance of every point into nn (may be NULL), and
 * delta_min, delta_avg over Delta3(n). n >= 2. 0 or -1 (memory). */
int cfpo3_nn_stats(const double *p, size_t n, double *nn, double *delta_min, double *delta_avg);

/* Periodic difference a - b in [-0.5, 0.5]. */
static inline double cfpo3_pdiff(double a, double b)
{
    double d = a - b;
    if (d > 0.5) d -= 1.0;
    else if (d < -0.5) d += 1.0;
    return d;
}

#endif
