/* ccdt.h - capacity-constrained Delaunay triangulation (Y. Xu, L. Liu,
 * C. Gotsman, S. J. Gortler, "Capacity-Constrained Delaunay Triangulation
 * for point distributions", Computers & Graphics 35(3), SMI 2011) on
 * CGAL's periodic Delaunay triangulation of the unit torus.
 *
 * Owns: the Delaunay triangulation of the n points and a copy of its
 * connectivity, the energy (the sum of the squared triangle areas of a
 * connectivity; on the torus a triangulation of n points has 2n triangles
 * whose signed areas sum to 1 whatever the positions, so this is the area
 * variance up to constants), the two phases and one iteration, the net
 * displacements and the iteration statistics.
 * Does not own: the stopping loop, files or the command line (main_ccdt.c).
 *
 * The method, as the paper describes it (abstract, Sec. 3): the energy is
 * minimised by alternating a geometry phase that moves the points with the
 * connectivity fixed and a Delaunay phase that makes the connectivity the
 * Delaunay triangulation of the new positions. One iteration here:
 *  1. Geometry phase (connectivity fixed): Gauss-Seidel sweeps over the
 *     points in id order. A triangle's area is linear in each of its
 *     vertices, so the position of point v that minimises the squared
 *     deviations of its incident triangles' areas from the mean 1/(2n),
 *     the others fixed, solves a 2x2 least-squares system; v moves towards
 *     it by the step s <= 1 that keeps every incident triangle at a tenth
 *     of its area at least (no triangle inverts: the connectivity stays an
 *     embedding). At most 8 sweeps; fewer when a sweep moves no point by
 *     tol * L or more (L = cfpo's cell side, as for cfpo and FPO).
 *  2. Delaunay phase: the points are re-triangulated (CGAL builds the
 *     Delaunay triangulation of the new positions; the result is the one a
 *     sequence of Lawson flips reaches) and the new connectivity copied.
 * Damping: taken literally the alternation cycles (the geometry phase
 * pushes edges past the flip boundary, the flips push the points back) and
 * never meets tol. So an iteration applies the fraction `step` of the
 * geometry phase's moves (start + step (result - start)) before the
 * Delaunay phase; the next step is half of it when the energy of the new
 * Delaunay triangulation is higher than that of the previous one, else
 * 1.25 times it, at most 1 (the first step is 1).
 * Converged when no point's net move over an iteration reaches tol * L.
 * What the paper's text (not at hand: only its abstract and description)
 * leaves open and we chose: the number of sweeps per Delaunay phase (up to
 * 8), the step limit against inversion (0.9 of the step to the first
 * degenerate triangle), the damping, re-triangulation instead of flips
 * (same triangulation), and the start (uniform random points).
 *
 * The reference schedule (ccdt_set_reference; the comparison code of de
 * Goes et al.'s BNOT paper runs CCDT so): an iteration is one Gauss-Seidel
 * sweep with full steps (every point to its least-squares position, no
 * guard against inversion), then the Delaunay phase; no damping; a fixed
 * number K of iterations (converged after the K-th).
 *
 * Monotonicity (what holds exactly, up to rounding): each vertex update
 * does not increase the energy of the fixed connectivity (the local sum is
 * a convex quadratic in the step, smallest at s = 1), so neither does a
 * sweep or a geometry phase. The Delaunay phase moves no point and may
 * raise or lower the energy (a flip of a convex quadrilateral keeps the
 * sum of its two areas, not the sum of their squares).
 * A C interface over a C++ implementation. */
#ifndef CFPO_BASELINES_CCDT_H
#define CFPO_BASELINES_CCDT_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest n: the copy numbers the 6n corners with 32-bit integers. */
#define CCDT_MAX_N ((int64_t)700000000)

typedef struct ccdt_engine ccdt_engine;

/* Uniform random start (the paper's). NULL with a message. */
ccdt_engine *ccdt_create(int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
/* A given start (n points, xy interleaved, in [0,1), distinct), scale L.
 * For tests. */
ccdt_engine *ccdt_create_from(int64_t n, const double *xy, double L, double tol, char *err,
                              size_t errlen);
void ccdt_free(ccdt_engine *E);

/* One iteration: a geometry phase, then a Delaunay phase. s->moved:
 * points whose net move reached tol * L; s->solved: vertex updates
 * (n per sweep); s->max_disp: largest net move / L. */
void ccdt_iterate(ccdt_engine *E, cfpo_iter_stats *s);
/* The phases one at a time, for tests. ccdt_sweep: one Gauss-Seidel sweep
 * with the connectivity fixed (the points are not wrapped into [0,1) until
 * the Delaunay phase); returns the largest move / L. ccdt_delaunay: the
 * Delaunay phase; returns the number of edges that are new (-1 if points
 * coincide, which the step rule rules out). */
double ccdt_sweep(ccdt_engine *E);
int64_t ccdt_delaunay(ccdt_engine *E);

/* The reference schedule for K iterations from the next one on (K 0:
 * the damped schedule to convergence, the default). */
void ccdt_set_reference(ccdt_engine *E, int iterations);
/* Sweeps, step taken (fraction of the geometry phase's moves; 0: none)
 * and new Delaunay edges of the last iteration. */
int ccdt_sweeps(const ccdt_engine *E);
double ccdt_step(const ccdt_engine *E);
int64_t ccdt_new_edges(const ccdt_engine *E);
/* The energy of the current connectivity at the current positions; and the
 * energy of CGAL's triangulation (equal right after a Delaunay phase). */
double ccdt_energy(const ccdt_engine *E);
double ccdt_energy_recomputed(const ccdt_engine *E);
/* On the current connectivity: coefficient of variation of the areas (std
 * / mean); largest |area - mean| / mean; smallest signed area / mean; the
 * sum of the signed areas (1 on the torus). */
double ccdt_area_cv(const ccdt_engine *E);
double ccdt_area_maxdev(const ccdt_engine *E);
double ccdt_area_min(const ccdt_engine *E);
double ccdt_area_sum(const ccdt_engine *E);

void ccdt_deltas(ccdt_engine *E, double *dmin, double *davg);
const double *ccdt_points(const ccdt_engine *E);
/* After a Delaunay phase: CGAL's is_valid(), n vertices, stored points
 * equal to the array, 2n triangles, the copy has 2n triangles of positive
 * area. 1 when all hold; 0 also between a sweep and the Delaunay phase. */
int ccdt_check(const ccdt_engine *E);

#ifdef __cplusplus
}
#endif
#endif
