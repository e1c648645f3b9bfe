/* sched3.c - see sched3.h.
 *
 * The schedule's block in a checkpoint, little-endian:
 *    0  magic "CFPO3SCH"   8 bytes
 *    8  round              u32   0..rounds
 *   12  rounds K           u32   0..CFPO3_SCHED_ROUNDS_MAX
 *   16  amp A              f64   in (0, 1]
 *   24  flat W             u32   0..CFPO_FLAT_MAXW
 *   28  best round         u32   0..round
 *   32  flat gain G        f64   in (0, 1]
 *   40  iterations before  u64   the rounds before this one, 0..1e9
 *   48  best delta_min     f64   (round > 0: the best set's)
 *   56  best delta_avg     f64
 *   64  flat count         u32   iterations pushed into the window, 0..1e9
 *   68  ended              u32   0: the round goes on, 1: it converged, 2: the flatness rule held
 *   72  near               u32   0 or 1: the rounds start in the near phase (the
 *                                option; the header's flag is the round's phase)
 *   76  reserved           u32   0
 *   80  seed               u64   the run's (round r > 0 runs its engine under
 *                                cfpo3_sched_round_seed(seed, r))
 *   88  the window: W + 1 delta_min then W + 1 delta_avg (f64; none when W = 0)
 *   then, when round > 0, the best set: n points of 24 bytes in [0,1). */
#include "sched3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bytes_le.h"
#include "comm.h"
#include "rng.h"
#include "engine3_ops.h"
#include "run_loop.h"
#include "runsignal.h"
#include "shake3.h"
#include "stopflat.h"

#define MAGIC "CFPO3SCH"
#define FIXED 88
#define COUNT_MAX 1000000000ULL
#define ROUND_STREAM 0x524f554e44330000ULL /* "ROUND3" */

uint64_t cfpo3_sched_round_seed(uint64_t seed, int round)
{
    return round == 0 ? seed : cfpo_rand64(seed, ROUND_STREAM, (uint64_t)round);
}

void cfpo3_sched_default(cfpo3_sched_opts *so)
{
    so->rounds = CFPO3_SCHED_ROUNDS;
    so->amp = CFPO3_SCHED_AMP;
    so->flat = CFPO3_SCHED_FLAT;
    so->flat_gain = CFPO3_SCHED_GAIN;
}

typedef struct {
    cfpo3_sched_opts so;
    int64_t n;
    int round, iters_before, best_round;
    double best_min, best_avg;
    double *best; /* 3n, every rank, once round 0 ended (K > 0) */
    cfpo_flat_rule flat;
    int ended;      /* 0, 1 converged, 2 flat (this round) */
    int near;       /* the near-phase option of every round's start */
    uint64_t seed;  /* the run's (round 0's engine's) */
    int started;    /* the run loop's first call (the set before any iteration) came */
    int skip_first; /* a resumed round: its window holds the current set already */
    int caller;     /* on_iter asked to stop */
    cfpo3_sched_iter_fn on_iter;
    void *user;
} sched;


static size_t block_len(int flat, int round, int64_t n)
{
    return FIXED + (flat > 0 ? 16 * ((size_t)flat + 1) : 0) + (round > 0 ? 24 * (size_t)n : 0);
}

/* The block (rank 0 builds it; the others give none: rank 0 writes). */
static int tail(void *user, unsigned char **buf, size_t *len)
{
    const sched *S = user;
    *buf = NULL;
    *len = 0;
    if (comm_rank() != 0) return 0;
    const size_t L = block_len(S->so.flat, S->round, S->n);
    unsigned char *b = calloc(L, 1);
    if (!b) return -1;
    memcpy(b, MAGIC, 8);
    le_put32(b + 8, (uint32_t)S->round);
    le_put32(b + 12, (uint32_t)S->so.rounds);
    le_putd(b + 16, S->so.amp);
    le_put32(b + 24, (uint32_t)S->so.flat);
    le_put32(b + 28, (uint32_t)S->best_round);
    le_putd(b + 32, S->so.flat_gain);
    le_put64(b + 40, (uint64_t)S->iters_before);
    le_putd(b + 48, S->best_min);
    le_putd(b + 56, S->best_avg);
    le_put32(b + 64, (uint32_t)S->flat.count);
    le_put32(b + 68, (uint32_t)S->ended);
    le_put32(b + 72, (uint32_t)S->near);
    le_put64(b + 80, S->seed);
    size_t at = FIXED;
    if (S->so.flat > 0) {
        const size_t w1 = (size_t)S->so.flat + 1;
        memcpy(b + at, S->flat.dmin, 8 * w1);
        memcpy(b + at + 8 * w1, S->flat.davg, 8 * w1);
        at += 16 * w1;
    }
    if (S->round > 0) memcpy(b + at, S->best, 24 * (size_t)S->n);
    *buf = b;
    *len = L;
    return 0;
}

int cfpo3_sched_block_check(const unsigned char *b, size_t len, int64_t n, char *err, size_t errlen)
{
    const char *why = NULL;
    if (len < FIXED || memcmp(b, MAGIC, 8) != 0) {
        why = "no schedule block";
    } else {
        const uint32_t round = le_get32(b + 8), rounds = le_get32(b + 12), flat = le_get32(b + 24), br = le_get32(b + 28);
        const uint32_t count = le_get32(b + 64), ended = le_get32(b + 68);
        const double amp = le_getd(b + 16), gain = le_getd(b + 32);
        if (rounds > CFPO3_SCHED_ROUNDS_MAX || round > rounds || br > round || !(amp > 0 && amp <= 1) ||
            flat > CFPO_FLAT_MAXW || !(gain > 0 && gain <= 1) || le_get64(b + 40) > COUNT_MAX || count > COUNT_MAX ||
            ended > 2 || (rounds == 0 && flat == 0) || le_get32(b + 72) > 1 || le_get32(b + 76) != 0)
            why = "a schedule field out of range";
        else if (!isfinite(le_getd(b + 48)) || !isfinite(le_getd(b + 56)))
            why = "a schedule field out of range";
        else if (len != block_len((int)flat, (int)round, n))
            why = "the schedule block's size does not match";
        else {
            const unsigned char *p = b + FIXED;
            for (size_t i = 0; i < (flat > 0 ? 2 * ((size_t)flat + 1) : 0) && !why; i++)
                if (!isfinite(le_getd(p + 8 * i))) why = "a schedule field out of range";
            p += flat > 0 ? 16 * ((size_t)flat + 1) : 0;
            for (size_t i = 0; round > 0 && i < 3 * (size_t)n && !why; i++) {
                const double x = le_getd(p + 8 * i);
                if (!(x >= 0.0 && x < 1.0)) why = "a best-set coordinate outside [0,1)";
            }
        }
    }
    if (why) snprintf(err, errlen, "%s", why);
    return why ? -1 : 0;
}

/* S from a checkpoint's block. 0, or -1 with err. */
static int load(sched *S, const unsigned char *b, size_t len, char *err, size_t errlen)
{
    if (cfpo3_sched_block_check(b, len, S->n, err, errlen) != 0) return -1;
    S->round = (int)le_get32(b + 8);
    S->so.rounds = (int)le_get32(b + 12);
    S->so.amp = le_getd(b + 16);
    S->so.flat = (int)le_get32(b + 24);
    S->best_round = (int)le_get32(b + 28);
    S->so.flat_gain = le_getd(b + 32);
    S->iters_before = (int)le_get64(b + 40);
    S->best_min = le_getd(b + 48);
    S->best_avg = le_getd(b + 56);
    S->ended = (int)le_get32(b + 68);
    S->near = (int)le_get32(b + 72);
    S->seed = le_get64(b + 80);
    if (cfpo_flat_init(&S->flat, S->so.flat, S->so.flat_gain) != 0) goto oom;
    S->flat.count = (int)le_get32(b + 64);
    size_t at = FIXED;
    if (S->so.flat > 0) {
        const size_t w1 = (size_t)S->so.flat + 1;
        memcpy(S->flat.dmin, b + at, 8 * w1);
        memcpy(S->flat.davg, b + at + 8 * w1, 8 * w1);
        at += 16 * w1;
    }
    if (S->round > 0) {
        S->best = malloc(24 * (size_t)S->n);
        if (!S->best) goto oom;
        memcpy(S->best, b + at, 24 * (size_t)S->n);
    }
    return 0;
oom:
    snprintf(err, errlen, "out of memory");
    return -1;
}

/* The run loop's callback: the flatness window, then the caller's line. */
static int on_progress(const cfpo_iter_stats *st, void *user)
{
    sched *S = user;
    const int first = !S->started;
    if (S->on_iter && S->on_iter(st, S->round, first, S->user)) S->caller = 1;
    if (first) { /* the set before the first iteration: the window's first value */
        S->started = 1;
        if (!S->skip_first) cfpo_flat_push(&S->flat, st->delta_min, st->delta_avg);
        return S->caller;
    }
    const int hit = cfpo_flat_push(&S->flat, st->delta_min, st->delta_avg);
    S->ended = st->converged ? 1 : hit ? 2 : 0;
    return hit || S->caller;
}

static int fail(sched *S, cfpo3_sched_result *r, char *err, size_t errlen, const char *msg)
{
    if (msg) snprintf(err, errlen, "%s", msg);
    if (r->e) cfpo3_set_checkpoint_tail(r->e, NULL, NULL); /* (S dies here) */
    cfpo_flat_free(&S->flat);
    free(S->best);
    return -1;
}

int cfpo3_sched_run(cfpo3_engine *e, const cfpo3_sched_args *a, cfpo3_sched_result *r, char *err,
                    size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->e = e;
    sched S;
    memset(&S, 0, sizeof S);
    S.n = cfpo3_n(e);
    S.on_iter = a->on_iter;
    S.user = a->user;
    size_t tl;
    const unsigned char *tb = cfpo3_checkpoint_tail(e, &tl);
    if (tb) {
        char why[200];
        if (load(&S, tb, tl, why, sizeof why) != 0) {
            snprintf(err, errlen, "the checkpoint's schedule: %s", why);
            return fail(&S, r, err, errlen, NULL);
        }
        S.skip_first = 1;
    } else {
        S.so = a->so;
        S.near = cfpo3_options_of(e)->near; /* a fresh engine's option */
        S.seed = cfpo3_options_of(e)->seed;
        if (cfpo_flat_init(&S.flat, S.so.flat, S.so.flat_gain) != 0) return fail(&S, r, err, errlen, "out of memory");
    }
    const int active = S.so.rounds > 0 || S.so.flat > 0; /* else the plain run: no block */
    const int64_t n = S.n;
    int stop, conv;
    for (;;) {
        if (active) cfpo3_set_checkpoint_tail(e, tail, &S);
        conv = 0;
        if (S.skip_first && S.ended) { /* resumed at the end of a round */
            stop = S.ended == 1 ? CFPO_STOP_CONVERGED : CFPO_STOP_FLAT;
        } else {
            cfpo_options lo;
            memset(&lo, 0, sizeof lo);
            lo.max_iter = a->max_iter - S.iters_before > 0 ? a->max_iter - S.iters_before : 0;
            lo.stop = a->stop;
            lo.progress = on_progress;
            lo.user = &S;
            cfpo_run_engine R;
            cfpo_result res;
            cfpo3_as_run(e, &lo, a->t0, &R);
            if (a->ckpt) runsignal_install(); /* SIGTERM / SIGUSR1: a checkpoint, then exit 3 */
            const int rc = cfpo_run_loop(&R, a->ckpt, a->ckpt ? a->every : 0, &res, err, errlen);
            runsignal_restore();
            if (rc != 0) return fail(&S, r, err, errlen, NULL);
            stop = res.stop == CFPO_STOP_CALLER && !S.caller ? CFPO_STOP_FLAT : res.stop;
            conv = res.converged;
        }
        S.skip_first = 0;
        S.started = 0;
        const int it = cfpo3_iterations(e);
        r->stop = stop;
        if (stop == CFPO_STOP_SIGNAL) { /* the summary's figures: where the round stood */
            r->signal_iter = it;
            S.iters_before += it;
            cfpo3_measure(e, &S.best_min, &S.best_avg);
            break;
        }
        double dmin, davg;
        cfpo3_measure(e, &dmin, &davg);
        if (S.so.rounds == 0) {
            S.best_min = dmin, S.best_avg = davg;
        } else if (S.round == 0 || dmin > S.best_min || (dmin == S.best_min && davg > S.best_avg)) {
            if (!S.best) S.best = malloc(24 * (size_t)n);
            if (comm_all(S.best != NULL) == 0) return fail(&S, r, err, errlen, "out of memory for the best set");
            if (comm_size() > 1) {
                if (cfpo3_gather(e, S.best) != 0) return fail(&S, r, err, errlen, "out of memory gathering the best set");
            } else {
                memcpy(S.best, cfpo3_points(e), 24 * (size_t)n);
            }
            S.best_min = dmin, S.best_avg = davg, S.best_round = S.round;
        }
        S.iters_before += it;
        const int round_end = stop == CFPO_STOP_CONVERGED || stop == CFPO_STOP_FLAT;
        if (!round_end || S.round == S.so.rounds) {
            r->converged = S.round == S.so.rounds && (round_end || conv);
            break;
        }
        /* the next round: the best set shaken, in a fresh engine (the old
         * one freed first, so that one engine is held at a time) */
        cfpo3_options o = *cfpo3_options_of(e); /* (near: a resumed engine's is its phase) */
        o.near = S.near;
        o.seed = cfpo3_sched_round_seed(S.seed, S.round + 1); /* its own grid shifts and colour orders */
        double *buf = malloc(24 * (size_t)n);
        if (comm_all(buf != NULL) == 0) {
            free(buf);
            return fail(&S, r, err, errlen, "out of memory for the shake");
        }
        memcpy(buf, S.best, 24 * (size_t)n);
        cfpo3_shake(buf, n, S.seed, S.round + 1, S.so.amp);
        cfpo3_free(e);
        r->e = NULL;
        char why[400];
        e = cfpo3_create_given(buf, n, &o, why, sizeof why);
        free(buf);
        const int mine = e != NULL;
        if (comm_all(mine) == 0) {
            cfpo3_free(e);
            snprintf(err, errlen, "the shaken set of round %d: %s", S.round + 1, mine ? "failed on another rank" : why);
            return fail(&S, r, err, errlen, NULL);
        }
        r->e = e;
        S.round++;
        S.flat.count = 0;
        S.ended = 0;
    }
    cfpo3_set_checkpoint_tail(e, NULL, NULL);
    cfpo_flat_free(&S.flat);
    r->best = S.best;
    r->dmin = S.best_min;
    r->davg = S.best_avg;
    r->iterations = S.iters_before;
    r->rounds_done = S.round;
    r->best_round = S.best_round;
    r->so = S.so;
    r->seed = S.seed;
    return 0;
}
