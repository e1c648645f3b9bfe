/* geom.h - layer 1 (may include layer 0): torus geometry and the exact
 * local solver.
 *
 * Owns: the hexagonal bound Delta(n), wrapping onto [0,1), periodic
 * distances, and LocalCFPO: the point of an axis-aligned square S that is
 * farthest from a small point set Y (largest empty circle centred in S).
 * Pure functions: no allocation, no globals, no I/O. The caller passes
 * scratch memory. Coordinates given to the solver are local (already
 * unwrapped around one cell), so no periodicity is involved there. */
#ifndef CFPO_GEOM_H
#define CFPO_GEOM_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* Largest possible minimum distance of n points on the unit torus. */
static inline double cfpo_delta_bound(double n) { return sqrt(2.0 / (sqrt(3.0) * n)); }

/* The low-frequency band of n points: integer k with 0 < |k| <= 0.2 sqrt(n),
 * decided exactly (25 |k|^2 <= n). P0 is the periodogram's mean over it
 * (analysis/measures/lowfreq.c) and the hyperuniform variant removes its
 * density modes (transport.c). */
static inline int cfpo_in_lowk_band(int64_t kx, int64_t ky, int64_t n)
{
    const int64_t q = kx * kx + ky * ky;
    return q > 0 && 25 * q <= n;
}

/* v mapped into [0,1): never returns 1.0. */
static inline double cfpo_wrap01(double v)
{
    v -= floor(v);
    return v >= 1.0 ? 0.0 : v;
}

/* Signed periodic difference a - b mapped into [-0.5, 0.5]. */
static inline double cfpo_torus_diff(double a, double b)
{
    double d = a - b;
    return d - floor(d + 0.5);
}

static inline double cfpo_torus_dist2(double ax, double ay, double bx, double by)
{
    double dx = cfpo_torus_diff(ax, bx), dy = cfpo_torus_diff(ay, by);
    return dx * dx + dy * dy;
}

typedef struct { double x0, y0, x1, y1; } cfpo_square; /* [x0,x1] x [y0,y1] */

/* Scratch doubles the solver needs for m points. */
static inline size_t cfpo_solver_scratch(size_t m) { return 8 * (m + 8); }

/* min_j |(cx,cy) - y_j|^2 over the m points, skipping index `skip`
 * (pass -1 to skip nothing). +INFINITY when no point is left. */
double cfpo_min_dist2(double cx, double cy, const double *yx, const double *yy, int m, int skip);

/* LocalCFPO. Y = the m points (yx[i], yy[i]) except index `skip` (-1: none).
 * Finds the point c of S maximising d(c) = min_{y in Y} |c - y| over S,
 * exactly: it is a vertex of the Voronoi cell of some y clipped to S (a
 * Voronoi vertex, a Voronoi edge meeting the boundary of S, or a corner).
 * Returns d(c)^2 as computed from Y (not from the clipping), or +INFINITY
 * when Y is empty (then c is S's centre).
 *
 * `floor2` prunes: Voronoi cells whose every point is at most floor2 away
 * (squared) are skipped, and if no point of S beats floor2 the function
 * returns -1 (c is then S's centre). Pass -1 for the plain maximum.
 * `hx, hy` is a hint near which the maximiser is expected (the current
 * position); it only orders the work and never changes the returned value.
 * Ties between equal values go to the first found, in an order that depends
 * only on (Y in the given order, hint), so the result is reproducible.
 * scratch: cfpo_solver_scratch(m) doubles. */
double cfpo_local_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S,
                        double hx, double hy, double floor2, double *cx, double *cy,
                        double *scratch);

/* The near solve: LocalCFPO searching only the Voronoi cells (in Y,
 * clipped to S) of the first `cells` points of Y (cells >= 1) in the
 * hint's order, nearest to the hint first. With the hint at x, the first
 * is the cell x lies in: with cells = 1, x goes to the farthest vertex of
 * its own region; with 2, of its own region or its second-nearest
 * neighbour's. A spot LocalCFPO finds in another cell (a hole beyond the
 * next points) is not looked for. The same arguments, value and tie rules
 * as cfpo_local_solve; its answer is LocalCFPO's whenever LocalCFPO's
 * maximiser lies in a searched cell, and never larger (both up to
 * rounding: a vertex clipped from another cell may differ in the last
 * bits). One cell is about a third of LocalCFPO's work: proving that no
 * other cell holds a farther spot is most of its cost. */
double cfpo_near_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                       double floor2, double *cx, double *cy, double *scratch, int cells);

#endif
