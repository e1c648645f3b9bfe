/* shake3.h - layer 1 of the 3-D engine: the shake between rounds of
 * `cfpo3d --shake K`.
 *
 * Owns: the perturbation that lifts a set out of the jammed state the
 * optimisation ends in: every coordinate moved by a uniform amount in
 * [-amp, amp) Delta3(n), keyed by (seed, round, point id, axis) (so it
 * does not depend on threads or ranks), and wrapped into [0, 1)
 * (docs/method.md, "Three dimensions").
 * May include: rng.h (layer 0), solve3.h. */
#ifndef CFPO_SHAKE3_H
#define CFPO_SHAKE3_H

#include <stdint.h>

/* Shakes the n points xyz (3n doubles in [0, 1), by id) in place. */
void cfpo3_shake(double *xyz, int64_t n, uint64_t seed, int round, double amp);

#endif
