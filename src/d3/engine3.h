/* engine3.h - layer 2 of the 3-D engine: CFPO on the unit 3-torus, one
 * process, OpenMP threads.
 *
 * Owns: the engine's state (points by id, the grid and its shift, the
 * cells' buckets, the skip stamps) and its interface, shaped like the 2-D
 * engines' so that it plugs into one pipeline: create (from n, or from
 * given points), step (one iteration, returning cfpo_iter_stats), measure,
 * checkpoint write and read (engine3_ckpt.c), the points out. The
 * iteration itself (27 colours, the constraint cube, the adaptive margin,
 * the moves) is engine3_step.c's. docs/method.md, "Three dimensions". */
#ifndef CFPO_ENGINE3_H
#define CFPO_ENGINE3_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"
#include "grid3.h"

/* Default tolerance (relative to the cell side), and the over-relaxation
 * weights of the default policy (docs/method.md, "Three dimensions"). */
#define CFPO3_DEFAULT_TOL 1e-4

typedef struct {
    uint64_t seed;
    int threads;     /* 0: OpenMP's default */
    double tol;      /* move gain and convergence, relative to L */
    int relax;       /* 1: over-relaxed moves (the default), 0: to the solver's spot */
    int shift;       /* 1: the grid moves before iterations 1, 5, 9, ... (default) */
    int skip;        /* 1: cells whose block did not change are not solved again */
    int near;        /* 1: start in the near phase (the default), 0: the exact solve from the start */
} cfpo3_options;

void cfpo3_options_default(cfpo3_options *o);

typedef struct cfpo3_engine cfpo3_engine;

/* The most given points one cell may hold (cfpo3_create_given): a
 * cell's work grows fast with its count; the engine's own sets hold at
 * most about 12. */
#define CFPO3_INIT_MAX_CELL 64

/* From n (the jittered start) or from given points (3n doubles in [0,1),
 * copied; refused when a cell holds more than CFPO3_INIT_MAX_CELL). NULL
 * with one line in err (n too small, a crowded cell, out of memory). */
cfpo3_engine *cfpo3_create(int64_t n, const cfpo3_options *o, char *err, size_t errlen);
cfpo3_engine *cfpo3_create_given(const double *xyz, int64_t n, const cfpo3_options *o, char *err,
                                 size_t errlen);
void cfpo3_free(cfpo3_engine *e);

/* One iteration. Fills s (iteration, delta_min, delta_avg over Delta3,
 * moved, solved, max_disp, max_move, converged, seconds). 0, or -1 (out of
 * memory). */
int cfpo3_step(cfpo3_engine *e, cfpo_iter_stats *s);

/* The current set's delta_min and delta_avg over Delta3(n). */
void cfpo3_measure(const cfpo3_engine *e, double *delta_min, double *delta_avg);

/* Iterations done so far (a resumed engine counts the earlier ones). */
int cfpo3_iterations(const cfpo3_engine *e);
int64_t cfpo3_n(const cfpo3_engine *e);
const cfpo3_grid *cfpo3_grid_of(const cfpo3_engine *e);
const cfpo3_options *cfpo3_options_of(const cfpo3_engine *e);
/* The points by id, 3n doubles in [0,1): valid until the next step. On
 * one rank only (several ranks hold their region's points: use
 * cfpo3_gather). */
const double *cfpo3_points(const cfpo3_engine *e);
/* Collective: every point by id into all (3n doubles), on every rank. 0,
 * or -1 (memory, on any rank). */
int cfpo3_gather(const cfpo3_engine *e, double *all);
/* This rank's timers so far: v = compute, halo and migration seconds,
 * halo and migration bytes sent; the colour phases run; bricks[3] the
 * cut's runs along x, y, z. */
void cfpo3_rank_timers(const cfpo3_engine *e, double v[5], int64_t *phases, int bricks[3]);
/* The points of this rank's brick. */
int64_t cfpo3_own_points(const cfpo3_engine *e);
/* The local solver's work so far, summed over solves: Voronoi cells
 * clipped, farthest vertices tested against the bisectors, cuts made (for
 * measuring). */
void cfpo3_work(const cfpo3_engine *e, long *cells, long *tests, long *cuts);
/* Heap bytes a point at the peak of one rank's run (for --dry-run), from
 * what cfpo3_create and the measure allocate: every rank holds n-long
 * arrays (positions, previous positions, cell, cell lists: 60 B a point)
 * and 40 B a grid cell, and the measure's peak, at the start, when a
 * nearest neighbour may lie beyond its block and the whole set is
 * measured: 76 B a point on one rank, 72 + 32 / ranks + 32 B (the set
 * gathered) on several (docs/results/2026-11-29-3d-solve.md). Not divided
 * by the ranks. */
double cfpo3_bytes_per_point_ranks(int64_t n, int ranks);
/* The same on one rank. */
double cfpo3_bytes_per_point(int64_t n);

/* Checkpoints (engine3_ckpt.c): a versioned binary file with a CRC-32,
 * written whole or not at all. The resumed run gives the same bytes as an
 * uninterrupted one. read: the options other than threads come from the
 * file; NULL with one line in err. A caller may add a block of its own
 * after the points (the command's schedule, sched3.h): fn fills *buf
 * (malloc'd, freed by the writer) and *len on every rank (0 or -1), and
 * the block of a read checkpoint is kept with the engine (NULL, 0 when
 * it carried none). */
typedef int (*cfpo3_tail_fn)(void *user, unsigned char **buf, size_t *len);
void cfpo3_set_checkpoint_tail(cfpo3_engine *e, cfpo3_tail_fn fn, void *user);
const unsigned char *cfpo3_checkpoint_tail(const cfpo3_engine *e, size_t *len);
int cfpo3_checkpoint_write(const cfpo3_engine *e, const char *path, char *err, size_t errlen);
cfpo3_engine *cfpo3_checkpoint_read(const char *path, int threads, char *err, size_t errlen);
/* The checksum a checkpoint's bytes (header and points, len < 4 GiB)
 * should carry at offset 60 (tests, fuzzing). */
uint32_t cfpo3_checkpoint_crc(const unsigned char *buf, size_t len);
/* The same reader on bytes in memory (tests, fuzzing). */
cfpo3_engine *cfpo3_checkpoint_parse(const unsigned char *buf, size_t len, const char *name, int threads,
                                     char *err, size_t errlen);

#endif
