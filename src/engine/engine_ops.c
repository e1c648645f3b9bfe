/* engine_ops.c - the uniform engine's table of the one interface
 * (engine_iface.h), and its run through the one loop (run_loop.h).
 * One rank: a failure mid-iteration (eng_fatal, out of memory) jumps back
 * to the step here, which returns -1 with its message, so a library
 * caller (the Python module) never sees exit(). Several ranks: every rank
 * must stop, so it aborts (cells.c). */
#include "cells.h"

#include <stdio.h>
#include <string.h>

#include "run_loop.h"

static int step(void *p, cfpo_iter_stats *s, char *err, size_t errlen)
{
    cfpo_engine *E = p;
    if (E->nranks == 1) {
        jmp_buf back;
        if (setjmp(back) != 0) {
            E->fail = NULL;
            snprintf(err, errlen, "%s", E->fail_msg);
            return -1;
        }
        E->fail = &back;
        cfpo_engine_iterate(E, s);
        E->fail = NULL;
    } else {
        cfpo_engine_iterate(E, s);
    }
    s->iteration = ++E->iter0;
    return 0;
}

static int now_stats(void *p, cfpo_iter_stats *s, char *err, size_t errlen)
{
    (void)err;
    (void)errlen;
    cfpo_engine *E = p;
    memset(s, 0, sizeof *s);
    s->iteration = E->iter0;
    s->converged = E->resumed_converged;
    cfpo_engine_deltas(E, &s->delta_min, &s->delta_avg);
    return 0;
}

static int put_points(void *E, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    return cfpo_engine_write_points(E, f, base, err, errlen);
}

static int put_text(void *E, pf_writer *w, char *err, size_t errlen)
{
    return cfpo_engine_write(E, w, err, errlen);
}

static int checkpoint(void *p, const char *path, int iteration, int converged, char *err, size_t errlen)
{
    cfpo_engine *E = p;
    const char *was = E->cfg.checkpoint;
    E->cfg.checkpoint = path;
    const int rc = eng_write_checkpoint(E, iteration, converged, err, errlen);
    E->cfg.checkpoint = was;
    return rc;
}

static void copy(void *E, double *xy) { cfpo_engine_points(E, xy); }
static void timing(void *E, cfpo_engine_timing *t) { cfpo_engine_timing_get(E, t); }
static int64_t cells_per_side(const void *E) { return cfpo_engine_grid(E)->g; }
static void release(void *E) { cfpo_engine_free(E); }

static const cfpo_engine_ops ops = {"uniform", step, now_stats, put_points, put_text, copy, checkpoint, timing,
                                    cells_per_side, release};

void cfpo_engine_as_run(cfpo_engine *E, cfpo_run_engine *R)
{
    *R = (cfpo_run_engine){.ops = &ops, .E = E, .n = E->n, .o = E->o, .t_born = E->t_born};
}

int cfpo_engine_run(cfpo_engine *E, cfpo_result *res, char *err, size_t errlen)
{
    cfpo_run_engine R;
    cfpo_engine_as_run(E, &R);
    return cfpo_run_loop(&R, E->cfg.checkpoint, E->cfg.checkpoint_every, res, err, errlen);
}
