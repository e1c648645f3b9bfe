/* stats.h - layer 1 (may include layer 0 and geom.h): distance statistics
 * of any point set on the unit torus.
 *
 * Owns: nearest-neighbour distances of an arbitrary set (x0 y0 x1 y1 ...,
 * coordinates in [0,1)), through a temporary uniform grid, in O(n), and
 * delta_min / delta_avg normalised by Delta(n). Used by every tool that
 * judges a set it did not make (baselines, analysis); the CFPO engine keeps
 * its own buckets and computes the same numbers from them. */
#ifndef CFPO_STATS_H
#define CFPO_STATS_H

#include <stddef.h>

/* Nearest-neighbour distance of every point into nn (n doubles; may be
 * NULL), and delta_min, delta_avg normalised by Delta(n). n >= 2.
 * Returns 0, or -1 when out of memory. The result does not depend on the
 * number of threads. */
int cfpo_nn_stats(const double *xy, size_t n, double *nn, double *delta_min, double *delta_avg);

#endif
