/* engine_iface.h - layer 3: the one interface every engine offers to the
 * run (run_loop.h), the files (runfiles.h) and the library (cfpo.h).
 *
 * An engine is a pointer to its state and a table of what it does:
 * one iteration (statistics reduced over ranks), the set as it stands,
 * its points out (into a file shared by every rank, or through one
 * rank's point-file writer), a checkpoint, its per-rank timers, and its
 * end. The uniform engine (engine.h; its table in engine_ops.c) and the
 * density engine (dens_engine.h; dens_ops.c) fill it, with checkpoints in
 * the one 2-D format (ckpt.h); engines.h makes the one a 2-D run asks
 * for. The 3-D engine (src/d3/engine3_ops.c) fills it too: its points are
 * n x 3, so its point writers (put_points, put_text, copy) are NULL and
 * its files and checkpoints are its own (src/d3/). What they share is
 * written once above this line: the stop rules, progress, periodic and
 * signalled checkpoints (run_loop.c), the output files (runfiles.c).
 * May include: cfpo_types.h, comm.h, pointfile.h (layers 0-2). */
#ifndef CFPO_ENGINE_IFACE_H
#define CFPO_ENGINE_IFACE_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"
#include "comm.h"
#include "pointfile.h"

/* Per-rank totals over the run, as min, mean and max over ranks
 * (collective). Bytes are those this rank sent. */
typedef struct {
    double compute[3], migrate[3], halo[3];
    double halo_bytes[3], migrate_bytes[3];
    int64_t phases;
    int64_t checked_migrations, checked_halos; /* with a check mode */
} cfpo_engine_timing;

typedef struct {
    const char *name; /* "uniform", "density" */
    /* Collective: one iteration; s gets its statistics (iteration number,
     * deltas, moves, seconds as the largest over ranks). 0, or -1 with a
     * message on every rank. */
    int (*step)(void *E, cfpo_iter_stats *s, char *err, size_t errlen);
    /* Collective: the statistics of the set as it stands (iteration: where
     * the engine stands, converged: as a checkpoint said). 0 or -1. */
    int (*now)(void *E, cfpo_iter_stats *s, char *err, size_t errlen);
    /* Collective: every rank writes its points, id k at base + 16 k. */
    int (*put_points)(void *E, comm_file *f, uint64_t base, char *err, size_t errlen);
    /* One rank: every point, in id order, into w. */
    int (*put_text)(void *E, pf_writer *w, char *err, size_t errlen);
    /* One rank: every point, in id order, into xy (2 n doubles). */
    void (*copy)(void *E, double *xy);
    /* Collective: a checkpoint of the set at `iteration` to path. */
    int (*checkpoint)(void *E, const char *path, int iteration, int converged, char *err, size_t errlen);
    void (*timing)(void *E, cfpo_engine_timing *t); /* collective */
    int64_t (*cells_per_side)(const void *E);
    void (*free)(void *E);
} cfpo_engine_ops;

typedef struct {
    const cfpo_engine_ops *ops;
    void *E;
    int64_t n;
    cfpo_options o; /* as the engine runs them (seed, tol, stop rules, progress) */
    double t_born;  /* when its creation began (the time limit counts from it) */
} cfpo_run_engine;

#endif
