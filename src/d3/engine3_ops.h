/* engine3_ops.h - the 3-D engine (engine3.h) behind the one interface
 * every engine offers (src/engine/engine_iface.h), so that it runs through the
 * one run loop (src/engine/run_loop.h: stop rules, progress, periodic, final and
 * signalled checkpoints). Its points are n x 3: the table's 2-D point
 * writers (put_points, put_text, copy) are NULL, and its files are
 * points3.h's; its checkpoints are engine3_ckpt.c's format (n x 3). */
#ifndef CFPO_ENGINE3_OPS_H
#define CFPO_ENGINE3_OPS_H

#include "engine3.h"
#include "engine_iface.h"

/* R runs e (not owned: R->ops->free frees it); R->o: max_iter, stop rules,
 * progress and user from o; t_born the caller's clock at creation. */
void cfpo3_as_run(cfpo3_engine *e, const cfpo_options *o, double t_born, cfpo_run_engine *R);

#endif
