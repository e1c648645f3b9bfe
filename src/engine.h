/* engine.h - layer 3: the CFPO iteration over the whole torus with OpenMP.
 *
 * Owns: the buckets (points stored cell by cell, CSR offsets, id order
 * inside a cell), the colour schedule (9 phases, or 4 for the simplified
 * variant), the per-phase solve of every cell of one colour in parallel, the
 * skip flags, net displacements and the per-iteration statistics.
 * Does not own: choosing g or making the start (grid), the local solver
 * (geom), files or the command line.
 *
 * With one process the tile is the whole torus and a cell's halo is its own
 * wrap: neighbour (cx+1) of the last column is column 0, shifted by +1. */
#ifndef CFPO_ENGINE_H
#define CFPO_ENGINE_H

#include <stdint.h>

#include "cfpo.h"
#include "grid.h"
#include "pointfile.h"

typedef struct cfpo_engine cfpo_engine;

/* Allocates and makes the initial set. NULL with a message on failure. */
cfpo_engine *cfpo_engine_create(int64_t n, const cfpo_options *o, char *err, size_t errlen);
void cfpo_engine_free(cfpo_engine *E);

const cfpo_grid *cfpo_engine_grid(const cfpo_engine *E);

/* Bytes the engine would allocate for n points (for refusing runs that
 * cannot fit before allocating anything). */
uint64_t cfpo_engine_bytes(int64_t n, int variant, int threads);

/* One phase: every cell of colour `colour` in parallel. Returns the number
 * of moves; *solved gets the number of local problems solved. */
int64_t cfpo_engine_phase(cfpo_engine *E, int colour, int64_t *solved);

/* One whole iteration (all colours in order), with its statistics. */
void cfpo_engine_iterate(cfpo_engine *E, cfpo_iter_stats *s);

/* delta_min and delta_avg of the current set, normalised by Delta(n). */
void cfpo_engine_deltas(cfpo_engine *E, double *dmin, double *davg);

/* Copies the points into xy (2n doubles) in id order. */
void cfpo_engine_points(const cfpo_engine *E, double *xy);

/* Streams the points in id order into an open writer (no 16n copy: uses
 * the engine's spare buffers). */
int cfpo_engine_write(cfpo_engine *E, pf_writer *w, char *err, size_t errlen);

/* Runs to convergence or max_iter, calling o->progress; fills res. */
void cfpo_engine_run(cfpo_engine *E, cfpo_result *res);

#endif
