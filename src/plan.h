/* plan.h - layer 4: what a run of n points over P ranks needs, from
 * arithmetic alone (nothing allocated): the grid, the cut into tiles, the
 * largest tile's points and memory, the halo and migration traffic of a
 * phase; and the check that this machine can hold the run.
 * May include: cfpo_types.h, grid.h, tiles.h (layers 0-2). */
#ifndef CFPO_PLAN_H
#define CFPO_PLAN_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"
#include "grid.h"
#include "tiles.h"

typedef struct {
    int64_t n;
    cfpo_grid G;
    cfpo_tiling T;
    int ranks, threads;
    int64_t wmin, wmax, hmin, hmax; /* tile sides in cells */
    int64_t cells_max;              /* cells of the largest tile */
    double points_per_cell;
    double points_max;              /* points of the largest tile, about */
    double bytes_per_rank;          /* the engine's memory on the largest tile */
    double halo_cells, halo_bytes;  /* sent per rank and phase */
    double migrate_bytes;           /* sent per rank and phase, at most about */
    int64_t max_ranks;              /* the largest usable rank count for n */
} cfpo_plan;

/* The plan for n points on P ranks (px, py: a forced cut, or 0). 0, or -1
 * with a one-line message (n, the options or the cut are invalid). */
int cfpo_plan_make(cfpo_plan *p, int64_t n, const cfpo_options *o, int P, int px, int py, char *err,
                   size_t errlen);

/* Collective: can this run's ranks (comm_size() of them, sharing the
 * machine with comm_local_size() - 1 others) hold n points? 0; -1 with a
 * message for an invalid request; -2 when it exceeds memory. */
int cfpo_plan_check(int64_t n, const cfpo_options *o, int px, int py, char *err, size_t errlen);

/* Collective: peak resident memory summed over ranks and its largest
 * value on one rank, in bytes. */
void cfpo_plan_peak_memory(uint64_t *sum, uint64_t *max);

#endif
