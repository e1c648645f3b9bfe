/* solver_simd.h - layer 1, host only: the AVX2 and AVX-512 LocalCFPO
 * (solver_avx2.c, solver_avx512.c) beside the plain one, for geom.c's
 * choice and for the tests and the benchmark that compare them. Everyone
 * else calls cfpo_local_solve.
 * May include geom.h. */
#ifndef CFPO_SOLVER_SIMD_H
#define CFPO_SOLVER_SIMD_H

#include "geom.h"

/* The AVX2 and AVX-512 code is compiled on x86-64 by GCC or Clang
 * (function by function, with the target attribute, whatever -march says),
 * and chosen at run time by what the CPU has. */
#if (defined(__x86_64__) || defined(_M_X64)) && (defined(__GNUC__) || defined(__clang__)) && !defined(CFPO_NO_AVX2)
#define CFPO_SOLVER_AVX2 1
#else
#define CFPO_SOLVER_AVX2 0
#endif

/* 1 where cfpo_local_solve_avx2 runs its AVX2 code (else it is the plain
 * solver under another name). */
int cfpo_solver_avx2_usable(void);

/* 1 where the CPU has AVX-512 (F and DQ), AVX2 and BMI2, so that the
 * AVX-512 route (solver_avx512.c) can run. */
int cfpo_solver_avx512_usable(void);

/* The solver cfpo_local_solve runs, "avx512", "avx2" or "plain", chosen
 * once: the widest route the CPU runs, unless the environment says
 * CFPO_SOLVER=plain or avx2 (the tests compare the routes on whole runs;
 * a route the CPU lacks gives the next narrower one). NULL when
 * CFPO_SOLVER holds anything but "plain", "avx2", "avx512" or "auto" (cfpo
 * reports it; the choice is then as if unset). */
const char *cfpo_solver_name(void);

/* The plain solver (solver_impl.h), whatever the CPU. */
double cfpo_local_solve_plain(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                              double hy, double floor2, double *cx, double *cy, double *scratch);

/* The AVX2 and AVX-512 solvers: the same arguments and the same bits as
 * the plain one. Call each only where its _usable() says 1. */
double cfpo_local_solve_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                             double hy, double floor2, double *cx, double *cy, double *scratch);
double cfpo_local_solve_avx512(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                               double hy, double floor2, double *cx, double *cy, double *scratch);

/* The solvers over the Voronoi cells of the first `cells` points in the
 * hint's order (m: LocalCFPO; fewer: the near solve of geom.h), plain,
 * AVX2 and AVX-512 (call the last two only where usable): the same bits. */
double cfpo_solve_cells_plain(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                              double hy, double floor2, double *cx, double *cy, double *scratch, int cells);
double cfpo_solve_cells_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                             double hy, double floor2, double *cx, double *cy, double *scratch, int cells);
double cfpo_solve_cells_avx512(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                               double hy, double floor2, double *cx, double *cy, double *scratch, int cells);

#if CFPO_SOLVER_AVX2
/* Pieces the AVX2 and AVX-512 routes share. The plain cut of a polygon
 * held in arrays (one of more than 8 vertices) by the bisector (m, n):
 * -1 when it misses the polygon, 0 when it removes all of it, else the
 * count written to ox, oy and, in *far2, their largest squared distance
 * from (ax, ay) (solver_avx2.c). */
int cfpo_simd_cut_large(const double *x, const double *y, int nv, double mx, double my, double nx, double ny,
                        double ax, double ay, double *sd, double *ox, double *oy, double *far2);
/* The AVX2 prefilter: does some bisector of (ax, ay) with another point
 * put all of S beyond it by the margin? (solver_avx2.c, with the proof.) */
int cfpo_simd_cell_empty(const double *px, const double *py, int k, double ax, double ay, const double corner[4][2],
                         double A);

/* The plain loop's last step for a cell that survived its cuts: each
 * vertex in order that lies farther than *best from (ax, ay) (squared)
 * replaces *best and (*bx, *by); returns whether one did. */
static inline int cfpo_simd_best_vertex(const double *x, const double *y, int nv, double ax, double ay, double *best,
                                        double *bx, double *by)
{
    int found = 0;
    for (int v = 0; v < nv; v++) {
        double dx = x[v] - ax, dy = y[v] - ay;
        double d2 = dx * dx + dy * dy;
        if (d2 > *best) {
            *best = d2;
            *bx = x[v];
            *by = y[v];
            found = 1;
        }
    }
    return found;
}
#endif

/* Where not NULL, called by cfpo_local_solve and cfpo_near_solve with every call's inputs
 * before it solves (cfpo-bench capture; set only while one thread runs). */
extern void (*cfpo_solve_observer)(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                                   double hy, double floor2);

#endif
