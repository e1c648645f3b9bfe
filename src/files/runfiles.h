/* runfiles.h - layer 4: the files of one cfpo run across ranks, for
 * every engine (engine_iface.h): the points (text through one rank's
 * writer; .npy and raw written by every rank into one shared file through
 * MPI-IO) and the trace (rank 0; its rows kept in memory during the run).
 * Nothing is created during the run: at the end each file is written to a
 * temporary beside its final name, registered with the signal clean-up,
 * and renamed into place only when all were written whole; a failed or
 * interrupted run (even by kill -9) leaves no file behind.
 * May include: cfpo_types.h, engine_iface.h (layers 0-3). */
#ifndef CFPO_RUNFILES_H
#define CFPO_RUNFILES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "engine_iface.h"

typedef struct cfpo_runfiles cfpo_runfiles;

/* Checks, before anything is opened, that no name is empty, that the
 * output, trace and checkpoint are three different files (the same file
 * under another name counts as the same), and that `out` has a known
 * format this many ranks can write. 0, or -1 with a one-line message (a
 * usage error). Any name may be NULL. */
int cfpo_runfiles_check(const char *out, const char *trace, const char *checkpoint, int ranks, char *err,
                        size_t errlen);

/* Collective: tries that `out` (n points), `trace` and `checkpoint` (any
 * may be NULL) can be created (a temporary beside each, made and
 * removed), so a bad path fails before the work; starts the trace in
 * memory with its header. NULL with a message on every rank when one
 * cannot be created (nothing left behind). */
cfpo_runfiles *cfpo_runfiles_open(const char *out, const char *trace, const char *checkpoint, int64_t n,
                                  char *err, size_t errlen);

/* The trace stream on rank 0 (NULL elsewhere, or without a trace): rows
 * written to it reach the file at commit. */
FILE *cfpo_runfiles_trace(const cfpo_runfiles *f);

/* Collective: writes the engine's points and the trace, finishes every
 * file, and only when all were written whole puts them in place; frees f.
 * 0, or -1 with a message (then no file was replaced and no temporary is
 * left). */
int cfpo_runfiles_commit(cfpo_runfiles *f, const cfpo_run_engine *R, char *err, size_t errlen);

/* Collective: removes every temporary; frees f (NULL: nothing). */
void cfpo_runfiles_abort(cfpo_runfiles *f);

#endif
