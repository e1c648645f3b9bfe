/* cfpo_types.h - layer 0: the sampler's plain types and constants (the
 * variants, tolerances, per-iteration statistics, stop rules, options and
 * result), shared by every layer and by the public cfpo.h. Declares no
 * function and includes nothing of the project. */
#ifndef CFPO_TYPES_H
#define CFPO_TYPES_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CFPO_VERSION "0.1.0"

/* PAPER: the published algorithm (9 phases, S = cell grown by L - Delta(n),
 * the stratified start). SIMPLIFIED: 4 phases, S = own cell. ADAPTIVE (the
 * default): 9 phases on the same grid with the margin and start described
 * in docs/method.md. FULL is the old name of PAPER. */
enum { CFPO_VARIANT_PAPER = 0, CFPO_VARIANT_SIMPLIFIED = 1, CFPO_VARIANT_ADAPTIVE = 2, CFPO_VARIANT_HYPERUNIFORM = 3 };
#define CFPO_VARIANT_FULL CFPO_VARIANT_PAPER

/* Default move/convergence tolerance, relative to the cell side: the
 * paper's variants use 1e-4; the adaptive variant 3e-5, where it reaches
 * FPO's delta_min at convergence (docs/method.md). */
#define CFPO_DEFAULT_TOL 1e-4
#define CFPO_ADAPTIVE_TOL 3e-5
/* Under a density: a move must gain more than this many local spacings in
 * the measure (policy.h chooses among the three). */
#define CFPO_DENSITY_TOL 1e-4
/* The largest tolerance any command, option set or checkpoint may carry
 * (the one bound, checked everywhere a tolerance comes in). */
#define CFPO_TOL_MAX 0.49
#define CFPO_DEFAULT_MAX_ITER 10000
#define CFPO_MAX_ITER_MAX 1000000000 /* the largest --max-iter (0..1e9) */

typedef struct {
    int iteration;     /* 1-based; 0 is the initial set */
    double delta_min;  /* min nearest-neighbour distance / Delta(n) */
    double delta_avg;  /* mean nearest-neighbour distance / Delta(n) */
    int64_t moved;     /* moves made in this iteration */
    int64_t solved;    /* local problems solved (the rest were skipped) */
    double max_disp;   /* largest net displacement over the iteration / cell side */
    double seconds;    /* wall time of this iteration, statistics included */
    int converged;     /* max_disp < tol */
    double max_move;   /* largest single move in the iteration / cell side */
    int near;          /* 1: solved by the near solve (the adaptive variant's
                          first phase, docs/method.md), 0: by LocalCFPO */
    int stale;         /* 1: delta_min and delta_avg are the last measured
                          ones, not this iteration's (cfpo_options.lazy_measure) */
} cfpo_iter_stats;

/* Called after every iteration (and once with iteration 0); returning
 * nonzero stops the run early (the result then says converged = 0). */
typedef int (*cfpo_progress_fn)(const cfpo_iter_stats *s, void *user);

/* Stop rules besides convergence and max_iter (0 = not set): stop as soon
 * as every given target holds (delta_min >= target_min, delta_avg >=
 * target_avg), or at the first iteration boundary past time_limit seconds. */
typedef struct {
    double target_min, target_avg, time_limit;
} cfpo_stop_rules;

typedef struct {
    uint64_t seed;
    int variant;       /* CFPO_VARIANT_* */
    int threads;       /* OpenMP threads; 0 = all cores */
    int max_iter;      /* cap on iterations */
    double tol;        /* relative to the cell side: a move must gain more
                          than tol * L in distance to Y(x); converged when no
                          point's net move over an iteration reaches tol * L */
    int skip;          /* 1: do not re-solve points whose neighbourhood did
                          not change (same output, less work) */
    cfpo_stop_rules stop;
    cfpo_progress_fn progress;
    void *user;
    int lazy_measure;  /* 1: the density engine, whose measure is a pass of
                          its own, measures delta_min and delta_avg only at
                          the iterations its stop rules read (docs/method.md,
                          "Density": every 16th; every one when a target is
                          set) and where the run stops: the same points and
                          result, about a tenth less time an iteration; the
                          progress callback sees the last measured values in
                          between (stale = 1). 0: every iteration (the
                          uniform and 3-D engines always do). The same on
                          every rank, as every option */
} cfpo_options;

typedef struct {
    int iterations;
    int converged;
    double seconds;
    double delta_min, delta_avg;
    int64_t cells_per_side;
    int stop;          /* why it stopped: CFPO_STOP_* of stoprule.h */
} cfpo_result;

#ifdef __cplusplus
}
#endif
#endif
