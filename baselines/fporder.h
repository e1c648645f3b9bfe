/* fporder.h - the greedy farthest-point order of a given set on the unit
 * torus: the first point, then again and again the point farthest from those
 * already taken (ties: the lower index). Every prefix of the order is then a
 * greedy farthest-point subset of the set (Gonzalez 1985; the classic
 * "farthest point sampling" of a fixed set).
 *
 * Owns the exact algorithm: a max-heap of upper bounds of each point's
 * distance to the taken points (a distance only falls as points are taken),
 * the top's bound refreshed by a nearest-neighbour query (nngrow.h) and the
 * point taken when its true distance still beats every other bound. */
#ifndef CFPO_BASELINES_FPORDER_H
#define CFPO_BASELINES_FPORDER_H
#include <stddef.h>

/* order[0..n): the greedy order starting at point `first` (< n). 0, or -1
 * when out of memory. */
int fp_order(const double *xy, size_t n, size_t first, size_t *order);
#endif
