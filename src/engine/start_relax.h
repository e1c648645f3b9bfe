/* start_relax.h - layer 2: the adaptive start's gridless relaxation.
 *
 * Owns: a few Jacobi steps of a short-range repulsion applied to the
 * start before the first sweep (docs/method.md, "--variant adaptive",
 * item 1). Each point moves away from every point nearer than
 * r = RADIUS Delta(n), by ALPHA (r - d) / 2 along their line summed over
 * those points, the sum capped at CAP r; all points move at once from the
 * previous step's positions. The step depends on the points' distances
 * only: it has no cell, no colour and no offset, so it writes nothing at
 * the cell grid's frequencies. It takes the start from delta_min near 0
 * to about 0.6 Delta(n), so the first sweeps under the grid make short
 * moves and print the grid less (docs/tried.md, issue 44).
 *
 * Determinism: a point's new position is a pure function of the
 * positions and keys of the points within r of it (the sum runs over
 * them in a fixed order: the 3 x 3 bins of a torus-wide binning, each
 * bin's points by key), so a band of the start computes the same bytes
 * for every point far enough from its edges, whatever the band, the
 * thread count or the rank count. cfpo_start_relax_reach says how far.
 * Does not own: the start itself (start.c), which calls this.
 * May include: geom.h, rng.h (layers 0-1). */
#ifndef CFPO_START_RELAX_H
#define CFPO_START_RELAX_H

#include <stddef.h>
#include <stdint.h>

/* The number of steps for n points (0: no relaxation). */
int cfpo_start_relax_steps(int64_t n);

/* How far (torus units) a point's final position can depend on the
 * others, plus how far it can move, for n points: a band must hold every
 * point within this distance of its rows for those rows to come out
 * exact. */
double cfpo_start_relax_reach(int64_t n);

/* Relaxes the m points (x[i], y[i]) in [0, 1)^2 with unique keys key[i],
 * all within the rows [ylo, yhi) of the torus taken without wrapping
 * (ylo may be negative, yhi above 1; yhi - ylo >= 1: the whole torus), n
 * the size of the whole set. Returns 0, or -1 when out of memory (the
 * points are then as they were). */
int cfpo_start_relax(double *x, double *y, const uint64_t *key, size_t m, int64_t n, double ylo, double yhi,
                     int threads);

#endif
