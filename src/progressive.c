/* progressive.c - see progressive.h. */
#include "progressive.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "grid.h"
#include "tiles.h"
#include "omp_compat.h"
#include "prog_colour.h"
#include "prog_balance.h"
#include "prog_insert.h"
#include "prog_order.h"
#include "prog_herd.h"
#include "prog_measure.h"
#include "rng.h"
#include "run_loop.h"
#include "stoprule.h"

#define PROG_SALT 0x9e3779b97f4a7c15ULL /* level seeds: seed ^ mix(level + salt) */
#define BALANCE_SALT 0x42414c414e4345ULL /* ... ^ mix(balance tag + this) with the balance on */
#define BALANCE_TAG_MAX 1000000          /* the largest leaf size a resume's message looks for */
/* The tag of the default with the balance on (the paced order, the small
 * levels herded) has HERD_TAG too. Earlier versions' defaults, whose
 * checkpoints are refused (their earlier levels are in an order this
 * version no longer makes): 2 C alone, the greedy order, and 2 C +
 * PACED_TAG, the paced order in every level */
#define PACED_TAG (1ULL << 40)
#define HERD_TAG (1ULL << 41)
#define OLD_TAG(t) (!((t) & 1) && !((t) & HERD_TAG)) /* an earlier version's default */

int cfpo_prog_balance_of(const cfpo_prog_options *p)
{
    if (p->classes > 0 || p->balance < 0) return 0;
    return p->balance > 0 ? p->balance : CFPO_PROG_DEFAULT_BALANCE;
}

/* The level seed for a balance tag (0: off; else 2 C + order). */
static uint64_t level_seed_tag(uint64_t seed, int k, uint64_t tag)
{
    if (k == 0) return seed;
    const uint64_t s = seed ^ cfpo_mix64((uint64_t)k + PROG_SALT);
    return tag ? s ^ cfpo_mix64(tag + BALANCE_SALT) : s;
}

static uint64_t balance_tag(const cfpo_prog_options *p)
{
    const int C = cfpo_prog_balance_of(p);
    return C > 0 ? 2 * (uint64_t)C + (p->balance_order ? 1 : HERD_TAG) : 0;
}

uint64_t cfpo_prog_level_seed(uint64_t seed, int k, const cfpo_prog_options *p)
{
    return level_seed_tag(seed, k, balance_tag(p));
}

int cfpo_prog_sizes(int64_t n, int variant, const cfpo_prog_options *p, int64_t *sizes, char *err, size_t errlen)
{
    const int64_t nmin = cfpo_grid_min_n(variant);
    if (p->classes > 0) {
        const int64_t K = p->classes;
        if (K > CFPO_PROG_MAX_LEVELS || K > n || n / K < nmin) {
            snprintf(err, errlen, "--classes %lld: each class needs at least %lld points (n / K) and K at most %d; "
                     "n = %lld", (long long)K, (long long)nmin, CFPO_PROG_MAX_LEVELS, (long long)n);
            return -1;
        }
        for (int64_t c = 0; c < K; c++) sizes[c] = (c + 1) * n / K;
        return (int)K;
    }
    const int64_t base = p->base > 0 ? p->base : CFPO_PROG_DEFAULT_BASE;
    if (base > n) {
        snprintf(err, errlen, "--base %lld is larger than n = %lld", (long long)base, (long long)n);
        return -1;
    }
    if (base < nmin) {
        snprintf(err, errlen, "--base %lld is too small: the grid needs at least %lld points", (long long)base,
                 (long long)nmin);
        return -1;
    }
    int k = 0;
    for (int64_t m = base; k < CFPO_PROG_MAX_LEVELS; m *= 2) {
        sizes[k++] = m < n ? m : n;
        if (m >= n) break;
    }
    return k;
}

void cfpo_prog_worst(const cfpo_prog_level *levels, int k, int *by_min, int *by_avg)
{
    *by_min = *by_avg = 0;
    for (int i = 1; i < k; i++) {
        if (levels[i].delta_min < levels[*by_min].delta_min) *by_min = i;
        if (levels[i].delta_avg < levels[*by_avg].delta_avg) *by_avg = i;
    }
}

/* The engine's m points into xy in id order, on every rank: under
 * several ranks each holds its own points only, so the others' slots are
 * filled with -inf and the ranks' copies merged by a maximum (each slot
 * is one rank's point, so the merge gives its bits). The levels' insertions,
 * orderings and joint moves then run on the whole prefix on every rank,
 * the same on each. */
static void all_points(const cfpo_engine *E, int64_t m, double *xy)
{
    if (comm_size() > 1)
        for (size_t i = 0; i < 2 * (size_t)m; i++) xy[i] = -INFINITY;
    cfpo_engine_points(E, xy);
    if (comm_size() > 1) comm_max_d(xy, (int)(2 * m));
}

/* Under several ranks, whether a set of m points is too small to cut
 * across them (a tile under CFPO_TILE_MIN cells a side): then every rank
 * works on it alone, the same way (comm_solo_begin), and the ranks hold
 * the same points after it. The full set is cut as a plain run's is. */
static int alone(int64_t m, const cfpo_options *o)
{
    if (comm_size() == 1) return 0;
    cfpo_grid G;
    cfpo_tiling T;
    char e[256];
    return cfpo_grid_init(&G, m, o->variant, o->seed, e, sizeof e) == 0 &&
           cfpo_tiling_init(&T, G.g, comm_size(), 0, 0, e, sizeof e) != 0;
}

/* One level: m points, the first `fixed` held, from xy (NULL: the
 * variant's own start); its engine into R, its run into res and L. */
static int run_level(int64_t m, int64_t fixed, const double *xy, const cfpo_options *lo, const cfpo_prog_options *p,
                     const char *resume, cfpo_run_engine *R, cfpo_result *res, cfpo_prog_level *L, char *err,
                     size_t errlen)
{
    cfpo_engine_config cfg = {0};
    cfg.start_xy = xy;
    cfg.fixed = fixed;
    cfg.resume = resume;
    const double t0 = omp_get_wtime();
    if (alone(m, lo)) comm_solo_begin(); /* comm_solo_end: nothing when it did not begin */
    cfpo_engine *E = cfpo_engine_create_ex(m, lo, &cfg, err, errlen);
    if (!E) {
        comm_solo_end();
        return -1;
    }
    cfpo_engine_as_run(E, R);
    R->t_born = t0;
    double d0, a0;
    cfpo_engine_deltas(E, &d0, &a0);
    const int rc = cfpo_run_loop(R, p->checkpoint, p->checkpoint ? p->checkpoint_every : 0, res, err, errlen);
    comm_solo_end(); /* alone, E holds all m points on every rank: all_points takes them as they are */
    if (rc != 0) {
        cfpo_engine_free(E);
        return -1;
    }
    *L = (cfpo_prog_level){.m = m, .iterations = res->iterations, .stop = res->stop, .delta_min0 = d0,
                           .delta_min = res->delta_min, .delta_avg = res->delta_avg,
                           .seconds = omp_get_wtime() - t0};
    return 0;
}

/* The prefixes' measures once later levels moved their points: each
 * prefix as a set of its own (an engine that only measures). */
static int remeasure(const double *xy, int K, const cfpo_options *o, cfpo_prog_level *levels, char *err,
                     size_t errlen)
{
    for (int k = 0; k < K - 1; k++) {
        cfpo_engine_config cfg = {0};
        cfg.start_xy = xy;
        if (alone(levels[k].m, o)) comm_solo_begin();
        cfpo_engine *E = cfpo_engine_create_ex(levels[k].m, o, &cfg, err, errlen);
        if (E) cfpo_engine_deltas(E, &levels[k].delta_min, &levels[k].delta_avg);
        comm_solo_end();
        if (!E) return -1;
        cfpo_engine_free(E);
    }
    return 0;
}

/* The balance setting of a tag, in the command's words. */
static void tag_words(uint64_t tag, char *s, size_t len)
{
    const unsigned long long C = (unsigned long long)((tag & ~(PACED_TAG | HERD_TAG)) / 2);
    if (!tag) snprintf(s, len, "--level-balance 0");
    else if (tag & HERD_TAG) snprintf(s, len, "--level-balance %llu", C);
    else if (tag & 1) snprintf(s, len, "--level-balance %llu --level-balance-order", C);
    else snprintf(s, len, "--level-balance %llu by an earlier version, whose %s order of the levels this one no "
                  "longer makes", C, tag & PACED_TAG ? "paced" : "greedy");
}

/* A checkpoint of level k >= 1 whose seed is level k's under another
 * balance setting: -1 with one line naming both settings; 0 otherwise
 * (its seed is this run's, or another run's: the engine refuses that). */
static int check_balance(const char *path, uint64_t ck_seed, uint64_t seed, int k, const cfpo_prog_options *p,
                         char *err, size_t errlen)
{
    const uint64_t want = balance_tag(p);
    if (k == 0 || ck_seed == level_seed_tag(seed, k, want)) return 0;
    for (uint64_t t = 0; t <= 2 * (uint64_t)BALANCE_TAG_MAX + 1; t = t ? t + 1 : 2)
        for (int v = 0; v < (t & 1 ? 1 : 3) && t; v++) { /* even t: the greedy, paced and herded defaults */
            const uint64_t tag = t + (v == 1 ? PACED_TAG : v == 2 ? HERD_TAG : 0);
            if (tag == want || ck_seed != level_seed_tag(seed, k, tag)) continue;
            char had[128], now[128];
            tag_words(tag, had, sizeof had);
            tag_words(want, now, sizeof now);
            if (OLD_TAG(tag))
                snprintf(err, errlen, "--resume %s: the checkpoint was written with %s; start the run again", path, had);
            else
                snprintf(err, errlen, "--resume %s: the checkpoint was written with %s, this run has %s; resume with "
                         "the checkpoint's setting", path, had, now);
            return -1;
        }
    if (want && ck_seed == level_seed_tag(seed, k, 0)) {
        char now[128];
        tag_words(want, now, sizeof now);
        snprintf(err, errlen, "--resume %s: the checkpoint was written with --level-balance 0, this run has %s; resume "
                 "with the checkpoint's setting", path, now);
        return -1;
    }
    return 0;
}

/* The level a checkpoint belongs to: the one of its size (and, past level
 * 0, of this run's balance setting: check_balance). */
static int resumed_level(const char *path, const int64_t *sizes, int K, uint64_t seed, const cfpo_prog_options *p,
                         char *err, size_t errlen)
{
    cfpo_checkpoint_info info;
    if (cfpo_checkpoint_peek(path, &info, err, errlen) != 0) return -1;
    for (int k = 0; k < K; k++)
        if (sizes[k] == info.n) return check_balance(path, info.seed, seed, k, p, err, errlen) != 0 ? -1 : k;
    snprintf(err, errlen, "--resume %s: the checkpoint holds %lld points, no level of this run has that size", path,
             (long long)info.n);
    return -1;
}

/* The points of a level's checkpoint (m points, level seed in lo) into
 * xy: the earlier levels' prefixes, to measure them again. */
static int remeasure_points(const char *path, int64_t m, const cfpo_options *lo, double *xy, char *err,
                            size_t errlen)
{
    cfpo_engine_config cfg = {0};
    cfg.resume = path;
    if (alone(m, lo)) comm_solo_begin();
    cfpo_engine *E = cfpo_engine_create_ex(m, lo, &cfg, err, errlen);
    comm_solo_end();
    if (!E) return -1;
    all_points(E, m, xy);
    cfpo_engine_free(E);
    return 0;
}

/* An engine holding the n points of xy as they are (none moves): the
 * run's output. */
static int hold(int64_t n, const double *xy, const cfpo_options *o, cfpo_run_engine *R, char *err, size_t errlen)
{
    cfpo_engine_config cfg = {0};
    cfg.start_xy = xy;
    cfg.fixed = n;
    cfpo_engine *E = cfpo_engine_create_ex(n, o, &cfg, err, errlen);
    if (!E) return -1;
    cfpo_engine_as_run(E, R);
    return 0;
}

/* Level k's points m0 .. m1 - 1 in their prefix order: with the balance
 * on, the greedy order paced by the quadtree (prog_order.h), herded in
 * the levels of at most CFPO_PROG_HERD_MAX points (prog_herd.h), or with
 * balance_order the cells' proportions kept by time (prog_balance.h);
 * with it off, greedy. */
static int order_level(double *xy, int64_t m0, int64_t m1, const cfpo_options *o, const cfpo_prog_options *p, int k,
                       char *err, size_t errlen)
{
    const int C = cfpo_prog_balance_of(p);
    if (C > 0 && p->balance_order) return cfpo_prog_order_balanced(xy, m0, m1, C, o->seed, (uint64_t)k, err, errlen);
    if (C > 0 && m1 <= CFPO_PROG_HERD_MAX)
        return cfpo_prog_order_herded(xy, m0, m1, CFPO_PROG_ORDER_CELL, CFPO_PROG_ORDER_TOL, CFPO_PROG_HERD_FLOOR,
                                      CFPO_PROG_HERD_FREQ, err, errlen);
    if (C > 0) return cfpo_prog_order_paced(xy, m0, m1, CFPO_PROG_ORDER_CELL, CFPO_PROG_ORDER_TOL, err, errlen);
    return cfpo_prog_order(xy, m0, m1, err, errlen);
}

/* The bounded joint move (prog_joint.h) of levels 0 .. k in xy (prefix
 * m_k; its pair weights use the full set's target only at the last level
 * K - 1), each level's points in greedy order again after it (the dyadic
 * prefixes are the same sets), levels 0 .. k measured again as prefixes
 * (and res at the last level). With classes the move's groups are the
 * classes 0 .. k and their union (prog_joint.h). polish: the full set's
 * polish instead (k = K - 1, progressive.h polish). */
static int joint_phase(double *xy, const int64_t *sizes, int k, int K, const cfpo_options *o,
                       const cfpo_prog_options *p, int polish, cfpo_prog_level *levels, cfpo_result *res, char *err,
                       size_t errlen)
{
    cfpo_prog_joint_options jo = p->joint;
    if (k == K - 1 && p->joint_last > 0) jo.sweeps = p->joint_last;
    jo.seed = o->seed ^ cfpo_mix64((uint64_t)k + PROG_SALT + 0x4a4f494e54ULL);
    if (polish) { /* the full set's polish (progressive.h polish) */
        jo.sweeps = p->polish;
        jo.floor = p->polish_floor > 0 ? p->polish_floor : 0.78;
        jo.seed = o->seed ^ cfpo_mix64((uint64_t)k + PROG_SALT + 0x504f4c495348ULL);
        if (p->polish_sweep) jo.sweep_done = p->polish_sweep;
    }
    jo.classes = p->classes > 0;
    jo.threads = o->threads;
    if (k < K - 1 && !jo.classes) jo.target_full = jo.target_prefix;
    double dmin[CFPO_PROG_MAX_LEVELS + 1], davg[CFPO_PROG_MAX_LEVELS + 1];
    const double t0 = omp_get_wtime();
    if (cfpo_prog_joint(xy, sizes, k + 1, &jo, dmin, davg, err, errlen) != 0) return -1;
    for (int j = 0; j <= k; j++)
        if (order_level(xy, j > 0 ? sizes[j - 1] : 0, sizes[j], o, p, j, err, errlen) != 0) return -1;
    if (jo.classes && cfpo_prog_measure(xy, sizes, k + 1, dmin, davg, err, errlen) != 0) return -1;
    for (int j = 0; j <= k; j++) levels[j].delta_min = dmin[j], levels[j].delta_avg = davg[j];
    levels[k].seconds += omp_get_wtime() - t0;
    if (k == K - 1) {
        res->delta_min = dmin[K - 1];
        res->delta_avg = davg[K - 1];
    }
    return 0;
}

/* Classes by colouring (progressive.h classes_levels = 0): a plain CFPO
 * run of n points (the caller's options and stop rules), coloured into
 * the K classes in class order, then the class-aware joint move. */
static int colour_run(int64_t n, const int64_t *sizes, int K, const cfpo_options *o, const cfpo_prog_options *p,
                      cfpo_run_engine *R, cfpo_result *res, cfpo_prog_level *levels, int *nlevels, char *err,
                      size_t errlen)
{
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int c = 0; c < K; c++)
        levels[c] = (cfpo_prog_level){.m = sizes[c], .delta_min0 = NAN, .delta_min = NAN, .delta_avg = NAN};
    *nlevels = K;
    if (p->level_begin) p->level_begin(0, n, p->user);
    cfpo_prog_level run;
    if (run_level(n, 0, NULL, o, p, NULL, R, res, &run, err, errlen) != 0) {
        free(xy);
        return -1;
    }
    levels[0].iterations = run.iterations, levels[0].stop = run.stop, levels[0].seconds = run.seconds;
    levels[0].delta_min0 = run.delta_min0;
    all_points(R->E, R->n, xy);
    R->ops->free(R->E);
    const double t0 = omp_get_wtime();
    cfpo_prog_colour_options co = {.reach = p->colour_reach};
    if (cfpo_prog_colour(xy, sizes, K, &co, err, errlen) != 0) {
        free(xy);
        return -1;
    }
    if (p->colour_out) *p->colour_out = co;
    cfpo_prog_options q = *p;
    if (q.joint.sweeps <= 0 && q.joint_last <= 0) q.joint.sweeps = CFPO_PROG_CLASS_SWEEPS;
    if (q.joint.target_prefix <= 0) q.joint.target_prefix = CFPO_PROG_CLASS_TARGET;
    if (q.joint.target_full <= 0) q.joint.target_full = CFPO_PROG_UNION_TARGET;
    if (q.joint.circum == 0) q.joint.circum = CFPO_PROG_CLASS_CIRCUM;
    if (q.joint.solve == 0) q.joint.solve = CFPO_PROG_CLASS_SOLVE;
    if (q.joint.swaps == 0) q.joint.swaps = CFPO_PROG_CLASS_SWAPS;
    q.joint.floor = p->union_floor > 0 ? p->union_floor : q.joint.target_full;
    if (p->level_begin) p->level_begin(K - 1, n, p->user);
    const double tc = omp_get_wtime() - t0; /* (the colouring; joint_phase adds its own time) */
    int rc = joint_phase(xy, sizes, K - 1, K, o, &q, 0, levels, res, err, errlen);
    levels[K - 1].seconds += tc;
    if (rc == 0) rc = hold(n, xy, o, R, err, errlen);
    free(xy);
    return rc;
}

int cfpo_prog_run(int64_t n, const cfpo_options *o, const cfpo_prog_options *p, cfpo_run_engine *R,
                  cfpo_result *res, cfpo_prog_level *levels, int *nlevels, char *err, size_t errlen)
{
    int64_t sizes[CFPO_PROG_MAX_LEVELS];
    const int K = cfpo_prog_sizes(n, o->variant, p, sizes, err, errlen);
    if (K < 0) return -1;
    if (p->classes > 0 && !p->classes_levels) return colour_run(n, sizes, K, o, p, R, res, levels, nlevels, err, errlen);
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    const int cand = p->candidates > 0 ? p->candidates : 16;
    const int balance = cfpo_prog_balance_of(p);
    const int cap = p->level_iter > 0 ? p->level_iter
                    : p->level_iter < 0 || p->classes > 0 || p->joint.sweeps > 0 || p->joint_last > 0
                        ? 0
                        : CFPO_PROG_DEFAULT_LEVEL_ITER;
    int k0 = 0; /* the level to start at: a resumed checkpoint's */
    if (p->resume && (k0 = resumed_level(p->resume, sizes, K, o->seed, p, err, errlen)) < 0) {
        free(xy);
        return -1;
    }
    for (int k = k0; k < K; k++) {
        const int64_t m = sizes[k], prev = k > 0 ? sizes[k - 1] : 0;
        cfpo_options lo = *o;
        lo.seed = cfpo_prog_level_seed(o->seed, k, p);
        if (cap > 0 && lo.max_iter > cap) lo.max_iter = cap; /* (progressive.h level_iter) */
        if (k < K - 1) { /* the last level keeps the caller's stop rules */
            memset(&lo.stop, 0, sizeof lo.stop);
            lo.stop.target_min = p->level_min;
        }
        if (k > k0 && (balance > 0 ? cfpo_prog_insert_balanced(xy, prev, m, cand, balance, lo.seed, (uint64_t)k, err,
                                                               errlen)
                                   : cfpo_prog_insert(xy, prev, m, cand, lo.seed, (uint64_t)k, err, errlen)) != 0)
            break;
        const char *resume = k == k0 ? p->resume : NULL;
        if (resume && k > 0 && remeasure_points(resume, m, &lo, xy, err, errlen) != 0) break;
        for (int j = 0; resume && j < k; j++) levels[j].m = sizes[j];
        if (resume && k > 0 && remeasure(xy, k + 1, o, levels, err, errlen) != 0) break;
        for (int j = 0; resume && j < k; j++) levels[j].iterations = -1, levels[j].delta_min0 = NAN;
        if (p->level_begin) p->level_begin(k, m, p->user);
        if (run_level(m, prev, k > 0 && !resume ? xy : NULL, &lo, p, resume, R, res, &levels[k], err, errlen) != 0)
            break;
        if (cap > 0 && o->max_iter > cap && res->stop == CFPO_STOP_MAX_ITER) {
            /* the cap, not the caller's --max-iter, ended the level: the
             * schedule's own end (progressive.h level_iter) */
            res->stop = levels[k].stop = CFPO_STOP_LEVEL_ITER;
            res->converged = 1;
        }
        if (res->stop == CFPO_STOP_SIGNAL) { /* the checkpoint is written: stop, no output */
            R->ops->free(R->E);
            free(xy);
            *nlevels = k + 1;
            return 1;
        }
        if (p->relax > 0 && k > 0) { /* the level before moves too, the one before that stays */
            cfpo_prog_level keep = levels[k];
            all_points(R->E, R->n, xy);
            R->ops->free(R->E);
            cfpo_options ro = lo;
            ro.max_iter = p->relax;
            if (run_level(m, k > 1 ? sizes[k - 2] : 0, xy, &ro, p, NULL, R, res, &levels[k], err, errlen) != 0) break;
            levels[k].iterations += keep.iterations;
            levels[k].seconds += keep.seconds;
            levels[k].delta_min0 = keep.delta_min0;
        }
        if (k < K - 1 && res->stop == CFPO_STOP_CALLER) { /* the caller stops the whole run */
            snprintf(err, errlen, "stopped by the caller at level %d (prefix %lld)", k, (long long)m);
            R->ops->free(R->E);
            break;
        }
        all_points(R->E, R->n, xy); /* the prefix, in id order */
        R->ops->free(R->E);
        if (order_level(xy, prev, m, o, p, k, err, errlen) != 0) break;
        const int joint = k > 0 &&
                          (k == K - 1 && p->joint_last > 0 ? p->joint_last : p->joint.sweeps) > 0;
        if (joint && joint_phase(xy, sizes, k, K, o, p, 0, levels, res, err, errlen) != 0) break;
        const int polish = k == K - 1 && p->polish > 0 && p->classes <= 0;
        if (polish && joint_phase(xy, sizes, k, K, o, p, 1, levels, res, err, errlen) != 0) break;
        if (k == K - 1) {
            if (joint || polish) {
                *nlevels = K;
                const int rc = hold(n, xy, o, R, err, errlen);
                free(xy);
                return rc;
            }
            int rc = p->relax > 0 ? remeasure(xy, K, o, levels, err, errlen) : 0;
            if (rc == 0) rc = hold(n, xy, o, R, err, errlen);
            free(xy);
            *nlevels = K;
            return rc;
        }
    }
    free(xy);
    return -1;
}
