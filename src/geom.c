/* geom.c - see geom.h. The solver's source is solver_impl.h, shared with
 * the device build. */
#include "geom.h"

#include <stdlib.h>
#include <string.h>

#include "solver_impl.h"
#include "solver_simd.h"

double cfpo_min_dist2(double cx, double cy, const double *yx, const double *yy, int m, int skip)
{
    return cfpo_min_dist2_hd(cx, cy, yx, yy, m, skip);
}

double cfpo_solve_cells_plain(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                              double hy, double floor2, double *cx, double *cy, double *scratch, int cells)
{
    return cfpo_solve_cells_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
}

double cfpo_local_solve_plain(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                              double hy, double floor2, double *cx, double *cy, double *scratch)
{
    return cfpo_local_solve_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
}

void (*cfpo_solve_observer)(const double *, const double *, int, int, cfpo_square, double, double, double);

/* 1: the AVX2 solver, 0: the plain one (see cfpo_solver_name). */
static int choose_avx2(void)
{
    const char *e = getenv("CFPO_SOLVER");
    return cfpo_solver_avx2_usable() && !(e && strcmp(e, "plain") == 0);
}

/* Chosen on the first call; every thread stores the same value. */
static int use_avx2(void)
{
    static int use = -1;
    int u = __atomic_load_n(&use, __ATOMIC_RELAXED);
    if (u < 0) __atomic_store_n(&use, u = choose_avx2(), __ATOMIC_RELAXED);
    return u;
}

const char *cfpo_solver_name(void)
{
    const char *e = getenv("CFPO_SOLVER");
    if (e && strcmp(e, "plain") != 0 && strcmp(e, "auto") != 0) return NULL;
    return use_avx2() ? "avx2" : "plain";
}

/* The AVX2 solver (same bits, solver_avx2.c) or the plain one, over the
 * first `cells` cells in the hint's order. */
static double solve(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                    double floor2, double *cx, double *cy, double *scratch, int cells)
{
    if (cfpo_solve_observer) cfpo_solve_observer(yx, yy, m, skip, S, hx, hy, floor2);
    if (CFPO_SOLVER_AVX2 && use_avx2())
        return cfpo_solve_cells_avx2(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
    return cfpo_solve_cells_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
}

double cfpo_local_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S,
                        double hx, double hy, double floor2, double *cx, double *cy,
                        double *scratch)
{
    return solve(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, m);
}

double cfpo_near_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                       double floor2, double *cx, double *cy, double *scratch, int cells)
{
    return solve(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells < 1 ? 1 : cells);
}
