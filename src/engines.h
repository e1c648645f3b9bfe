/* engines.h - layer 4: the engine a run asks for, behind the one
 * interface (engine_iface.h).
 *
 * Without a density: the uniform engine (engine.h). With one: the density
 * engine (dens_ops.h), except for a flat density (every pixel the same),
 * which is the uniform torus: the uniform engine then runs it, with the
 * density's hash in its checkpoints, and gives the bytes of the run
 * without --density. A resume with a density reads the checkpoint whole
 * on every rank and refuses another density's.
 * Owns: that choice, and the resume of a density run.
 * May include: engine.h, dens_ops.h, density.h, ckpt_io.h (layers 0-3). */
#ifndef CFPO_ENGINES_H
#define CFPO_ENGINES_H

#include "density.h"
#include "engine.h"

/* 1 when d is flat (the uniform torus). */
int cfpo_density_is_flat(const cfpo_density *d);

/* The default tolerance of a run of this variant under d (NULL: none). */
double cfpo_engines_default_tol(int variant, const cfpo_density *d);

/* Collective: the engine for n points under d (NULL: none) with options o
 * and cfg (resume, start_xy, checkpoint and, for the uniform engine,
 * tiles and check) into R; R->t_born = t_born. d must outlive R. 0, or -1
 * with one line in err on every rank. */
int cfpo_engines_open(int64_t n, const cfpo_options *o, const cfpo_engine_config *cfg, const cfpo_density *d,
                      double t_born, cfpo_run_engine *R, char *err, size_t errlen);

#endif
