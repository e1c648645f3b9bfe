/* progressive.h - layer 4: progressive (nested) CFPO on the uniform torus,
 * on any number of ranks (every rank holds the whole prefix between
 * levels; a level too small to cut across them runs on each alone). The set is built level by level: level k is the prefix of the
 * first m_k points (m_0 = base, m_k = min(2 m_(k-1), n), the last m = n;
 * or, with classes K, m_k = (k + 1) n / K). Level k's new points (ids
 * m_(k-1) .. m_k - 1) start by best-candidate insertion (prog_insert.h)
 * and are optimised by the uniform engine on the grid of m_k points with
 * the earlier levels held fixed (cfpo_engine_config.fixed): those still
 * constrain the movers and count as their neighbours, they never move. So
 * the output order is the prefix order, prefix m_k is final once its level
 * ends, its delta_min never falls while its level runs (the engine's
 * moves never lower a set's delta_min), and the bytes do not depend on the
 * thread or rank count (the engine's do not; the insertion is serial).
 * Owns: the level sizes, the per-level runs, the per-level results.
 * With joint.sweeps > 0 (progressive levels only) the bounded joint move
 * of prog_joint.h follows the last level: every point may move while no
 * dyadic prefix's delta_min falls; then each level's points are put in
 * their prefix order again and every level measured again. With polish > 0 the
 * full set is polished last by the same move with the full set's score,
 * the smaller prefixes held at or above a floor (prog_joint.h floor).
 * With classes (K equal groups) the default colours instead: one plain CFPO
 * run of n points, its points coloured into K balanced classes
 * (prog_colour.h) and put in class order, then the class-aware joint move
 * (prog_joint.h classes: every class's delta_min in Delta(N/K) and the
 * union's in Delta(n) never fall); the K LEVEL records are then the
 * prefixes of the class order (level 0 holds the CFPO run's iterations).
 * May include: engine.h, run_loop.h, prog_insert.h, prog_order.h, prog_herd.h, prog_balance.h, prog_joint.h, prog_colour.h (layers 0-4). */
#ifndef CFPO_PROGRESSIVE_H
#define CFPO_PROGRESSIVE_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "prog_colour.h"
#include "prog_joint.h"

#define CFPO_PROG_DEFAULT_BASE 64
#define CFPO_PROG_MAX_LEVELS 64
/* The class-aware move's defaults (classes by colouring; each used when
 * its option is 0): sweeps, the pair weights' targets (a pair of one
 * class: CLASS_TARGET Delta(N/K), across: UNION_TARGET Delta(N)), the
 * circumcentre candidates, the local ascent's steps, the class swaps
 * (each of these three off when below 0). */
#define CFPO_PROG_CLASS_SWEEPS 150
#define CFPO_PROG_CLASS_TARGET 0.80
#define CFPO_PROG_UNION_TARGET 0.88
#define CFPO_PROG_CLASS_CIRCUM 6
#define CFPO_PROG_CLASS_SOLVE 8
#define CFPO_PROG_CLASS_SWAPS 8
#define CFPO_PROG_DEFAULT_BALANCE 16 /* the balance's leaf size C by default (progressive levels, not classes) */
#define CFPO_PROG_DEFAULT_LEVEL_ITER 24 /* each level's iteration cap by default (no joint phase, no classes) */

typedef struct {
    int64_t m;          /* the prefix's size */
    int iterations;     /* the level's iterations */
    int stop;           /* why the level stopped (CFPO_STOP_*) */
    double delta_min0;  /* delta_min / Delta(m) of the prefix at the level's start */
    double delta_min, delta_avg; /* of the prefix at its end, in Delta(m) */
    double seconds;
} cfpo_prog_level;

typedef struct {
    int64_t base;     /* the first level's size (0: CFPO_PROG_DEFAULT_BASE) */
    int classes;      /* K > 0: K equal groups (class c = ids [c n/K, (c+1) n/K)) instead of doublings */
    double level_min; /* > 0: every level but the last stops once its prefix's delta_min reaches this */
    int candidates;   /* best-candidate draws per new point (0: 16) */
    int balance;      /* each level's new points by quota (prog_balance.h): every quadtree cell of
                         about C of the prefix's points gets its share; > 0: C = this; 0, the
                         default: C = CFPO_PROG_DEFAULT_BALANCE; < 0: off (best-candidate insertion
                         anywhere, prog_insert.h). Never with classes (cfpo_prog_balance_of) */
    int balance_order; /* with the balance on: each level's points spread through it by time, each
                          cell's evenly (prog_balance.h cfpo_prog_order_balanced); 0: the farthest
                          first, paced by the quadtree (prog_order.h cfpo_prog_order_paced), herded in
                          the levels of at most CFPO_PROG_HERD_MAX points (prog_herd.h); with
                          the balance off, the greedy order */
    int level_iter;   /* each level's iteration cap (the last's too; with the caller's max_iter): > 0 this;
                         0 the default: CFPO_PROG_DEFAULT_LEVEL_ITER without a joint phase and without
                         classes (a level's prefix is within about 0.001 of its end by then), none
                         otherwise; < 0 none (each level to convergence) */
    int relax;        /* > 0: after each level k >= 1, this many iterations with level k - 1
                         moving too (prefix m_(k-2) held); the earlier prefixes are measured
                         again at the end */
    cfpo_prog_joint_options joint; /* sweeps > 0: the bounded joint move after every level from
                                      level 1 on (its seed is set from the run's) */
    int joint_last;                /* > 0: the last level's sweeps instead of joint.sweeps */
    int polish;                    /* > 0 (not with classes): after the last level (and its joint move),
                                      this many sweeps of the joint move as the full set's polish
                                      (prog_joint.h floor): the full set's delta_min never falls, each
                                      smaller prefix stays at or above min(its value, polish_floor) */
    double polish_floor;           /* the polish's floor in each prefix's own units (0: 0.78) */
    /* Called for each sweep of the polish instead of joint.sweep_done
     * (with joint.user); may be NULL (then joint.sweep_done). */
    void (*polish_sweep)(int sweep, int64_t moved, const double *dmin, const double *davg, int K, void *user);
    int classes_levels;   /* with classes: 1 builds them as levels (class c with classes < c held);
                             0, the default, colours a plain CFPO run of n points into the classes
                             (prog_colour.h) and then runs the class-aware joint move (prog_joint.h,
                             classes) for joint.sweeps sweeps (0: CFPO_PROG_CLASS_SWEEPS) */
    double union_floor;   /* (colouring only) the union's delta_min may fall to this in Delta(n), not below
                             (nor below its value when that is lower already); 0: the union's target
                             (joint.target_full or CFPO_PROG_UNION_TARGET); at or above the union's
                             start (e.g. 1.2): the union's delta_min never falls */
    double colour_reach;  /* the colouring's reach in Delta(N/K) (0: 1.0) */
    cfpo_prog_colour_options *colour_out; /* (colouring only) when not NULL: the colouring's statistics */
    const char *checkpoint; /* the level under way's engine checkpoint (ckpt.h) here ... */
    int checkpoint_every;   /* ... every this many of its iterations and at its end */
    const char *resume;     /* go on from such a checkpoint (its size says its level) */
    /* Called before level k starts (k, its prefix size), e.g. to label
     * the trace's rows; may be NULL. */
    void (*level_begin)(int k, int64_t m, void *user);
    void *user;
} cfpo_prog_options;

/* The level sizes for n points into sizes (at most CFPO_PROG_MAX_LEVELS):
 * their count, or -1 with one line in err (a base or class size the grid
 * cannot hold, a base larger than n, K < 1 or K > n). */
int cfpo_prog_sizes(int64_t n, int variant, const cfpo_prog_options *p, int64_t *sizes, char *err, size_t errlen);

/* The balance's leaf size C of a run of p (progressive.h balance): 0 when
 * it is off (balance < 0, or classes > 0: the classes never use it). */
int cfpo_prog_balance_of(const cfpo_prog_options *p);

/* Level k's seed for the run's seed (level 0: the run's seed; level k >= 1:
 * mixed with k, and, when the balance is on, with its leaf size C and
 * balance_order too). The level's checkpoint holds this seed, so a resume
 * whose balance setting differs from the checkpoint's is told apart from
 * one of another run (cfpo_prog_run refuses it in one line). Level 0 is
 * the same set under every setting, so its checkpoint continues any. */
uint64_t cfpo_prog_level_seed(uint64_t seed, int k, const cfpo_prog_options *p);

/* Runs every level (collective over the ranks). o: the engine's options; its stop targets
 * and max_iter apply to the last level, max_iter to every level; its
 * progress callback sees every level's iterations (the statistics of the
 * prefix under way, in its own Delta(m)). On success R holds the last
 * level's engine (every point, id = prefix order; free with
 * R->ops->free), res its run, levels[0..*nlevels) the levels. 0; 1 when
 * a signal stopped it after writing the checkpoint (nothing held, no
 * output); or -1 with one line in err and nothing held. A resumed run
 * measures the finished levels again from the checkpoint's points (their
 * iterations -1, their start delta_min NaN). */
int cfpo_prog_run(int64_t n, const cfpo_options *o, const cfpo_prog_options *p, cfpo_run_engine *R,
                  cfpo_result *res, cfpo_prog_level *levels, int *nlevels, char *err, size_t errlen);

/* The worst level of levels[0..k) by delta_min (*by_min) and by
 * delta_avg (*by_avg): their indices. */
void cfpo_prog_worst(const cfpo_prog_level *levels, int k, int *by_min, int *by_avg);

#endif
