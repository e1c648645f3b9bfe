/* prog_colour.h - layer 3: the balanced colouring of a point set into K
 * classes for `--classes K` (progressive.h classes_mode): each point gets
 * one of K classes of the given sizes so that few pairs of one class lie
 * close, then xy is put in class order (class c = rows [sizes[c - 1],
 * sizes[c]), each class's points in their old order).
 *
 * The cost of a pair of one class at distance d < r (r = reach
 * Delta(N/K), N/K the mean class size) is (r / d)^8 - 1, steep, so the
 * closest pairs dominate; the colouring lowers the sum over every pair of
 * one class. A greedy start (points in id order, each to the class of
 * least cost among those not full), then passes of local moves in id
 * order: a point's relabel when the class sizes stay within a slack of
 * their targets, else the swap with a neighbour of the other class; both
 * taken only when they lower the sum; last, the classes brought back to
 * their sizes by the cheapest relabels (one at a time, from the last
 * class over its size to a class under its size: the relabel of least
 * cost, of the lowest id and then class among equal costs; a tournament
 * tree over that class's points, updated at the relabelled point's
 * neighbours only, finds each in O(log n)). Serial and deterministic (no
 * random draws): the same bytes for any thread count.
 * Owns: the colouring's pair lists and costs.
 * May include: geom.h, prog_buckets.h (layers 0-2). */
#ifndef CFPO_PROG_COLOUR_H
#define CFPO_PROG_COLOUR_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double reach; /* r in Delta(N/K) (0: 1.0) */
    int passes;   /* local passes at most (0: 50); they also end after a pass that changed nothing */
    int restore_scan; /* 1: the sizes restored by scanning every point for each relabel (the
                         reference, O(n) a relabel); 0: by a tournament tree, the same relabels */
    /* out: the same-class pairs closer than 0.8 Delta(N/K) before and after the local passes */
    int64_t close_start, close_end;
    int passes_run;
    int64_t restores; /* out: the relabels that brought the classes back to their sizes */
    double cpu_seconds; /* out: the colouring's CPU seconds (its thread's) */
} cfpo_prog_colour_options;

/* Colours the sizes[K - 1] points of xy into K classes of sizes
 * sizes[c] - sizes[c - 1] and reorders xy into class blocks in place.
 * 0, or -1 with one line in err (out of memory; xy unchanged). */
int cfpo_prog_colour(double *xy, const int64_t *sizes, int K, cfpo_prog_colour_options *co, char *err,
                     size_t errlen);

#endif
