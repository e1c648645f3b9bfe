/* engine.h - layer 3: the CFPO iteration over one tile of cells with
 * OpenMP, plus the duties that need the tile's insides (packing halo cells
 * and migrating points; the messages go through comm).
 *
 * Owns: the buckets (points stored cell by cell, CSR offsets, id order
 * inside a cell), the halo ring (copies of the neighbouring ranks' cells
 * next to the tile), the colour schedule (9 phases, or 4 for the simplified
 * variant), the per-phase solve of every cell of one colour in parallel, the
 * skip flags, net displacements, the per-iteration statistics (reduced over
 * ranks), output in id order and checkpoints.
 * Does not own: choosing g or the initial points (grid, start), the cut
 * into tiles (tiles), the local solver (geom), the variants' decisions
 * for each iteration (policy: margin, grid shift, solver, over-relaxation),
 * MPI itself (comm), the command line.
 * May include: cfpo_types.h (layer 0), geom.h (1), grid.h, tiles.h,
 * comm.h, pointfile.h (2), engine_iface.h (3). Never cfpo.h (the library's front, above).
 *
 * With one rank the tile is the whole torus and a cell's neighbours across
 * the seam are its own cells (column -1 is column g - 1, shifted by -1):
 * there is no halo and no message.
 *
 * Compute backends. The schedule (engine_schedule.c) runs each phase as
 * solve -> mark -> migrate -> relocate -> halo; solve, mark, relocate and
 * the per-iteration displacement reset and maximum go through a table of
 * functions, struct cfpo_backend in src/engine/backend.h, while migration and the
 * halo (MPI) stay on the host. The OpenMP backend (backend_cpu.c) is the
 * first. A second one (a GPU) plugs in by
 *   1. filling a cfpo_backend with its own functions (backend_<name>.c),
 *      keeping the per-cell order of the OpenMP backend (points of a cell
 *      in id order, the same solver source) so the bytes stay the same,
 *      and doing with each point what the iteration's policy says
 *      (E->pol, policy.h: square, solver, over-relaxation);
 *   2. keeping the host arrays current where the host reads them, through
 *      its sync_host / sync_device functions (see backend.h);
 *   3. being chosen in cfpo_engine_create_ex (engine.c sets E->be).
 * Everything above the engine (cfpo_engine_run, checkpoints, the output)
 * is the same for every backend. */
#ifndef CFPO_ENGINE_H
#define CFPO_ENGINE_H

#include <stdint.h>

#include "cfpo_types.h"
#include "comm.h"
#include "engine_iface.h"
#include "grid.h"
#include "pointfile.h"
#include "tiles.h"

typedef struct cfpo_engine cfpo_engine;

/* How a run is spread over ranks and what it keeps. Zero means default. */
typedef struct {
    int px, py;              /* a forced cut into px x py tiles, or 0 */
    int check;               /* verify invariants after every migration and
                                halo refresh (tests; slow) */
    const char *resume;      /* start from this checkpoint instead of anew */
    const double *start_xy;  /* or from these n points (x0 y0 x1 y1 ..., in
                                [0,1), point k gets id k) instead of the
                                variant's start; every rank passes all n */
    const char *checkpoint;  /* write a checkpoint here ... */
    int checkpoint_every;    /* ... every this many iterations */
    uint64_t density_hash;   /* a flat density's hash (engines.h): written
                                into checkpoints and asked of a resumed one;
                                0 without a density */
    int64_t fixed;           /* points with id < fixed never move; they stay
                                neighbours of the others (the progressive
                                levels, progressive.h); 0: every point moves */
} cfpo_engine_config;

/* Allocates and makes the initial set (collective over all ranks). NULL
 * with a message on failure, on every rank. */
cfpo_engine *cfpo_engine_create(int64_t n, const cfpo_options *o, char *err, size_t errlen);
cfpo_engine *cfpo_engine_create_ex(int64_t n, const cfpo_options *o, const cfpo_engine_config *cfg,
                                   char *err, size_t errlen);
void cfpo_engine_free(cfpo_engine *E);

const cfpo_grid *cfpo_engine_grid(const cfpo_engine *E);
const cfpo_tiling *cfpo_engine_tiling(const cfpo_engine *E);

/* Bytes one rank allocates for nlocal points in a tile of `cells` cells
 * (plus its ring of `ring` halo cells), with `threads` threads. */
uint64_t cfpo_engine_bytes_local(int64_t nlocal, int64_t cells, int64_t ring, int threads);
/* The same for the whole torus on one rank. */
uint64_t cfpo_engine_bytes(int64_t n, int variant, int threads);

/* Prepares the coming iteration from the set as it stands: its decisions
 * asked of the policy (policy.h; in the adaptive variant the margin from
 * delta(X) as last measured by cfpo_engine_deltas, the grid shift, the
 * solver and the over-relaxation), the grid moved to the shift, the net
 * displacements cleared. Call before the phases of an iteration
 * (cfpo_engine_iterate does). */
void cfpo_engine_begin(cfpo_engine *E);

/* One phase: every cell of colour `colour` in parallel, then migration and
 * halo refresh. Returns the number of moves on this rank; *solved gets the
 * number of local problems solved. */
int64_t cfpo_engine_phase(cfpo_engine *E, int colour, int64_t *solved);

/* One sweep: cfpo_engine_begin, then every
 * colour's phase in order; *moved and *solved are this rank's totals. The
 * one colour loop: cfpo_engine_iterate and cfpo-bench both sweep so. */
void cfpo_engine_sweep(cfpo_engine *E, int64_t *moved, int64_t *solved);

/* One whole iteration (a sweep), with its statistics reduced over all
 * ranks. */
void cfpo_engine_iterate(cfpo_engine *E, cfpo_iter_stats *s);

/* delta_min and delta_avg of the current set over all ranks, normalised by
 * Delta(n); the same bits for any number of ranks and threads. */
void cfpo_engine_deltas(cfpo_engine *E, double *dmin, double *davg);

/* One rank only: copies the points into xy (2n doubles) in id order. */
void cfpo_engine_points(const cfpo_engine *E, double *xy);

/* Collective: writes every rank's points into f, point of id k at byte
 * base + 16 k (x then y, little-endian float64). */
int cfpo_engine_write_points(cfpo_engine *E, comm_file *f, uint64_t base, char *err, size_t errlen);
/* One rank only: streams the points in id order into a text/npy/raw
 * writer. */
int cfpo_engine_write(cfpo_engine *E, pf_writer *w, char *err, size_t errlen);

/* Runs to convergence or max_iter (writing checkpoints when configured),
 * calling o->progress on every rank; fills res: the one run loop
 * (run_loop.h) over this engine's table. 0, or -1 with a message when a
 * checkpoint could not be written or memory ran out (on every rank). */
int cfpo_engine_run(cfpo_engine *E, cfpo_result *res, char *err, size_t errlen);

/* The engine's table of the one interface (engine_ops.c); the run engine
 * R then runs E (R->o: E's options). */
void cfpo_engine_as_run(cfpo_engine *E, cfpo_run_engine *R);

/* Per-rank totals over the run (engine_iface.h's cfpo_engine_timing). */
void cfpo_engine_timing_get(cfpo_engine *E, cfpo_engine_timing *t);

/* Reads a checkpoint's header (every rank reads it). */
typedef struct {
    int64_t n, iteration;
    uint64_t seed;
    int variant, converged;
    int near; /* the run was still in its near phase */
    double tol;
    uint64_t hash; /* the density's (version 4), 0 for a run without one */
} cfpo_checkpoint_info;
int cfpo_checkpoint_peek(const char *path, cfpo_checkpoint_info *info, char *err, size_t errlen);

#endif
