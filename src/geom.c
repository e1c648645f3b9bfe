/* geom.c - see geom.h. The solver's source is solver_impl.h, shared with
 * the device build. */
#include "geom.h"

#include "solver_impl.h"
#include "solver_simd.h"

double cfpo_min_dist2(double cx, double cy, const double *yx, const double *yy, int m, int skip)
{
    return cfpo_min_dist2_hd(cx, cy, yx, yy, m, skip);
}

double cfpo_local_solve_plain(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                              double hy, double floor2, double *cx, double *cy, double *scratch)
{
    return cfpo_local_solve_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
}

void (*cfpo_solve_observer)(const double *, const double *, int, int, cfpo_square, double, double, double);

/* The AVX2 solver where the CPU has it (same bits, solver_avx2.c): known
 * at compile time under -march with AVX2, else asked once. */
double cfpo_local_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S,
                        double hx, double hy, double floor2, double *cx, double *cy,
                        double *scratch)
{
    if (cfpo_solve_observer) cfpo_solve_observer(yx, yy, m, skip, S, hx, hy, floor2);
#if CFPO_SOLVER_AVX2
#ifdef __AVX2__
    return cfpo_local_solve_avx2(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
#else
    static int use = -1; /* every thread stores the same value */
    int u = __atomic_load_n(&use, __ATOMIC_RELAXED);
    if (u < 0) __atomic_store_n(&use, u = cfpo_solver_avx2_usable(), __ATOMIC_RELAXED);
    if (u) return cfpo_local_solve_avx2(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
#endif
#endif
    return cfpo_local_solve_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
}
