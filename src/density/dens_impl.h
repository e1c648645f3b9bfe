/* dens_impl.h - layer 3: the density engine's state, shared by its
 * files: dens_engine.c (lifetime, grid, schedule, measure, points out),
 * dens_sweep.c (an iteration's phases, on the one grid or the levels) and
 * dens_cell.c (one cell's solves and the accept rule). Not for use
 * outside them (dens_engine.h is the engine's interface). */
#ifndef CFPO_DENS_IMPL_H
#define CFPO_DENS_IMPL_H

#include <stdint.h>

#include "dens_buckets.h"
#include "dens_dist.h"
#include "dens_engine.h"
#include "dens_levels.h"
#include "dens_measure.h"
#include "dens_qbound.h"

#define KMAX 40        /* neighbours the solve looks at, nearest first */
#define KADD 24        /* ... plus at most this many that broke a candidate (dens_cell.c) */
#define REACH 2.0      /* ... within REACH local spacings */
#define CELL_SPACINGS 1.25 /* L >= CELL_SPACINGS r_max */
/* A point's level is one whose test spot, one cell from its block's edge,
 * keeps a value of (LEVEL_WORTH Delta)^2 by the outside bound
 * (dens_levels.h): a little above nearly every point's own value once the
 * set is spread (in a converged uniform set of 16,384 points the nearest
 * neighbour lies within 1.073 Delta for 99.9% of the points, the farthest
 * at 1.175). Until 2026-12-02 the test asked CELL_SPACINGS, which sent
 * points of the ramp 1:256 at 4,096 points to blocks of 100-650 points
 * (docs/tried.md, "The levels' test spot"). */
#define LEVEL_WORTH 1.1
#define BUCKET_FROM 64     /* blocks of fewer points are scanned whole (one bucket) */
#define BUCKET_PER 2.0     /* points a bucket on average */
#define BOUND_SAFE (1 + 1e-9)   /* a ring's distance bound must beat the value by this much */
#define DENS_SHIFT_EVERY 4      /* the grid keeps an offset for this many iterations */

typedef struct { /* one thread's buffers */
    double *bx, *by, *br, *nx, *ny, *nr, *ck, *cj, *scratch;
    int64_t *bid, *bslot; /* the block's points' ids and slots in cell order */
    int *nj, *ring; /* the nearest's block indices; a ring's buckets */
    size_t cap, ring_cap;
    cfpo_dens_buckets bk;
    int oom;
} tbuf;

struct cfpo_dens_engine {
    const cfpo_density *d;
    cfpo_dens_qbound qb;   /* the bound of q over a box, for the solve's prunings */
    cfpo_dens_qbound qlow; /* q's lower bound over a box, for the measure's search */
    cfpo_dens_nn_near near; /* the measure's search grid's near bounds, kept between measures */
    int64_t n, g;
    cfpo_options o;
    double D, L, sx, sy;
    cfpo_dens_store s; /* positions and sqrt of their pixels' densities (q): all, in id order, on one rank */
    cfpo_dens_dist *T; /* several ranks: the cut (NULL on one) */
    double *all;       /* several ranks: the whole set, gathered for the measure and the output */
    int64_t *cell, *cstart, *cidx, ccap;
    double *cxyq; /* x, y, q of the points in cell order (slot s = cidx's), kept equal to the store's */
    unsigned char *dirty; /* per cell: 1 when its 3 x 3 block changed since it was last solved without a move */
    int64_t solved;       /* this iteration's points solved on this rank */
    int nthreads;
    tbuf *tb;
    int iter, placed; /* placed: the grid has an offset (sx, sy) */
    int iters_run;    /* iterations made by this engine (not before a resume) */
    double davg_ref;  /* the schedule's delta_avg one window back (policy.h) */
    double last_dmin, last_davg; /* as last measured (o.lazy_measure: between measures) */
    double t_compute, t_migrate, t_halo; /* this rank's seconds in each */
    cfpo_dens_move_fn on_move;
    void *move_user;
    /* levels of cells sized to the local spacing (dens_levels.h); with
     * more than one, g, L, cstart, cidx and cxyq are the level being
     * solved's while it is, and level 0's otherwise */
    cfpo_dens_levels lv;
    int cur;              /* the level being solved */
    unsigned char *lev;   /* per store slot: an own point's level this iteration */
    uint32_t *fine;       /* per store slot: its finest cell (cfpo_dens_levels_fine), kept with its place */
    int fine_kept;        /* one rank: fine holds every point's cell under the levels' offset (the moves keep it) */
    int64_t *cstart0, *cidx0; /* several ranks: level 0's cells, for the halo refreshes */
    int64_t *slot;        /* several ranks: each store point's place in cidx (cxyq's row) */
    int64_t *lcells;      /* the level being solved: its cells holding a point (one rank) or this rank's cells (several), by colour */
    int64_t lcap;
    /* the skip on the levels (as dirty on the one grid): per level, per
     * cell, the last phase a move's old or new place lay in it (touch)
     * and the phase it was last solved in (seen, 0: not since the offset
     * changed); it is solved again when its 3 x 3 holds a touch >= seen
     * (cfpo_dens_levels_touched). phase counts the levels' colour phases,
     * from 1 */
    uint32_t *ltouch[CFPO_DENS_LEVELS_MAX], *lseen[CFPO_DENS_LEVELS_MAX];
    uint32_t phase;
    double *hold;         /* several ranks: the halo's places before a refresh */
    int64_t hcap;
};

static inline int64_t cell_of(const cfpo_dens_engine *E, double x, double y)
{
    return cfpo_dens_cell_of(E->g, E->sx, E->sy, x, y);
}

/* The cells of the grid E->g (under the offset E->sx, E->sy): E->cell,
 * cstart, cidx (store slots, in store order inside each cell), cxyq, and
 * slot when kept (dens_sweep.c). */
void dens_build_cells(cfpo_dens_engine *E);
/* The same for level l, each point's cell from its finest (E->fine). */
void dens_build_level(cfpo_dens_engine *E, int l);

/* One iteration's phases into *moves, *solved, *maxd (*tm: the phase
 * clock, for the timers; dens_sweep.c): on the one grid, or (more than one
 * level) level by level. Collective. 0, or -1 when out of memory. */
int dens_sweep_grid(cfpo_dens_engine *E, int64_t *moves, int64_t *solved, double *maxd, double *tm);
int dens_sweep_levels(cfpo_dens_engine *E, int64_t *moves, int64_t *solved, double *maxd, double *tm);

/* Solves the points of cell (cx, cy) one after another (dens_cell.c);
 * returns the moves made, the largest move (in local spacings) into
 * *maxd; sets b->oom when out of memory. */
int64_t dens_solve_cell(cfpo_dens_engine *E, tbuf *b, int64_t cx, int64_t cy, double *maxd);

#endif
