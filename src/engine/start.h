/* start.h - layer 2: the initial point set of the adaptive variant.
 *
 * Owns: the start of CFPO_VARIANT_ADAPTIVE, as points per optimisation
 * cell. The start is a jittered grid of h x h start cells, h = floor(sqrt
 * n), one uniform point in each, the n - h^2 remaining points in distinct
 * random start cells, then displaced by a smooth random area-preserving
 * map, 64 shears in turn (docs/method.md says why), then relaxed without a grid
 * (start_relax.h). Every coordinate is a pure function of (seed, the
 * start cells within the relaxation's reach), so any process makes any
 * optimisation cell's points from a band of start rows around them.
 * Order inside a cell: by start cell, then by point.
 * May include: geom.h, rng.h (layers 0-1), grid.h (the optimisation
 * grid), start_relax.h. */
#ifndef CFPO_START_H
#define CFPO_START_H

#include <stdint.h>

#include "grid.h"

typedef struct {
    int64_t cell;  /* global row-major index of the optimisation cell */
    uint64_t key;  /* order inside the cell */
    double x, y;
} cfpo_start_pt;

/* The points of the start that fall into optimisation rows [y0, y1) (all
 * columns), sorted by cell and then by key, made by `threads` OpenMP
 * threads (the same result for any count), relaxed (start_relax.h) unless
 * relax is 0; *out is malloc'ed. Returns
 * their number, or -1 when out of memory. */
int64_t cfpo_start_band(const cfpo_grid *G, int64_t y0, int64_t y1, int threads, int relax, cfpo_start_pt **out);

#endif
