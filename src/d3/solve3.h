/* solve3.h - layer 1 of the 3-D engine (includes nothing of the project):
 * the exact local solve in three dimensions.
 *
 * Owns: the bound Delta3(n), and LocalCFPO-3D: the point of an
 * axis-aligned box S farthest from a small point set Y (the centre of the
 * largest empty ball centred in S). The maximum of f(c) = min_j |c - y_j|
 * over S is a vertex of the Voronoi diagram of Y clipped to S; for each y_i
 * (nearest to the hint first) the box is clipped lazily, only by the
 * bisectors that cut off its current farthest vertex from y_i, until none
 * does (that vertex is the cell's answer) or the vertex is no farther than
 * the best found (the cell is abandoned) (docs/method.md, "Three
 * dimensions"). Pure functions: no allocation, no globals, no I/O; local
 * (already unwrapped) coordinates. */
#ifndef CFPO_SOLVE3_H
#define CFPO_SOLVE3_H

#include <math.h>
#include <stddef.h>

/* Largest possible minimum distance of n points on the unit 3-torus (the
 * FCC packing's, Kepler's bound): (sqrt(2)/n)^(1/3). */
static inline double cfpo3_delta_bound(double n) { return cbrt(sqrt(2.0) / n); }

/* Convex polytope as a vertex pool and faces given as index loops. */
#define P3_MAXV 192
#define P3_MAXF 96
#define P3_MAXI 768
typedef struct {
    int nv, nf;
    double v[3][P3_MAXV]; /* v[axis][vertex]: each coordinate contiguous */
    /* a value per vertex carried through clipping (the solver's squared
     * distance to the site whose cell it clips); -1 for a new vertex and
     * for the box's */
    double w[P3_MAXV];
    int fs[P3_MAXF + 1]; /* face f: fi[fs[f]] .. fi[fs[f+1]-1] */
    int fi[P3_MAXI];
} cfpo3_poly;

/* The box [lo, hi] (lo < hi on every axis) as a polytope. */
void cfpo3_poly_box(cfpo3_poly *p, const double lo[3], const double hi[3]);
/* Clips p by the half-space n.c <= off into q (q != p). Returns 0: the
 * plane cuts nothing (q not written), 1: cut (q holds the result), -1: the
 * half-space holds no vertex (empty). -2: out of room (the caller treats
 * the cell as not clipped further; it never happens for the solver's
 * neighbourhoods, whose cells have about 25 vertices). */
int cfpo3_poly_clip(const cfpo3_poly *p, cfpo3_poly *q, const double n[3], double off);
/* Largest squared distance from a vertex of p to y, and its index. */
double cfpo3_poly_far(const cfpo3_poly *p, const double y[3], int *at);

/* The most sites one solve takes. */
#define CFPO3_MAXM 1024

/* Work counters of one solve (for measuring; may be NULL): cells entered,
 * farthest vertices tested against the bisectors, cuts made. */
typedef struct {
    long cells, tests, cuts;
} cfpo3_solve_count;

/* LocalCFPO-3D. y: m points (3 doubles each), ordered by distance to the
 * hint (nearest first: the solver's order, not its correctness). S = [lo,
 * hi]. floor2: only spots whose squared distance to Y exceeds it count
 * (<= 0: none is excluded); cells that cannot beat it are not clipped.
 * Writes the farthest point into best and returns its squared distance to
 * Y (the squared distance to the nearest y), or -1 when no spot of S beats
 * floor2, m = 0 or m > CFPO3_MAXM. scratch: two polytopes. Exact up to
 * rounding: every vertex of the clipped Voronoi diagram that could win is
 * examined. A cell is skipped at once when one bisector puts the whole box
 * on the other site's side by a relative margin of 1e-12 (the cell misses
 * S). */
double cfpo3_local_solve(const double *y, int m, const double lo[3], const double hi[3], double floor2,
                         double best[3], cfpo3_poly scratch[2], cfpo3_solve_count *count);

/* The near solve: LocalCFPO-3D searching only the Voronoi cells of the
 * first `cells` sites of y (the hint's order: with x's nearest site first,
 * cells = 1 searches the cell x lies in). Every cell it searches is
 * solved against all the sites' bisectors, so its answer is a
 * vertex of the clipped diagram, in S, at its returned squared distance
 * from Y; it is the exact solve's when the winner lies in those cells.
 * cells >= m is cfpo3_local_solve. */
double cfpo3_near_solve(const double *y, int m, int cells, const double lo[3], const double hi[3], double floor2,
                        double best[3], cfpo3_poly scratch[2], cfpo3_solve_count *count);

#endif
