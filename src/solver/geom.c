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

enum { ROUTE_PLAIN, ROUTE_AVX2, ROUTE_AVX512, ROUTES };
static const char *const route_name[ROUTES] = {"plain", "avx2", "avx512"};

/* The widest route CFPO_SOLVER allows: the one it names, every route
 * when it is unset or "auto"; -1 when it names none. */
static int allowed_route(void)
{
    const char *e = getenv("CFPO_SOLVER");
    if (!e || strcmp(e, "auto") == 0) return ROUTE_AVX512;
    for (int q = 0; q < ROUTES; q++)
        if (strcmp(e, route_name[q]) == 0) return q;
    return -1;
}

/* The widest route the CPU runs, at most the one CFPO_SOLVER allows (all
 * when it holds a bad value: cfpo_solver_name reports that). */
static int choose_route(void)
{
    int most = allowed_route();
    if (most < 0) most = ROUTE_AVX512;
    if (most >= ROUTE_AVX512 && cfpo_solver_avx512_usable()) return ROUTE_AVX512;
    if (most >= ROUTE_AVX2 && cfpo_solver_avx2_usable()) return ROUTE_AVX2;
    return ROUTE_PLAIN;
}

/* Chosen on the first call; every thread stores the same value. */
static int route(void)
{
    static int use = -1;
    int u = __atomic_load_n(&use, __ATOMIC_RELAXED);
    if (u < 0) __atomic_store_n(&use, u = choose_route(), __ATOMIC_RELAXED);
    return u;
}

const char *cfpo_solver_name(void)
{
    return allowed_route() < 0 ? NULL : route_name[route()];
}

/* The AVX-512 or AVX2 solver (same bits, solver_avx512.c and
 * solver_avx2.c) or the plain one, over the first `cells` cells in the
 * hint's order. */
static double solve(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                    double floor2, double *cx, double *cy, double *scratch, int cells)
{
    if (cfpo_solve_observer) cfpo_solve_observer(yx, yy, m, skip, S, hx, hy, floor2);
    if (CFPO_SOLVER_AVX2) switch (route()) {
        case ROUTE_AVX512: return cfpo_solve_cells_avx512(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
        case ROUTE_AVX2: return cfpo_solve_cells_avx2(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
        default: break;
        }
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
