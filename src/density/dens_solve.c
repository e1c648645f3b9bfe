/* dens_solve.c - layer 2: the local solve under a density (dens_solve.h):
 * the choice between its plain route (dens_solve_plain.c), its AVX2 route
 * (dens_solve_avx2.c) and its AVX-512 route (dens_solve_avx512.c), which
 * give the same bits. */
#include "dens_solve.h"

#include <math.h>
#include <string.h>

#include "dens_clip.h"
#include "solver_simd.h"

/* The route that runs: 2 AVX-512, 1 AVX2, 0 plain, by what the CPU has
 * and CFPO_SOLVER allows (the same choice as LocalCFPO's, geom.c). */
int cfpo_dens_route(void)
{
    static int use = -1;
    int u = __atomic_load_n(&use, __ATOMIC_RELAXED);
    if (u < 0) {
        const char *r = cfpo_solver_name();
        u = r && strcmp(r, "avx512") == 0 ? 2 : r && strcmp(r, "avx2") == 0 ? 1 : 0;
        __atomic_store_n(&use, u, __ATOMIC_RELAXED);
    }
    return u;
}

double cfpo_dens_value(const double *yx, const double *yy, const double *yr, int k, double rc, double cx, double cy)
{
    switch (cfpo_dens_route()) {
        case 2: return cfpo_dens_value_avx512(yx, yy, yr, k, rc, cx, cy);
        case 1: return cfpo_dens_value_avx2(yx, yy, yr, k, rc, cx, cy);
        default: return cfpo_dens_value_plain(yx, yy, yr, k, rc, cx, cy);
    }
}

int cfpo_dens_solve(const double *yx, const double *yy, const double *yr, int k, int cells, cfpo_square S,
                    const cfpo_density *d, double qhi, double ox, double oy, double floor_f, double *cx, double *cy,
                    double *f, double *scratch)
{
    return cfpo_dens_solve_from(yx, yy, yr, k, 0, cells, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch);
}

int cfpo_dens_solve_from(const double *yx, const double *yy, const double *yr, int k, int from, int cells,
                         cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                         double *cx, double *cy, double *f, double *scratch)
{
    const int m = cells < k ? cells : k;
    int i0 = from < m ? from : m, found0 = 0;
    double best = floor_f;
    if (i0 > 0 && *f > floor_f) { /* the polygons before `from` gave (*cx, *cy) */
        best = *f;
        found0 = 1;
    } else {
        *cx = 0.5 * (S.x0 + S.x1);
        *cy = 0.5 * (S.y0 + S.y1);
    }
    if (k == 0) { /* nothing to keep away from: the box's centre */
        const double rc = cfpo_dens_local_q(d, ox, oy, *cx, *cy);
        *f = rc > 0 ? INFINITY : -1;
        return rc > 0;
    }
    double *w = scratch + 4 * ((size_t)k + 8); /* rho_j^(1/4), once */
    for (int j = 0; j < k; j++) w[j] = sqrt(yr[j]);
    switch (cfpo_dens_route()) {
        case 2: return cfpo_dens_solve_avx512(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, best, cx, cy, f, scratch);
        case 1: return cfpo_dens_solve_avx2(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, best, cx, cy, f, scratch);
        default: return cfpo_dens_solve_plain(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, best, cx, cy, f, scratch);
    }
}
