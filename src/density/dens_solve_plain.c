/* dens_solve_plain.c - layer 2: the density solve's plain route and the
 * plain value of f at a spot
 * (dens_clip.h has the pieces both routes share). */
#include <math.h>
#include <string.h>

#include "dens_clip.h"

int cfpo_dens_solve_plain(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                          cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                          double *cx, double *cy, double *f, double *scratch)
{
    const int vmax = k + 8;
    double *bufa = scratch, *bufb = bufa + 2 * (size_t)vmax, *tl = bufb + 3 * (size_t)vmax, *hl = tl + vmax;
    double best = floor_f; /* only a vertex above it counts: polygons and
                              evaluations that cannot beat it stop early */
    int found = found0;
    for (int i = i0; i < m; i++) {
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

double cfpo_dens_value_plain(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                             double cy)
{
    double best = INFINITY;
    for (int j = 0; j < k; j++) {
        const double dx = cx - yx[j], dy = cy - yy[j];
        const double v = (dx * dx + dy * dy) * yr[j];
        if (v < best) best = v;
    }
    return best * rc;
}
