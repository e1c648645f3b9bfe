/* dens_solve.h - layer 2: the local solve under a density (docs/method.md,
 * "Density"): a candidate for the farthest point, in the symmetric
 * measure, of one point from its neighbours inside a box S.
 *
 * With q = sqrt(rho), the objective at c is f(c) = q(c) min_j |c - y_j|^2
 * q_j (the squared symmetric measure times Delta^2). Its level sets are
 * bounded by Apollonius circles; the solve replaces each circle by the
 * straight line through the point that divides y_i y_j in the ratio
 * q_j^(1/2) : q_i^(1/2), perpendicular to y_i y_j (exact when rho_i =
 * rho_j, where it is today's bisector), clips S by those lines into one
 * polygon for each of the `cells` nearest neighbours (given nearest first:
 * DENS_CELLS = 10 as LocalCFPO does, or the near phase's 2, policy.h), and evaluates f exactly at every vertex (q(c) from the
 * pixel, the min over all neighbours). The best vertex is
 * a candidate only: the engine accepts it when f rises against every point
 * that can matter (dens_engine.c), which is what the guarantee rests on.
 * Owns: the candidate search. */
#ifndef CFPO_DENS_SOLVE_H
#define CFPO_DENS_SOLVE_H

#include <math.h>

#include "dens_clip.h"
#include "density.h"
#include "geom.h"

/* Scratch doubles the solve needs for k neighbours. */
static inline size_t cfpo_dens_scratch(int k) { return 8 * ((size_t)k + 8) + 16; }

/* Neighbours (yx, yy) with q = sqrt(rho) in yr (k of them, in a local frame whose
 * origin is (ox, oy) on the torus), nearest first, the box S (local frame);
 * the polygons of the first min(cells, k) neighbours are searched. Returns the
 * best vertex's f into *f and its position into (cx, cy) when it is above
 * floor_f, or 0 when no vertex on a non-zero pixel is (then *f = -1). The
 * engine passes the moving point's own value (a candidate must beat it):
 * polygons and evaluations that cannot beat it stop early, and the vertex
 * returned is the one the solve with floor_f < 0 returns whenever that
 * one beats floor_f (the same vertices, in the same order, strict
 * comparisons). qhi bounds q over every pixel a spot of S can read
 * (dens_qbound.h; sqrt(rho_max) always does): the prunings use it, and
 * any valid bound gives the same result. */
int cfpo_dens_solve(const double *yx, const double *yy, const double *yr, int k, int cells, cfpo_square S,
                    const cfpo_density *d, double qhi, double ox, double oy, double floor_f, double *cx, double *cy,
                    double *f, double *scratch);

/* The same search resumed: the polygons from `from` on (up to min(cells,
 * k)), after a call with the same neighbours, S, qhi and floor_f that
 * searched those before it (cells = from) and left *cx, *cy, *f. Returns
 * what cfpo_dens_solve with `cells` returns, bit for bit: that search
 * carries nothing from one polygon to the next but the best vertex so far
 * (the earlier call's result when it returned 1, else floor_f). */
int cfpo_dens_solve_from(const double *yx, const double *yy, const double *yr, int k, int from, int cells,
                         cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                         double *cx, double *cy, double *f, double *scratch);

/* The route the solve runs: 2 AVX-512, 1 AVX2, 0 plain, by what the CPU
 * has and CFPO_SOLVER allows (LocalCFPO's choice). */
int cfpo_dens_route(void);

/* f at c (local frame) against the k neighbours. */
double cfpo_dens_value(const double *yx, const double *yy, const double *yr, int k, double rc, double cx, double cy);

#endif
