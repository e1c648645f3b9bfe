/* dens_relax.h - layer 2: the density start's gridless relaxation.
 *
 * Owns: a few Jacobi steps of a short-range repulsion applied to the
 * density start (dens_start.h) before the first sweep, in the density's
 * local units (docs/method.md, "Density"): the pair (i, j) is pushed apart
 * when its distance is below r0 / max(q_i, q_j), q = sqrt(rho) at the
 * point, r0 = Delta(n): each end by ALPHA (r - d) / 2 along their line,
 * summed over its pairs, the sum capped at CAP r0 / q_i. A move onto a
 * zero-density pixel is not made. The step depends on the points'
 * places only (no cell, colour or offset).
 *
 * Determinism: each step bins the points (bins by id inside), and a
 * point's new place is a pure function of the old places, summed in bin
 * order: the same bytes for any thread count. Under several ranks each
 * rank moves the points of its rows of bins, and the caller's `share`
 * gathers the places (dens_engine.c passes one over comm.h): the same
 * bytes for any rank count.
 * Does not own: the start (dens_start.c).
 * May include: density.h, geom.h (layers 0-1). */
#ifndef CFPO_DENS_RELAX_H
#define CFPO_DENS_RELAX_H

#include <stddef.h>
#include <stdint.h>

#include "density.h"

/* The number of steps for n points (0: none). */
int cfpo_dens_relax_steps(int64_t n);

/* Every part calls it together: first once with mine NULL (0 when `ok`
 * holds on every part), then once a step: hands this part's new places
 * (`bytes` bytes, in bin order) to the other parts and fills `all` with
 * every part's, concatenated in part order (2 n doubles). 0, or -1 (then
 * on every part). */
typedef int (*cfpo_dens_relax_share)(void *ctx, int ok, const double *mine, size_t bytes, double *all);

/* Relaxes the n points xy (2 n doubles, on positive density) by `steps`
 * steps. The work of a step may be cut into `parts` (the ranks): part
 * `part` moves the points of its rows of bins, and `share` gives every
 * part all the new places (the same bytes for any count of parts; with
 * one part, share is not called and may be NULL). Nothing is done where
 * the density is too coarse for n (the sparsest pair's reach, Delta(n) /
 * sqrt(rho_min), not under half the torus less two bins; fewer than 3
 * bins a side). 0, or -1 when out of memory or when share fails (the
 * points are then those of the steps done: a pure function of the
 * input still). */
int cfpo_dens_relax(const cfpo_density *d, int64_t n, double *xy, int steps, int threads, int part, int parts,
                    cfpo_dens_relax_share share, void *ctx);

#endif
