/* dens_solve.c - layer 2: the local solve under a density (dens_solve.h):
 * its plain route, and the choice between it and the AVX-512 route
 * (dens_solve_avx512.c), which gives the same bits. */
#include "dens_solve.h"

#include <math.h>
#include <string.h>

#include "dens_solve_impl.h"
#include "solver_simd.h"

double cfpo_dens_value(const double *yx, const double *yy, const double *yr, int k, double rc, double cx, double cy)
{
    double best = INFINITY;
    for (int j = 0; j < k; j++) {
        const double dx = cx - yx[j], dy = cy - yy[j];
        const double v = (dx * dx + dy * dy) * yr[j];
        if (v < best) best = v;
    }
    return best * rc;
}

int cfpo_dens_solve_plain(const double *yx, const double *yy, const double *yr, const double *w, int k,
                          cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                          double *cx, double *cy, double *f, double *scratch)
{
    const int vmax = k + 8;
    double *bufa = scratch, *bufb = bufa + 2 * (size_t)vmax, *tl = bufb + 3 * (size_t)vmax, *hl = tl + vmax;
    double best = floor_f; /* only a vertex above it counts: polygons and
                              evaluations that cannot beat it stop early */
    int found = 0;
    for (int i = 0; i < (k < DENS_CELLS ? k : DENS_CELLS); i++) {
        const double ax = yx[i], ay = yy[i], wi = w[i];
        double corner[4][2];
        double far2 = dens_corners(S, ax, ay, corner);
        /* f in y_i's polygon is at most qhi |c - y_i|^2 q_i */
        if (qhi * far2 * yr[i] <= best) continue;
        dens_lines(ax, ay, wi, yx, yy, w, k, tl, hl);
        double *poly = bufa, *next = bufb;
        memcpy(poly, corner, sizeof corner);
        int nv = 4, alive = 1;
        for (int j = 0; j < k && alive; j++) {
            if (j == i || hl[j] >= far2) continue; /* the line misses the polygon */
            const double nx = yx[j] - ax, ny = yy[j] - ay, mx = ax + tl[j] * nx, my = ay + tl[j] * ny;
            if (nv > DENS_BIG) break;
            const int nn = dens_cut(&poly, nv, mx, my, nx, ny, ax, ay, vmax, &next, &far2);
            if (nn < 0) continue;
            if (nn == 0) { alive = 0; break; }
            nv = nn;
            if (qhi * far2 * yr[i] <= best) alive = 0;
        }
        if (alive) found |= dens_eval(poly, poly + 1, 2, nv, i, yx, yy, yr, k, S, d, qhi, ox, oy, &best, cx, cy, dens_geo_plain);
    }
    *f = found ? best : -1;
    return found;
}

/* 1 where the AVX-512 route runs: the CPU has it and CFPO_SOLVER allows
 * it (the same choice as LocalCFPO's, geom.c). */
static int use_avx512(void)
{
    static int use = -1;
    int u = __atomic_load_n(&use, __ATOMIC_RELAXED);
    if (u < 0) {
        const char *r = cfpo_solver_name();
        u = r && strcmp(r, "avx512") == 0;
        __atomic_store_n(&use, u, __ATOMIC_RELAXED);
    }
    return u;
}

int cfpo_dens_solve(const double *yx, const double *yy, const double *yr, int k, cfpo_square S,
                    const cfpo_density *d, double qhi, double ox, double oy, double floor_f, double *cx, double *cy,
                    double *f, double *scratch)
{
    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) { /* nothing to keep away from: the box's centre */
        const double rc = cfpo_dens_local_q(d, ox, oy, *cx, *cy);
        *f = rc > 0 ? INFINITY : -1;
        return rc > 0;
    }
    double *w = scratch + 4 * ((size_t)k + 8); /* rho_j^(1/4), once */
    for (int j = 0; j < k; j++) w[j] = sqrt(yr[j]);
    return use_avx512() ? cfpo_dens_solve_avx512(yx, yy, yr, w, k, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch)
                        : cfpo_dens_solve_plain(yx, yy, yr, w, k, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch);
}
