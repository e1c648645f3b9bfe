/* dens_ops.h - layer 3: the density engine (dens_engine.h) behind the one
 * interface (engine_iface.h).
 * May include: dens_engine.h, engine_iface.h and what they include. */
#ifndef CFPO_DENS_OPS_H
#define CFPO_DENS_OPS_H

#include "dens_engine.h"
#include "engine_iface.h"

/* Creates the density engine (cfpo_dens_create's arguments; converged0
 * and davg_ref: what a checkpoint resumed from said, else 0) into R
 * (R->t_born is the caller's). d must outlive R. 0, or -1 with one line. */
int cfpo_dens_open(const cfpo_density *d, int64_t n, const cfpo_options *o, const double *start, int iter0,
                   int converged0, double davg_ref, cfpo_run_engine *R, char *err, size_t errlen);

/* The points this rank owns in a density run R (n on one rank). */
int64_t cfpo_dens_run_own_points(const cfpo_run_engine *R);
/* The levels of cells of a density run (dens_levels.h; 1: the one grid). */
int cfpo_dens_run_levels(const cfpo_run_engine *R);

#endif
