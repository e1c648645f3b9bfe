/* farsub.c - the farthest point of a square from many points, tried first
 * on a few of them.
 *
 * For Q a subset of the points Y, d(p, Q) >= d(p, Y) everywhere, so the
 * farthest point u of S from Q (found exactly by the core's solver, Q being
 * small) bounds the answer from above: max_S d(., Y) <= d(u, Q). If no
 * point of Y is nearer to u than Q is, d(u, Y) = d(u, Q) is reached, so it
 * is the answer. Otherwise the point of Y nearest to u joins Q and the
 * solve is repeated, a few times at most.
 *
 * Q starts with the points nearest to S's corners, the middles of its
 * sides and the hint. Where Y is a line of points through the square (a
 * neighbourhood of a point of a segment), the answer is at a corner or
 * near the hint, and these few points already decide it: one small solve
 * and a scan of Y, instead of a region for each of Y's points. */
#include <math.h>

#include "farthest_int.h"

#define SUB_MAX 24  /* points in Q at most */
#define SUB_ROUNDS 3 /* solves at most */

/* Index of the point of Y nearest to (px, py) (the first of equals). */
static size_t nearest(const double *yx, const double *yy, size_t m, double px, double py, double *d2)
{
    size_t arg = 0;
    double best = INFINITY;
    for (size_t t = 0; t < m; t++) {
        const double dx = yx[t] - px, dy = yy[t] - py, e2 = dx * dx + dy * dy;
        if (e2 < best) { best = e2; arg = t; }
    }
    *d2 = best;
    return arg;
}

void an_nearest_each(const double *yx, const double *yy, size_t m, const double (*probe)[2], int k, size_t *arg)
{
    double pd[AN_NEAREST_EACH];
    for (int j = 0; j < k; j++) { pd[j] = INFINITY; arg[j] = 0; }
    for (size_t t = 0; t < m; t++) {
        const double x = yx[t], y = yy[t];
        for (int j = 0; j < k; j++) {
            const double dx = x - probe[j][0], dy = y - probe[j][1], e2 = dx * dx + dy * dy;
            if (e2 < pd[j]) { pd[j] = e2; arg[j] = t; }
        }
    }
}

/* Adds point t of Y to Q unless its position is there already: 1 if added. */
static int add(double *qx, double *qy, int *q, double x, double y)
{
    for (int k = 0; k < *q; k++)
        if (qx[k] == x && qy[k] == y) return 0;
    qx[*q] = x;
    qy[*q] = y;
    (*q)++;
    return 1;
}

double an_farthest_sub(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy, double *cx,
                       double *cy, double *scratch)
{
    double qx[SUB_MAX], qy[SUB_MAX], d2;
    int q = 0;
    const double mx = 0.5 * (S.x0 + S.x1), my = 0.5 * (S.y0 + S.y1);
    const double probe[9][2] = {{hx, hy},   {S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1},
                                {mx, S.y0}, {S.x1, my},   {mx, S.y1},   {S.x0, my}};
    size_t parg[9];
    an_nearest_each(yx, yy, m, probe, 9, parg);
    for (int k = 0; k < 9; k++) add(qx, qy, &q, yx[parg[k]], yy[parg[k]]);
    for (int round = 0; round < SUB_ROUNDS; round++) {
        double ux, uy;
        const double r2 = cfpo_local_solve(qx, qy, q, -1, S, hx, hy, -1, &ux, &uy, scratch);
        if (!(r2 >= 0) || r2 == INFINITY) return -3;
        const size_t t = nearest(yx, yy, m, ux, uy, &d2);
        if (d2 == cfpo_min_dist2(ux, uy, qx, qy, q, -1)) {
            *cx = ux;
            *cy = uy;
            return cfpo_min_dist2(ux, uy, yx, yy, (int)m, -1);
        }
        if (q == SUB_MAX || !add(qx, qy, &q, yx[t], yy[t])) return -3;
    }
    return -3;
}
