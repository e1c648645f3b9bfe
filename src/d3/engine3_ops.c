/* engine3_ops.c - see engine3_ops.h. */
#include "engine3_ops.h"

#include <stdio.h>
#include <string.h>

static int step(void *E, cfpo_iter_stats *s, char *err, size_t errlen)
{
    if (cfpo3_step(E, s) == 0) return 0;
    snprintf(err, errlen, "out of memory mid-run");
    return -1;
}

static int now_stats(void *E, cfpo_iter_stats *s, char *err, size_t errlen)
{
    (void)err;
    (void)errlen;
    memset(s, 0, sizeof *s);
    s->iteration = cfpo3_iterations(E);
    cfpo3_measure(E, &s->delta_min, &s->delta_avg);
    return 0;
}

static int checkpoint(void *E, const char *path, int iteration, int converged, char *err, size_t errlen)
{
    (void)iteration; /* the engine's own count */
    (void)converged;
    return cfpo3_checkpoint_write(E, path, err, errlen);
}

/* min, mean, max of v over ranks into out[3] */
static void spread(double v, double out[3])
{
    out[0] = out[1] = out[2] = v;
    comm_min_d(out, 1);
    comm_sum_d(out + 1, 1);
    comm_max_d(out + 2, 1);
    out[1] /= comm_size();
}

static void timing(void *E, cfpo_engine_timing *t)
{
    double v[5];
    int b[3];
    memset(t, 0, sizeof *t);
    cfpo3_rank_timers(E, v, &t->phases, b);
    spread(v[0], t->compute);
    spread(v[1], t->halo);
    spread(v[2], t->migrate);
    spread(v[3], t->halo_bytes);
    spread(v[4], t->migrate_bytes);
}

static int64_t cells_per_side(const void *E) { return cfpo3_grid_of(E)->g; }
static void release(void *E) { cfpo3_free(E); }

static const cfpo_engine_ops ops = {"3-d", step, now_stats, NULL, NULL, NULL, checkpoint, timing, cells_per_side,
                                    release};

void cfpo3_as_run(cfpo3_engine *e, const cfpo_options *o, double t_born, cfpo_run_engine *R)
{
    *R = (cfpo_run_engine){.ops = &ops, .E = e, .n = cfpo3_n(e), .o = *o, .t_born = t_born};
}
