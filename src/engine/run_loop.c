/* run_loop.c - see run_loop.h. */
#include "run_loop.h"

#include <stdio.h>

#include "omp_compat.h"
#include "runsignal.h"
#include "stoprule.h"

/* Stop rule and progress callback after statistics s (elapsed: seconds
 * since the engine's creation began, the largest over ranks, so every
 * rank stops at the same iteration). */
static int decide(const cfpo_run_engine *R, const cfpo_iter_stats *s, double elapsed)
{
    int why = cfpo_stop_check(&R->o.stop, s, elapsed, R->o.max_iter);
    if (R->o.progress && R->o.progress(s, R->o.user) && !why) why = CFPO_STOP_CALLER;
    return why;
}

/* A signal reached some rank of the job (the same answer on every rank,
 * also while each works alone: mpirun may deliver it to one rank an
 * iteration before another, and a rank that stopped alone would leave
 * the others waiting for it at the next exchange). */
static int signalled(void)
{
    int64_t v = runsignal_caught() != 0;
    comm_world_max_i64(&v, 1);
    return v != 0;
}

/* While the ranks work alone, the stop agreed across the job (the
 * largest reason): each rank runs the same iterations to the same bytes,
 * but a rule reading the clock could end them at different iterations,
 * and the signal check above must be met as often on every rank. */
static int agreed(int why)
{
    if (!comm_solo()) return why; /* the rules read reduced statistics and clock already */
    int64_t v = why;
    comm_world_max_i64(&v, 1);
    return (int)v;
}

int cfpo_run_loop(cfpo_run_engine *R, const char *checkpoint, int every, cfpo_result *res, char *err,
                  size_t errlen)
{
    const double t0 = omp_get_wtime();
    cfpo_iter_stats s = {0};
    if (R->ops->now(R->E, &s, err, errlen) != 0) return -1;
    s.seconds = omp_get_wtime() - t0;
    double elapsed = omp_get_wtime() - R->t_born;
    comm_max_d(&elapsed, 1);
    int why = agreed(decide(R, &s, elapsed));
    int rc = 0;
    while (!why) {
        if (checkpoint && signalled()) { /* a checkpoint of where the run stands, then stop */
            why = CFPO_STOP_SIGNAL;
            if (R->ops->checkpoint(R->E, checkpoint, s.iteration, s.converged, err, errlen) != 0) rc = -1;
            break;
        }
        if (R->ops->step(R->E, &s, err, errlen) != 0) return -1;
        elapsed += s.seconds;
        why = agreed(decide(R, &s, elapsed));
        /* every `every` iterations, and where the run stops (to go on from
         * with --resume and other limits) */
        if (checkpoint && every > 0 && (s.iteration % every == 0 || why) &&
            R->ops->checkpoint(R->E, checkpoint, s.iteration, s.converged, err, errlen) != 0) {
            rc = -1;
            break;
        }
    }
    if (rc == 0 && s.stale) { /* a lazy measure (cfpo_options.lazy_measure): the set where it stopped */
        cfpo_iter_stats m;
        if (R->ops->now(R->E, &m, err, errlen) != 0) return -1;
        s.delta_min = m.delta_min;
        s.delta_avg = m.delta_avg;
        s.stale = 0;
    }
    *res = (cfpo_result){.iterations = s.iteration, .converged = s.converged, .stop = why,
                         .seconds = omp_get_wtime() - t0, .delta_min = s.delta_min, .delta_avg = s.delta_avg,
                         .cells_per_side = R->ops->cells_per_side(R->E)};
    return rc;
}
