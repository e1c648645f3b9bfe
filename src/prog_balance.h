/* prog_balance.h - layer 4: a progressive level's new points placed so
 * that the prefix they complete has the same number of points in every
 * cell of a quadtree (up to one), whatever the earlier levels hold there
 * (progressive.h balance). Without it (prog_insert.h) the new points
 * follow the holes of the earlier levels, so a region the earlier levels
 * left too dense gets more new points too: their long-wavelength density
 * errors pass on to every later prefix, and the prefix's low-frequency
 * power grows with each doubling.
 *
 * The quota: top-down over the quadtree on the unit torus, a node's new
 * points go to its four children as near as integers allow to each
 * child's share of the prefix (m1 / 4^depth) less the points it already
 * holds (a child already over its share gets none; the rest share the
 * excess equally; the rounding's ties by a seeded draw), down to leaf
 * cells that hold about `per_cell` of the prefix's points. The points:
 * the leaf slots in a seeded random order, each new point the best of
 * `cand` uniform draws within its leaf cell (farthest from every point
 * placed so far, across cell borders too). Serial: the same bytes always.
 * Owns: the quadtree counts, the quotas and the slots' order.
 * May include: geom.h, rng.h, prog_buckets.h (layers 0-2), prog_order.h. */
#ifndef CFPO_PROG_BALANCE_H
#define CFPO_PROG_BALANCE_H

#include <stddef.h>
#include <stdint.h>

/* Points m0 .. m1 - 1 of xy after the m0 points already there, as above;
 * per_cell >= 1. 0, or -1 with one line in err (out of memory). */
int cfpo_prog_insert_balanced(double *xy, int64_t m0, int64_t m1, int cand, int per_cell, uint64_t seed,
                              uint64_t stream, char *err, size_t errlen);

/* The leaf quotas alone, for tests: the depth L (leaves 2^L a side, L at
 * most 15) for m1 points at per_cell, and into quota (4^L cells, row
 * major) each leaf's new points. 0, or -1 when out of memory. */
int cfpo_prog_balance_quota(const double *xy, int64_t m0, int64_t m1, int per_cell, uint64_t seed, uint64_t stream,
                            int *depth, int64_t **quota);

/* The level's points m0 .. m1 - 1 reordered so that every partial level
 * keeps the quadtree cells' proportions: first the greedy order
 * (prog_order.h cfpo_prog_order), then each leaf cell's points (cells of
 * about per_cell of the m1 points) spread evenly through the level, the
 * j-th of a cell's c points at time (j + u) / c (u a seeded draw per
 * cell), the cell's own points in their greedy order. 0, or -1 with one
 * line in err (out of memory). */
int cfpo_prog_order_balanced(double *xy, int64_t m0, int64_t m1, int per_cell, uint64_t seed, uint64_t stream,
                             char *err, size_t errlen);

#endif
