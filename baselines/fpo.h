/* fpo.h - Farthest Point Optimization (Schloemer, Heck, Deussen 2011) on
 * CGAL's periodic Delaunay triangulation, global (FPO) and local (LFPO).
 *
 * Owns: the dynamic triangulation of the n points, the priority queue of
 * faces by circumradius (lazy invalidation), one iteration (every point in
 * id order is removed, the largest empty circle of the rest is found, the
 * point is inserted at its centre if that gains more than tol * L, else
 * back where it was), the net displacements and the iteration statistics.
 * Does not own: the stopping loop, files or the command line (main_fpo.c).
 *
 * The scale L is cfpo's cell side for this n (cfpo_grid_init), so tol means
 * exactly what it means for `cfpo --tol`, and iteration counts compare.
 * Under a density (o->density; docs: baselines/README.md, "FPO under a
 * density"): q = sqrt(rho) at a point, the symmetric pair measure of
 * cfpo's density path, m(i, j)^2 Delta(n)^2 = d^2 q_i q_j
 * (src/density/dens_measure.h), and every distance FPO compares becomes that
 * measure. The candidates stay the Delaunay circumcentres (the geometry is
 * Euclidean): a face's value is the exact smallest measure of its centre c
 * to the other points, min over all j of d(c, x_j)^2 q_c q_j; its heap key
 * r^2 q_c min(q of its vertices) is an upper bound of that value (its
 * vertices are at distance r). Global FPO takes the face of largest value
 * by branch and bound on the heap (pop while the next key exceeds the best
 * value found); LFPO the best of the 2-ring's faces. The point moves there
 * when the value exceeds (m0 + tol L)^2, m0 its current exact smallest
 * measure (times Delta), and when the exact smallest measure at the new
 * place, all points included, exceeds m0^2: so a move always raises the
 * point's smallest measure and min m over all pairs never falls. The start
 * is drawn proportional to rho (dens_draw.h) from the uniform start's
 * numbers; the net displacements are measured as pairs, d q_a^(1/2)
 * q_b^(1/2). With rho = 1 every key, value, test and draw is the uniform
 * one's number for number (q = 1 exactly): the same bytes.
 * A C interface over a C++ implementation: this is the only file of the
 * suite that sees CGAL besides coverage.cpp. */
#ifndef CFPO_BASELINES_FPO_H
#define CFPO_BASELINES_FPO_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"

#ifdef __cplusplus
extern "C" {
#endif
#include "density.h" /* a C header without its own guard for C++ */

enum { FPO_START_RANDOM = 0, FPO_START_GRID = 1 };

typedef struct {
    uint64_t seed;
    int local;    /* 0: global FPO, 1: LFPO (search the 2-ring only) */
    int start;    /* FPO_START_RANDOM (uniform, the default) or FPO_START_GRID
                     (cfpo's stratified start, the same points as `cfpo`) */
    double tol;   /* relative to L, as cfpo's tol */
    const cfpo_density *density; /* NULL: uniform; else FPO under the
                     density (below), read during the run */
} fpo_options;

void fpo_options_init(fpo_options *o);

/* Checks n without allocating: 0; -1 with a one-line message when n is
 * too small for the grid the tolerance is measured on (the same minimum
 * as cfpo); -2 when the triangulation would not fit in memory. */
int fpo_validate(int64_t n, const fpo_options *o, char *err, size_t errlen);

typedef struct fpo_engine fpo_engine;

/* Makes the start and its triangulation. NULL with a message for n too
 * small (the same minimum as cfpo) or out of memory. */
fpo_engine *fpo_create(int64_t n, const fpo_options *o, char *err, size_t errlen);
void fpo_free(fpo_engine *E);

/* One iteration over all points; fills everything but s->iteration.
 * s->solved is the number of largest-empty-circle queries (n). */
void fpo_iterate(fpo_engine *E, cfpo_iter_stats *s);

/* delta_min, delta_avg of the current set, normalised by Delta(n) (under
 * a density: in the symmetric measure, cfpo_dens_nn). */
void fpo_deltas(fpo_engine *E, double *dmin, double *davg);

/* The points in id order (x0 y0 x1 y1 ...), 2n doubles owned by E. */
const double *fpo_points(const fpo_engine *E);

/* Checks: CGAL's is_valid() of the triangulation, vertex count == n, every
 * vertex's stored point equal to the point array, every face registered
 * once with its own circumcircle cached, and (global FPO) the best live
 * heap entry equal to the largest circumcircle. 1 when all hold. O(n log n). */
int fpo_check(const fpo_engine *E);

#ifdef __cplusplus
}
#endif
#endif
