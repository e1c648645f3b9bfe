/* dens_engine.h - layer 3: CFPO under a density, with OpenMP, on one rank
 * or, under mpirun, on several (dens_dist.h) (docs/method.md, "Density").
 *
 * The torus is cut into g x g square cells of side L >= 1.25 r_max (r_max
 * = Delta(n) / sqrt(rho_min), the sparsest local spacing), g a multiple of
 * 3, the grid shifted by a random offset every fourth iteration, the cells
 * coloured (x mod 3, y mod 3): nine phases, each solving its cells in
 * parallel, whose 3 x 3 blocks are disjoint. Each point of a cell, in id
 * order, gets a candidate from the local solve (dens_solve.h) inside the
 * box of half-side r_i around it, clipped to its cell, and moves there
 * only when its measure rises by more than tol local spacings, its squared
 * symmetric measure f rises against every other point of the block, and
 * no point outside the block can have f below the old value (their
 * distance is at least the candidate's distance to the block's edge, their
 * density at least rho_min). A rejected move changes nothing; so every
 * move raises the moved point's smallest measure, and the smallest measure
 * over all pairs never falls. A cell whose block did not change since it
 * was last solved without a move is skipped (it would move nothing). The
 * run has converged when no point moved by tol, or when delta_avg stalls
 * (policy.h, cfpo_policy_density_stalled).
 * The output does not depend on the thread count, nor, under mpirun, on
 * the rank count: each rank solves the cells it owns (dens_dist.h).
 * The run loop, checkpoints and files are the one interface's
 * (dens_ops.h, run_loop.h).
 * Owns: the grid, the colour schedule, the accept rule, the skipping, the
 * schedule's per-iteration decisions. */
#ifndef CFPO_DENS_ENGINE_H
#define CFPO_DENS_ENGINE_H

#include <stdint.h>

#include "cfpo_types.h"
#include "comm.h"
#include "density.h"
#include "engine_iface.h"

typedef struct cfpo_dens_engine cfpo_dens_engine;

/* The cells a side of the grid for n points under d. */
int64_t cfpo_dens_grid(const cfpo_density *d, int64_t n);

/* n points under d; start: 2 n doubles to start from (--init, a
 * checkpoint), or NULL for cfpo_dens_start's; iter0: the iteration the
 * start stands at. o: seed, threads, tol (a move must gain more than tol
 * local spacings in the measure; converged when no point moved that far
 * in an iteration), skip. NULL with one line in err on failure. */
cfpo_dens_engine *cfpo_dens_create(const cfpo_density *d, int64_t n, const cfpo_options *o, const double *start,
                                   int iter0, char *err, size_t errlen);

/* One iteration (nine phases); its statistics into *s. 0, or -1 when out of memory. */
int cfpo_dens_iterate(cfpo_dens_engine *E, cfpo_iter_stats *s);

/* The set's delta_min and delta_avg (collective). 0, or -1 when out of
 * memory. */
int cfpo_dens_measure(cfpo_dens_engine *E, double *dmin, double *davg);
/* The iteration the engine stands at. */
int cfpo_dens_iteration(const cfpo_dens_engine *E);
/* The schedule's stop rule's state (policy.h, cfpo_policy_density_stalled),
 * kept by checkpoints. */
double cfpo_dens_davg_ref(const cfpo_dens_engine *E);
void cfpo_dens_set_davg_ref(cfpo_dens_engine *E, double ref);
/* Collective: every rank writes its points into f, id k at base + 16 k. */
int cfpo_dens_write_points(cfpo_dens_engine *E, comm_file *f, uint64_t base, char *err, size_t errlen);
/* Collective: per-rank seconds in the solves, the migration and the halo
 * refreshes (no byte counts). */
void cfpo_dens_timing(const cfpo_dens_engine *E, cfpo_engine_timing *t);

/* 2 n doubles, id order. Under several ranks (dens_dist.h) collective: the
 * whole set gathered on every rank (NULL when out of memory on any). */
const double *cfpo_dens_points(const cfpo_dens_engine *E);
/* The points this rank owns (n on one rank). */
int64_t cfpo_dens_own_points(const cfpo_dens_engine *E);
/* The levels of cells (dens_levels.h): 1 when the one grid serves. */
int cfpo_dens_levels_count(const cfpo_dens_engine *E);

/* For the tests: fn(points, id, user) after every accepted move (from the
 * thread that made it). */
typedef void (*cfpo_dens_move_fn)(const double *xy, int64_t id, void *user);
void cfpo_dens_on_move(cfpo_dens_engine *E, cfpo_dens_move_fn fn, void *user);
int64_t cfpo_dens_cells_per_side(const cfpo_dens_engine *E);
void cfpo_dens_free(cfpo_dens_engine *E);

#endif
