/* stoprule.h - layer 2: when an iterative run stops.
 *
 * Owns: the one definition of the stop rules shared by CFPO (every rank
 * decides the same from the same reduced statistics) and the FPO
 * baselines: convergence by net change (the statistics' `converged`),
 * quality targets on delta_min / delta_avg, a wall-clock limit checked at
 * iteration boundaries, and the iteration cap; their names for the SUMMARY
 * line; the command-line options that set them.
 * May include: cfpo_types.h (layer 0), cli.h. */
#ifndef CFPO_STOPRULE_H
#define CFPO_STOPRULE_H

#include "cfpo_types.h"

enum {
    CFPO_STOP_NONE = 0,   /* go on */
    CFPO_STOP_CONVERGED,  /* no point's net move reached tol * L */
    CFPO_STOP_TARGET,     /* every given quality target holds */
    CFPO_STOP_TIME,       /* the first iteration boundary past the time limit */
    CFPO_STOP_MAX_ITER,   /* the iteration cap */
    CFPO_STOP_CALLER,     /* the progress callback asked to stop */
    CFPO_STOP_SIGNAL,     /* SIGTERM or SIGUSR1, a checkpoint written (run_loop.h) */
    CFPO_STOP_FLAT,       /* the flatness rule held (stopflat.h; the 3-D command) */
    CFPO_STOP_LEVEL_ITER  /* a progressive level reached its cap, the schedule's end (progressive.h) */
};

void cfpo_stop_rules_init(cfpo_stop_rules *r);

/* The three rules' options: the long option without its dashes and the
 * range (lo, hi] of its value; target-min, target-avg, time-limit. */
typedef struct {
    const char *name;
    double lo, hi;
} cfpo_stop_option;
extern const cfpo_stop_option cfpo_stop_options[3];

/* Parses the value of --target-min, --target-avg or --time-limit (`name`
 * is the long option without its dashes) into r; a bad value is a usage
 * error (one line, exit 2). Returns 1 when name is one of the three, 0
 * otherwise (nothing done). */
int cli_stop_option(const char *prog, const char *name, const char *arg, cfpo_stop_rules *r);

/* The convergence rule of CFPO and the FPO baselines alike: an iteration
 * that moved no point, or whose largest net displacement of a point (in
 * cell sides) stayed under tol. */
static inline int cfpo_net_converged(int64_t moved, double max_disp, double tol)
{
    return moved == 0 || max_disp < tol;
}

/* The rule that stops a run after an iteration with statistics s (s->iteration
 * iterations done, s->converged as the method defines it), `elapsed`
 * seconds since the run started, under an iteration cap max_iter; rules are
 * tried in the order converged, target, time, max-iter. CFPO_STOP_NONE: go
 * on. */
int cfpo_stop_check(const cfpo_stop_rules *r, const cfpo_iter_stats *s, double elapsed, int max_iter);

/* 1 when every target that is set holds for (dmin, davg); 0 when none is
 * set or one does not hold. */
int cfpo_stop_targets_met(const cfpo_stop_rules *r, double dmin, double davg);

/* "converged", "target", "time", "max-iter", "caller", "signal", "flat"
 * ("-" for none). */
const char *cfpo_stop_name(int why);

#endif
