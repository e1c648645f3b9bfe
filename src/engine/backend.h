/* backend.h - layer 3, internal to the engine: the seam between the colour
 * schedule (engine_schedule.c, host side) and the code that does the
 * per-phase work on the points (a compute backend). Only src/engine/engine*.c and
 * src/engine/backend_*.c include it. May include cells.h.
 *
 * A phase, as the schedule runs it:
 *
 *   backend   solve     every own cell of the colour, in parallel; points
 *                       move in place; each cell's mask says into which of
 *                       its 3x3 neighbours its points went
 *   backend   mark      turn the masks into change marks (skip flags and
 *                       statistics blocks); report whether a point left its
 *                       cell
 *   host      migrate   pack points that left the tile, exchange them with
 *                       the neighbouring ranks (comm)
 *   backend   relocate  rebuild the cell lists: points that changed cell
 *                       inside the tile, and arrivals
 *   host      halo      refresh the copies of the neighbours' border cells
 *
 * plus, once an iteration, begin (clear the net displacements) and
 * max_disp2 (the largest net displacement, for the convergence rule), and
 * regrid, which computes the masks after the grid moved under the points
 * (the adaptive variant's shift) so the same mark / migrate / relocate
 * steps re-bucket them.
 *
 * What a backend does with each point follows the iteration's policy,
 * E->pol (policy.h, set by the schedule before the iteration's first
 * phase): the square (cfpo_policy_square, which also says when a point
 * stays), the solver (the near solve with pol.near_cells cells, or
 * LocalCFPO) and the over-relaxed spot (cfpo_policy_relax). A backend
 * reads these and holds no decision of a variant's schedule itself.
 *
 * The host steps (migration, halo, statistics, output, checkpoints) read
 * and write the engine's point arrays (px, py, pid, dq, start) directly.
 * A backend that keeps its own copy of the points (a GPU) makes them
 * current in sync_host before each host step that reads them and takes
 * back what the host changed in sync_device after it; the CPU backend
 * works on the host arrays and needs neither. With one rank no point
 * leaves the tile and the halo is empty, so only the statistics and the
 * output need the host copy. */
#ifndef CFPO_BACKEND_H
#define CFPO_BACKEND_H

#include "cells.h"

typedef struct cfpo_backend {
    const char *name;
    /* Once an iteration, before its first phase: net displacements and
     * the largest single move set to zero. */
    void (*begin)(cfpo_engine *E);
    /* Solves every own cell of colour C (cells whose block did not change
     * are skipped when E->o.skip). Returns the moves; adds the local
     * problems solved to *solved; raises E->max_move. */
    int64_t (*solve)(cfpo_engine *E, const eng_colour *C, int64_t *solved);
    /* After the grid moved: each cell of colour C gets the mask of the
     * cells that now hold its points. */
    void (*regrid)(cfpo_engine *E, const eng_colour *C);
    /* Marks the blocks around every cell of colour C whose mask is set;
     * returns 1 when some point left its cell. */
    int (*mark)(cfpo_engine *E, const eng_colour *C);
    /* Clears the masks of colour C (keeping the skip flags). */
    void (*unmark)(cfpo_engine *E, const eng_colour *C);
    /* Rebuilds the cell lists after colour `colour`'s moves and the
     * arrivals in E->arr. 0, or -1 when out of memory. */
    int (*relocate)(cfpo_engine *E, int colour);
    /* The largest squared net displacement of a point this iteration. */
    double (*max_disp2)(const cfpo_engine *E);
    /* Host copy current / device copy current (NULL: nothing to do). */
    void (*sync_host)(cfpo_engine *E);
    void (*sync_device)(cfpo_engine *E);
} cfpo_backend;

/* The OpenMP backend (backend_cpu.c). */
extern const cfpo_backend eng_backend_cpu;

#endif
