/* run_loop.h - layer 3: the one run loop of every engine.
 *
 * Iterates an engine (engine_iface.h) until a stop rule holds (stoprule.h:
 * converged, targets, time limit, iteration cap; the progress callback),
 * calling the progress callback after every iteration and once before the
 * first; writes a checkpoint every `every` iterations and where the run
 * stops (a run that stopped at a limit continues with --resume); and, when the
 * process got SIGTERM or SIGUSR1 (runsignal.h) and a checkpoint is
 * configured, writes one at the next iteration boundary and stops with
 * CFPO_STOP_SIGNAL. Every rank decides the same: the statistics, the
 * elapsed time and the signal are reduced over ranks. Where the last
 * iteration did not measure the set (cfpo_options.lazy_measure), the
 * result's deltas come from the engine's `now`.
 * May include: engine_iface.h, runsignal.h, stoprule.h (layers 0-3). */
#ifndef CFPO_RUN_LOOP_H
#define CFPO_RUN_LOOP_H

#include "engine_iface.h"

/* Collective. checkpoint (may be NULL) every `every` iterations (0: only on
 * a signal). res gets the run. 0, or -1 with a message on every rank (a
 * step or a checkpoint failed). */
int cfpo_run_loop(cfpo_run_engine *R, const char *checkpoint, int every, cfpo_result *res, char *err,
                  size_t errlen);

#endif
