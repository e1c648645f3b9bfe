/* bl_loop.h - the one run loop of the iterative baselines, with the stop
 * rules (src/common/stoprule.h), used by their commands (bl_cli.c) and by the
 * Python binding alike: the start is row 0; after it and after every
 * iteration the caller's row hook sees the statistics, then the rules are
 * tried in the order converged, targets, time, max-iter, then the hook's
 * own wish to stop (stop=caller).
 * Does not own: files, progress lines, the caller's interruption (all in
 * the row hook), any method (bl_method.h). */
#ifndef CFPO_BASELINES_BL_LOOP_H
#define CFPO_BASELINES_BL_LOOP_H

#include "bl_method.h"

/* After each row: 0 go on, 1 stop (the caller's rule), -1 fail (the loop
 * ends at once). `elapsed`: seconds since the run's t0. */
typedef int (*bl_row_fn)(void *user, void *E, const cfpo_iter_stats *s, double elapsed);

typedef struct {
    int64_t n;
    uint64_t seed;
    double tol;
    int max_iter;
    cfpo_stop_rules rules;
    const cfpo_density *density; /* NULL, or the density (m->create_density) */
} bl_loop_args;

typedef struct {
    int iterations;
    cfpo_iter_stats last; /* the last row's statistics */
    int why;              /* CFPO_STOP_*; CFPO_STOP_NONE when failed */
    int failed;           /* the hook returned -1 */
} bl_outcome;

/* Creates m's engine with options v and runs it until a rule stops it;
 * t0 is the run's start on cli_now()'s clock. Returns the engine (the
 * caller takes its points and destroys it), or NULL with a message when it
 * cannot be made. */
void *bl_loop(const bl_method *m, const bl_value *v, const bl_loop_args *a, double t0, bl_row_fn row, void *user,
              bl_outcome *o, char *err, size_t errlen);

/* The row of trace values of an iteration: the common columns
 * (CFPO_TRACE_COMMON), then the method's; row has room for
 * CFPO_TRACE_COMMON + BL_MAX_COLUMNS. Returns how many. */
int bl_trace_values(const bl_method *m, void *E, const cfpo_iter_stats *s, double elapsed, double *row);

#endif
