/* prog_order.h - layer 4: the order of a progressive level's points once
 * optimised (progressive.h), so that the prefixes that end inside a level
 * are spread out too: the greedy farthest-point order, and the same order
 * paced by a quadtree, so that a partial level also keeps the regions'
 * shares of its points.
 *
 * The greedy order takes next the point farthest from all before it; it
 * fills the largest holes first, wherever they cluster, so a partial
 * level is unbalanced: at round(m sqrt 2) points its integration variance
 * was 2.2-7.1x weighted sample elimination's at 65,536 points. The paced
 * order takes next the farthest point whose quadtree cells, from the four
 * quarters of the torus down to leaves of CFPO_PROG_ORDER_CELL to 4
 * CFPO_PROG_ORDER_CELL of the level's m1 points, have each given at most
 * floor(t c / q) + tol of their c of the level's q new points after t
 * picks (results 2026-12-02-paced26). The default orders the levels of at
 * most CFPO_PROG_HERD_MAX points by prog_herd.h's herded order instead
 * (the same allowances; results 2026-12-02-prog28).
 * Owns: the lazy max-heap of the greedy choice, the quadtree's
 * allowances and the points they hold back. Serial: the same bytes always.
 * May include: prog_buckets.h (layer 2). */
#ifndef CFPO_PROG_ORDER_H
#define CFPO_PROG_ORDER_H

#include <stddef.h>
#include <stdint.h>

#define CFPO_PROG_ORDER_CELL 2 /* the paced order's leaves: this many to 4x as many of the level's m1 points */
#define CFPO_PROG_ORDER_TOL 1  /* ... and each cell's allowance over its share */

/* Points m0 .. m1 - 1 of xy reordered in place, greedily: next the one
 * farthest from the first m0 and those already taken (ties: the lower
 * index). Exact. So every prefix between m0 and m1 is as far apart as a
 * greedy choice among the level's points makes it. 0, or -1 with one line
 * in err (out of memory). */
int cfpo_prog_order(double *xy, int64_t m0, int64_t m1, char *err, size_t errlen);

/* The greedy order paced: the quadtree of the unit torus down to leaves
 * of per_cell (> 0) to 4 per_cell of the m1 points (depth L, the largest
 * with m1 / 4^L >= per_cell, at most 15; none when L = 0); a cell
 * holding c of the q = m1 - m0 new points may have given at most
 * floor(t c / q) + tol (tol >= 1) of them after t picks; next the
 * farthest point (ties: the lower index) none of whose cells is used up.
 * Such a point always exists. 0, or -1 with one line in err (out of
 * memory, tol < 1). */
int cfpo_prog_order_paced(double *xy, int64_t m0, int64_t m1, double per_cell, int tol, char *err, size_t errlen);

/* The depth of the paced order's quadtree for m1 points (as above). */
int cfpo_prog_order_depth(int64_t m1, double per_cell);

#endif
