/* iter_main.h - the command line shared by the iterative baselines that
 * are not FPO (cfpo-ccvt, cfpo-ccdt): cfpo's options (-n, --seed,
 * --max-iter, --tol, --target-min, --target-avg, --time-limit, -o,
 * --trace, -q, -h, -V), its stop rules (src/stoprule.h), the trace with
 * cfpo's columns (plus a method's own after them), the progress line and
 * one SUMMARY line; exit codes 0/1/2 and one-line errors; no output file
 * unless the run succeeds (bl_run.h).
 * Does not own: any method. A method plugs in through it_method: its
 * engine behind a void pointer, and at most a few options of its own. */
#ifndef CFPO_BASELINES_ITER_MAIN_H
#define CFPO_BASELINES_ITER_MAIN_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"

typedef struct {
    const char *prog;        /* command name, e.g. "cfpo-ccvt" */
    const char *method;      /* SUMMARY method= */
    const char *about;       /* the help's description lines */
    const char *options_help;/* the help's lines for the method's options ("" if none) */
    const char *extra_opt;   /* the one long option with a value the method takes, or NULL */
    const char *trace_extra; /* extra trace columns, "\tname..." ("" if none) */
    /* parses the value of extra_opt into ctx; 0 ok, -1 bad (usage error) */
    int (*parse_extra)(void *ctx, const char *arg, char *err, size_t errlen);
    /* bytes the method needs for n points (its own memory model) */
    uint64_t (*bytes)(void *ctx, int64_t n);
    /* the engine for n points, seed and tol; NULL with a message */
    void *(*create)(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
    void (*iterate)(void *E, cfpo_iter_stats *s);
    void (*deltas)(void *E, double *dmin, double *davg);
    /* writes the extra trace columns' values ("\tv..."), may be NULL */
    void (*trace_values)(void *E, char *buf, size_t len);
    const double *(*points)(void *E);
    void (*destroy)(void *E);
} it_method;

int it_main(int argc, char **argv, const it_method *m, void *ctx);

#endif
