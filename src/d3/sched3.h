/* sched3.h - the 3-D command's schedule of runs (docs/method.md, "Three
 * dimensions", "The default schedule").
 *
 * Owns: rounds of the one run loop (run_loop.h) over the 3-D engine:
 * round 0 from the start set, then K rounds, each from the best set so far
 * (the larger delta_min, then delta_avg) shaken by up to A Delta3 a
 * coordinate (shake3.h) in a fresh engine seeded for the round (so its
 * grid shifts and colour orders are not round 0's again). A round ends when the engine
 * converges or the flatness rule holds (stopflat.h, window W, gain G,
 * over that round's iterations); the user's rules (targets, time limit,
 * the iteration cap over all rounds, a signal) end the whole schedule.
 * The best set is the result. And the schedule's block in a checkpoint
 * (engine3.h's caller's block): the round, the iterations of the rounds
 * before, the flatness window, whether the round had ended, and the best
 * set, so that --resume continues with the bytes of an uninterrupted run
 * on any rank count. K = 0 and W = 0 is the plain run (no block).
 * May include: engine3.h, the run loop and the common rules. */
#ifndef CFPO_SCHED3_H
#define CFPO_SCHED3_H

#include <stdio.h>

#include "engine3.h"
#include "stoprule.h"

/* The default of the 3-D command: 3 shakes of 0.15 Delta3, rounds ended
 * by a flat window of 20 iterations under a gain of 1e-5. */
#define CFPO3_SCHED_ROUNDS 3
#define CFPO3_SCHED_AMP 0.15
#define CFPO3_SCHED_FLAT 20
#define CFPO3_SCHED_GAIN 1e-5
#define CFPO3_SCHED_ROUNDS_MAX 1000

typedef struct {
    int rounds;       /* K: shaken rounds after round 0 (0..CFPO3_SCHED_ROUNDS_MAX) */
    double amp;       /* A, in (0, 1] */
    int flat;         /* W: 0 (off) .. CFPO_FLAT_MAXW */
    double flat_gain; /* G, in (0, 1] */
} cfpo3_sched_opts;

void cfpo3_sched_default(cfpo3_sched_opts *so);

/* Called as the run loop's progress callback is (once before a round's
 * first iteration, first = 1, then after every iteration): the progress
 * line and the trace. Nonzero: stop the whole schedule (CFPO_STOP_CALLER). */
typedef int (*cfpo3_sched_iter_fn)(const cfpo_iter_stats *st, int round, int first, void *user);

typedef struct {
    cfpo3_sched_opts so; /* ignored on resume (the block's) */
    int max_iter;        /* over all rounds */
    cfpo_stop_rules stop;
    double t0;           /* the command's clock at its start (the time limit's) */
    const char *ckpt;    /* NULL: no checkpoints */
    int every;
    cfpo3_sched_iter_fn on_iter;
    void *user;
} cfpo3_sched_args;

typedef struct {
    cfpo3_engine *e;   /* the last round's engine (the caller frees it) */
    double *best;      /* K > 0: the best set, 3n by id, on every rank (the caller frees it); else NULL: e's set */
    double dmin, davg; /* the result's */
    int stop;          /* CFPO_STOP_*: the last round's (converged, flat) or what ended the schedule
                          (target, time, max-iter, signal, caller: on_iter asked) */
    int converged;     /* 1: every round ran and ended by convergence or the flatness rule */
    int iterations;    /* over all rounds */
    int rounds_done, best_round;
    int signal_iter;   /* stop == CFPO_STOP_SIGNAL: the round's iteration */
    cfpo3_sched_opts so; /* what ran (the block's on resume) */
    uint64_t seed;       /* the run's seed (round 0's) */
} cfpo3_sched_result;

/* Collective. Runs the schedule from e (owned from here on; fresh, or read
 * from a checkpoint whose block, if any, says where the schedule stood).
 * 0, or -1 with one line in err on every rank (a step, a checkpoint, a
 * bad block, memory); on -1 r->e is still the caller's to free. */
int cfpo3_sched_run(cfpo3_engine *e, const cfpo3_sched_args *a, cfpo3_sched_result *r, char *err,
                    size_t errlen);

/* The seed of round r's engine: the run's seed for round 0, a hash of it
 * and r after. */
uint64_t cfpo3_sched_round_seed(uint64_t seed, int round);

/* The schedule's block of a checkpoint checked on its own (tests,
 * fuzzing): 0, or -1 with why in err. n: the checkpoint's points. */
int cfpo3_sched_block_check(const unsigned char *b, size_t len, int64_t n, char *err, size_t errlen);

#endif
