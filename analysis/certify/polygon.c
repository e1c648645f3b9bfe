/* polygon.c - see polygon.h. */
#include "polygon.h"

#include <math.h>
#include <string.h>

int an_clip_bisector(const double *p, int n, double *q, double *sd, double ax, double ay, double bx, double by)
{
    const double nx = bx - ax, ny = by - ay, mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    int out = 0;
    for (int v = 0; v < n; v++) {
        sd[v] = (p[2 * v] - mx) * nx + (p[2 * v + 1] - my) * ny;
        out |= sd[v] > 0;
    }
    return out ? an_clip_sd(p, n, q, sd) : -1;
}

double an_split_farthest(const double *P, int nv, const double *qx, const double *qy, size_t k, double *R,
                         double *U, double *sd, double *bx, double *by)
{
    double best = -1;
    double *const r0 = R, *const u0 = U;
    for (size_t a = 0; a < k; a++) {
        memcpy(R, P, 2 * (size_t)nv * sizeof *R);
        int nr = nv;
        for (size_t b = 0; b < k && nr > 0; b++) {
            if (b == a) continue;
            const int cut = an_clip_bisector(R, nr, U, sd, qx[a], qy[a], qx[b], qy[b]);
            if (cut < 0) continue;
            nr = cut;
            double *tmp = R; R = U; U = tmp;
        }
        for (int v = 0; v < nr; v++) {
            const double dx = R[2 * v] - qx[a], dy = R[2 * v + 1] - qy[a], e2 = dx * dx + dy * dy;
            if (e2 > best) { best = e2; *bx = R[2 * v]; *by = R[2 * v + 1]; }
        }
        R = r0;
        U = u0;
    }
    return best;
}

double an_touch_eps(const double *P, int nv, double x, double y)
{
    double ext = 0;
    for (int v = 0; v < nv; v++) {
        const double ax = fabs(P[2 * v] - x), ay = fabs(P[2 * v + 1] - y), e = ax > ay ? ax : ay;
        ext = e > ext ? e : ext;
    }
    return 1e-9 * (ext + 1e-300);
}

int an_touches(const double *P, int nv, double x, double y, double px, double py, double eps)
{
    const double nx = px - x, ny = py - y, mx = 0.5 * (px + x), my = 0.5 * (py + y);
    const double scale = sqrt(nx * nx + ny * ny);
    for (int v = 0; v < nv; v++)
        if ((P[2 * v] - mx) * nx + (P[2 * v + 1] - my) * ny >= -eps * scale) return 1;
    return 0;
}
