/* iter_main.h - the command line shared by the iterative baselines
 * (cfpo-fpo, cfpo-lfpo, cfpo-ccvt, cfpo-ccdt): cfpo's options (-n, --seed,
 * --max-iter, --tol, --target-min, --target-avg, --time-limit, -o,
 * --trace, -q, -h, -V), its stop rules (src/stoprule.h), the trace with
 * cfpo's columns (plus a method's own after them), the progress line and
 * one SUMMARY line; exit codes 0/1/2 and one-line errors; no output file
 * unless the run succeeds (bl_run.h).
 * Does not own: any method. A method plugs in through it_method: its
 * engine behind a void pointer, and at most IT_MAX_OPTIONS options of its
 * own. */
#ifndef CFPO_BASELINES_ITER_MAIN_H
#define CFPO_BASELINES_ITER_MAIN_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"

#define IT_MAX_OPTIONS 8

/* A long option of the method's own: --name, with a value when has_arg. */
typedef struct {
    const char *name;
    int has_arg;
} it_option;

typedef struct {
    const char *prog;        /* command name, e.g. "cfpo-ccvt" */
    const char *method;      /* SUMMARY method= */
    const char *about;       /* the help's description lines */
    const char *options_help;/* the help's lines for the method's options ("" if none) */
    const it_option *options;/* the method's options, ended by a NULL name; NULL if none */
    const char *trace_extra; /* extra trace columns, "\tname..." ("" if none) */
    /* option options[which] was given (arg NULL for a flag) into ctx; 0 ok,
     * -1 bad (usage error) */
    int (*parse_option)(void *ctx, int which, const char *arg, char *err, size_t errlen);
    /* SUMMARY method= when the options decide it; NULL: method */
    const char *(*method_name)(void *ctx);
    /* checks n before any work: 0 ok, -1 usage error, -2 runtime failure
     * (too large for memory), with a message; NULL: cfpo's smallest n and
     * bytes() against the machine's memory */
    int (*validate)(void *ctx, int64_t n, double tol, char *err, size_t errlen);
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
