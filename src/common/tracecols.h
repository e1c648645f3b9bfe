/* tracecols.h - layer 1: the columns of an iterative run's --trace file.
 *
 * Owns: the one definition of the trace columns (name and printf format)
 * of `cfpo --trace` and of the iterative baselines, whose files start with
 * the first CFPO_TRACE_COMMON of them and go on with their own; the row of
 * values of an iteration's statistics; writing a header and a row.
 * Read by src/files/runfiles.c and src/main.c (the cfpo command), baselines/
 * (bl_loop.c) and the Python binding (python/src), which learns the names
 * from here.
 * May include: cfpo_types.h (layer 0). */
#ifndef CFPO_TRACECOLS_H
#define CFPO_TRACECOLS_H

#include <stdio.h>

#include "cfpo_types.h"

/* A column: its name in the header and the printf format of its value
 * ("%lld": a whole number, printed from (long long)value). */
typedef struct {
    const char *name;
    const char *fmt;
} cfpo_trace_column;

#define CFPO_TRACE_COLUMNS 10 /* cfpo's columns */
#define CFPO_TRACE_COMMON 8   /* the first ones, every iterative method's */

extern const cfpo_trace_column cfpo_trace_columns[CFPO_TRACE_COLUMNS];

/* The values of cfpo's columns for statistics s, `elapsed` seconds into
 * the run. */
void cfpo_trace_values(const cfpo_iter_stats *s, double elapsed, double row[CFPO_TRACE_COLUMNS]);

/* 1 when the column's values are whole numbers. */
int cfpo_trace_is_whole(const cfpo_trace_column *c);

/* The names of cols[0..n-1], each after a tab except the first when
 * `first` (no newline). */
void cfpo_trace_write_names(FILE *f, const cfpo_trace_column *cols, int n, int first);

/* The values v[0..n-1] in their columns' formats, likewise. */
void cfpo_trace_write_values(FILE *f, const cfpo_trace_column *cols, const double *v, int n, int first);

#endif
