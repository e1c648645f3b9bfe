/* prog_joint.h - layer 4: the bounded joint move of a progressive set
 * (progressive.h), after its last level: every point, of any level, may
 * move, but only so that no dyadic prefix's delta_min falls.
 *
 * Point i of level l (ids below sizes[l], not below sizes[l - 1]) and
 * point j of level l' form a pair of level L = max(l, l'): the pair lies
 * in the prefixes m_L .. m_(K-1). Prefix k's delta_min (in Delta(m_k)) is
 * dmin_k, measured at the start of each sweep; so the pair's floor is
 * F_L = max over k >= L of dmin_k Delta(m_k), and a move that keeps every
 * pair of the mover at or above its floor keeps every prefix's delta_min
 * at or above its value at the sweep's start (the floors rise with the
 * prefixes, so the measured delta_min of each prefix never falls from one
 * sweep to the next).
 * The objective of a move is the pair measure with targets: the mover's
 * smallest d_ij / G_L, G_L = t_L Delta(m_L), t_L = target_prefix for every
 * level but the last and target_full for the last (the full set). Each
 * sweep visits the levels in order, each level's points by the cells of a
 * 9-coloured grid (cells of one colour in parallel, each cell's points in
 * id order; cells of one colour are too far apart for their moves to
 * meet, so the bytes never depend on the thread count); point i tries
 * `candidates` positions near it (half
 * straight away from the pair that binds it, half in a disk; steps in
 * fractions of its nearest neighbour's distance; counter-based draws from
 * seed, sweep and i) and takes the best that keeps every floor and raises
 * its own measure. With floor > 0 (the polish) the prefixes below the full
 * set may give up delta_min down to that floor, and the score is the full
 * set's alone (the field below). With hold > 0, a pair of level L shorter than
 * hold Delta(m_L) may not shrink either: each point's nearest distance in
 * each of its prefixes m_k then never falls below the smaller of its old
 * value and hold Delta(m_k), which guards the prefixes' delta_avg.
 * Options (off by default) add circumcentre candidates, a local ascent, a
 * soft-minimum score, a delta_avg term and pair moves (the fields below).
 * Owns: the pair floors and weights, the bucket grid of the moves, the
 * prefix measures of each sweep.
 * May include: geom.h, rng.h, prog_buckets.h, prog_pgrid.h (layers 0-3). */
#ifndef CFPO_PROG_JOINT_H
#define CFPO_PROG_JOINT_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int sweeps;           /* passes over every point; the phase also ends after a pass that moved nothing */
    int candidates;       /* trial positions per point and sweep (0: 12) */
    double avg;           /* > 0: the score of a move is the pair measure plus avg times the mover's
                             mean, over the groups that hold it, of its nearest distance in the group
                             over the group's G_L (each capped); guards the prefixes' delta_avg; 0: off */
    double soft;          /* > 0: the pair measure of a move is the soft minimum -soft log sum exp(-q_j / soft)
                             over the mover's pairs below the cap (counts the near-binding pairs too,
                             unjams); 0: the minimum */
    int circum;           /* > 0: also the circumcentres of the triples of the mover's this many nearest
                             neighbours (the farthest-point candidates), the best kept before the solve */
    int pairs;            /* > 0: a point whose own moves all fail tries this many pair moves with its
                             binding partner (when that is of its level or finer; not with hold) */
    int swaps;            /* > 0 (classes): a point whose own moves all fail tries class swaps: it and one
                             of its this many first neighbours of another class within 1.5 Delta(n)
                             exchange places (so their classes), kept when the smaller of their
                             measures rises and every pair keeps its floor; 0: off */
    int solve;            /* > 0: then up to this many steps of the local solve from the best trial
                             (the ascent of the smallest pair measure over the neighbours); 0: off */
    double target_prefix; /* t_L for every level but the last (0: 0.78) */
    double target_full;   /* t_L for the last level (0: 0.90) */
    double hold;          /* > 0: a pair of level L shorter than hold Delta(m_L) may not shrink
                             (guards each prefix's delta_avg); 0: off */
    double floor;         /* with classes, > 0: the union's floor: a pair may fall to min(the union's
                             delta_min, floor) Delta(n), a pair of one class not below its class's
                             delta_min either (each class's delta_min never falls; the union's never
                             below that floor). Without classes, > 0: the polish of the full set. Every pair's weight
                             is the full set's, target_full Delta(n) (the mover's nearest distance in
                             the full set is the score), and each prefix k below the full set may
                             fall to floor Delta(m_k) but not below (nor below its value when that
                             is lower already): its pair floor is min(dmin_k, floor) Delta(m_k);
                             the full set's delta_min never falls. 0: off */
    int classes;          /* 1: the levels are classes (progressive.h's --classes): a pair within
                             class c has level c (weight target_prefix Delta(class size), floor
                             the class's and the union's), a pair across classes level K (weight
                             target_full Delta(n), floor the union's); K + 1 groups are measured */
    uint64_t seed;
    int threads;          /* OpenMP threads of the moves (0: all); the bytes do not depend on it */
    /* Called with sweep 0 (the start) and after every sweep: the points
     * moved, each prefix's delta_min and delta_avg in its own Delta(m_k);
     * may be NULL. */
    void (*sweep_done)(int sweep, int64_t moved, const double *dmin, const double *davg, int K, void *user);
    void *user;
} cfpo_prog_joint_options;

/* The joint move of xy (sizes[K - 1] points, prefix order) in place; the
 * prefixes' final measures into dmin, davg (K each; with classes K + 1:
 * the classes in their own units, then the union). The ids never change
 * level. 0, or -1 with one line in err (xy unchanged but for moves that
 * were made; out of memory is the only failure: before any move, or with
 * solve or circum in a sweep, when a thread's neighbour list grows). */
int cfpo_prog_joint(double *xy, const int64_t *sizes, int K, const cfpo_prog_joint_options *jo, double *dmin,
                    double *davg, char *err, size_t errlen);

#endif
