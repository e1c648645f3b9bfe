/* dens_solve.c - layer 2: the local solve under a density (dens_solve.h). */
#include "dens_solve.h"

#define CELLS 10 /* the polygons of the CELLS nearest neighbours (given nearest first) */

#include <math.h>

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

int cfpo_dens_solve(const double *yx, const double *yy, const double *yr, int k, cfpo_square S,
                    const cfpo_density *d, double ox, double oy, double floor_f, double *cx, double *cy, double *f,
                    double *scratch)
{
    const size_t cap = 2 * ((size_t)k + 8);
    double *bufa = scratch, *bufb = bufa + cap;
    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    double best = floor_f; /* only a vertex above it counts: polygons and
                              evaluations that cannot beat it stop early */
    int found = 0;
    const double qmax = sqrt(d->rho_max);
    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) { /* nothing to keep away from: the box's centre */
        const double rc = cfpo_dens_local_q(d, ox, oy, *cx, *cy);
        *f = rc > 0 ? INFINITY : -1;
        return rc > 0;
    }
    double *w = bufb + cap; /* rho_j^(1/4), once */
    for (int j = 0; j < k; j++) w[j] = sqrt(yr[j]);
    for (int i = 0; i < (k < CELLS ? k : CELLS); i++) {
        const double ax = yx[i], ay = yy[i], wi = w[i];
        double *poly = bufa, *next = bufb;
        int nv = 4;
        double far2 = 0;
        for (int c = 0; c < 4; c++) {
            poly[2 * c] = corner[c][0];
            poly[2 * c + 1] = corner[c][1];
            const double dx = corner[c][0] - ax, dy = corner[c][1] - ay;
            if (dx * dx + dy * dy > far2) far2 = dx * dx + dy * dy;
        }
        /* f in y_i's polygon is at most q_max |c - y_i|^2 q_i */
        if (qmax * far2 * yr[i] <= best) continue;
        int alive = 1;
        for (int j = 0; j < k && alive; j++) {
            if (j == i) continue;
            const double nx = yx[j] - ax, ny = yy[j] - ay, wj = w[j];
            const double t = wj / (wi + wj), n2 = nx * nx + ny * ny;
            if (t * t * n2 >= far2) continue; /* the line misses the polygon */
            const double mx = ax + t * nx, my = ay + t * ny;
            double smax = -INFINITY, smin = INFINITY, sd[64];
            if (nv > 64) break;
            for (int v = 0; v < nv; v++) {
                const double s = (poly[2 * v] - mx) * nx + (poly[2 * v + 1] - my) * ny;
                sd[v] = s;
                if (s > smax) smax = s;
                if (s < smin) smin = s;
            }
            if (smax <= 0) continue;
            if (smin > 0) { alive = 0; break; }
            int nn = 0;
            far2 = 0;
            for (int v = 0; v < nv && nn + 2 <= (int)(cap / 2); v++) {
                const int w = v + 1 == nv ? 0 : v + 1;
                const double s0 = sd[v], s1 = sd[w];
                if (s0 <= 0) {
                    next[2 * nn] = poly[2 * v];
                    next[2 * nn + 1] = poly[2 * v + 1];
                    nn++;
                }
                if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
                    const double tt = s0 / (s0 - s1);
                    next[2 * nn] = poly[2 * v] + tt * (poly[2 * w] - poly[2 * v]);
                    next[2 * nn + 1] = poly[2 * v + 1] + tt * (poly[2 * w + 1] - poly[2 * v + 1]);
                    nn++;
                }
            }
            for (int v = 0; v < nn; v++) {
                const double dx = next[2 * v] - ax, dy = next[2 * v + 1] - ay;
                if (dx * dx + dy * dy > far2) far2 = dx * dx + dy * dy;
            }
            double *tmp = poly;
            poly = next;
            next = tmp;
            nv = nn;
            if (nv == 0 || qmax * far2 * yr[i] <= best) alive = 0;
        }
        if (!alive) continue;
        for (int v = 0; v < nv; v++) {
            double px = poly[2 * v], py = poly[2 * v + 1];
            if (px < S.x0) px = S.x0;
            if (px > S.x1) px = S.x1;
            if (py < S.y0) py = S.y0;
            if (py > S.y1) py = S.y1;
            /* min_j |c - y_j|^2 q_j first, abandoned as soon as even the
             * largest q(c) cannot lift it above best (the pixel's q, a
             * memory access, only for vertices that may win); then f =
             * that min times q(c): rounding is monotone, so it is the
             * min of the products, bit for bit */
            double geo = INFINITY;
            for (int j = 0; j < k && geo * qmax > best; j++) {
                const double dx = px - yx[j], dy = py - yy[j];
                const double v = (dx * dx + dy * dy) * yr[j];
                if (v < geo) geo = v;
            }
            if (!(geo * qmax > best)) continue;
            const double rc = cfpo_dens_local_q(d, ox, oy, px, py);
            if (!(rc > 0)) continue;
            const double val = geo * rc;
            if (val > best) {
                best = val;
                *cx = px;
                *cy = py;
                found = 1;
            }
        }
    }
    *f = found ? best : -1;
    return found;
}
