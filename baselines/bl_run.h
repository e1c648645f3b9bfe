/* bl_run.h - the part of a baseline command's run that talks to files:
 * the output point file and the --trace file, opened before the work so an
 * unwritable path fails at once, committed atomically at the end, removed
 * on failure or SIGINT (src/common/cli.h's guards). Also the progress line.
 * Does not own: option parsing (each main_*.c, in cfpo's style) or any
 * method. */
#ifndef CFPO_BASELINES_BL_RUN_H
#define CFPO_BASELINES_BL_RUN_H

#include <stddef.h>
#include <stdio.h>

#include "cli.h"
#include "pointfile.h"

typedef struct {
    const char *prog;
    const char *out, *trace;
    pf_writer *w;      /* open when the count is known in advance */
    size_t n;          /* that count; 0 when unknown until the end */
    cli_atomic tr;
    FILE *tf;          /* the trace stream, or NULL */
    cli_progress pg;
    double t0;
} bl_run;

/* Usage error (exit 2) when `out` has no known point-file extension. */
void bl_check_output_name(const char *prog, const char *out);

/* Opens the output (n > 0: the exact count that will be written; n == 0:
 * unknown, the path is only probed now and written at the end) and the
 * trace with its header line. Exits with status 1 and a message on failure.
 * Starts the clock. */
void bl_run_open(bl_run *r, const char *prog, const char *out, const char *trace, size_t n,
                 const char *trace_header, int quiet);

/* Writes the n points (xy interleaved) and commits the output and the
 * trace. Exits with status 1 and a message on failure. */
void bl_run_finish(bl_run *r, const double *xy, size_t n);

#endif
