/* engine3_dist.h - the 3-D engine on several ranks (docs/mpi.md, "Three
 * dimensions"); shared by engine3.c, engine3_step.c and engine3_ckpt.c,
 * below them (it calls none of their functions).
 *
 * The g^3 cells are cut into bricks (bricks3.h). A rank solves the cells
 * of its brick and holds the points of its region (brick and one layer of
 * halo cells): a point it does not hold has cellof -1. Arrays stay indexed
 * by id, so the buckets of a held cell list its points in id order, as on
 * one rank, and every 3x3x3 block a rank solves is assembled from the
 * same points in the same order as on one rank: each decision, and so the
 * output, is the same bytes for any rank count (and thread count).
 * - After each colour phase, every move (id, its cell before and after,
 *   its position, its position at the iteration's start) goes to the
 *   neighbours whose region holds either cell; they apply it (a point
 *   entering the region is added, one leaving it dropped) and stamp both
 *   cells changed, as the mover did.
 * - When the grid takes a new shift, each rank sends each point of its
 *   brick to the ranks whose region holds its new cell (itself too): the
 *   migration. Cells move by at most one under a new shift, so both go to
 *   neighbours only.
 * - The measure: each rank finds the nearest neighbour of its brick's
 *   points in their blocks; one farther than a cell side may have a nearer
 *   one outside, and then every rank measures the whole set (gathered).
 *   delta_min is a minimum; delta_avg's sum is taken in 2^-62 fixed point
 *   (two 31-bit parts a distance), which no order changes.
 * - Checkpoints and point files gather the set in id order. */
#ifndef CFPO_ENGINE3_DIST_H
#define CFPO_ENGINE3_DIST_H

#include "state3.h"

/* Sets up e->B and the message buffers for comm_size() ranks. 0, or -1
 * with one line in err (too many ranks for the grid; out of memory). */
int cfpo3_dist_init(cfpo3_engine *e, char *err, size_t errlen);
void cfpo3_dist_free(cfpo3_engine *e);

/* cellof of every held point (cellof >= 0) from pos and e->shift; a point
 * outside the region is dropped (-1). Threads. The caller rebuckets. */
void cfpo3_dist_cells(cfpo3_engine *e);

/* Collective (P > 1): the migration to the new e->shift. 0, or -1 when
 * out of memory on this rank. The caller rebuckets. */
int cfpo3_dist_migrate(cfpo3_engine *e);

/* A move of the current phase (P > 1), noted by the mover. */
int cfpo3_dist_note(cfpo3_move_list *l, int64_t id, int32_t from, int32_t to, const double *x, const double *p0);

/* Collective (P > 1), after a colour phase: sends the phase's moves
 * (e->mv) to the neighbours and applies theirs, stamping `ph`. *crossed
 * gets 1 when a held point changed cell or was added or dropped. 0, or -1
 * when out of memory. */
int cfpo3_dist_halo(cfpo3_engine *e, uint64_t ph, int *crossed);

/* Collective: e->dmin, e->davg of the whole set. 0, or -1 (memory, on any
 * rank). */
int cfpo3_dist_measure(cfpo3_engine *e);

/* Collective: every point in id order into all (3n doubles), on every
 * rank; on one rank a copy. 0, or -1 (memory, on any rank). */
int cfpo3_dist_gather(const cfpo3_engine *e, double *all);

/* Points of this rank's brick. */
int64_t cfpo3_dist_own(const cfpo3_engine *e);

#endif
