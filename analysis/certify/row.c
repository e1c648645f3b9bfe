/* row.c - the farthest point of a square from points that all lie on one
 * horizontal or one vertical line (the same y, or the same x, to the
 * bit): a row of points, such as a line of them across the torus.
 *
 * The Voronoi regions of points on a line are the slabs between the
 * bisectors of neighbours along it, so the region of the point at a (in
 * sorted order) is [m_left, m_right] across the line, m the midpoints;
 * cut to the square it is a rectangle (or nothing), and its farthest
 * point from a is one of its corners. The answer is the largest of these.
 * Exact like the general solver, in one pass over the sorted row instead
 * of a region per point: on such a row the square's sides hold nearly
 * equal maxima, one per gap, so no point can be passed over and the
 * general solver clips every region. */
#include <math.h>
#include <stdlib.h>

#include "farthest_int.h"

static int cmp_double(const void *a, const void *b)
{
    const double p = *(const double *)a, q = *(const double *)b;
    return p < q ? -1 : p > q;
}

double an_farthest_row(const double *yx, const double *yy, size_t m, cfpo_square S, double *cx, double *cy,
                       double *tmp)
{
    if (m < 2) return -3;
    int axis; /* 0: the points share y (a horizontal row), 1: they share x */
    if (yy[1] == yy[0]) axis = 0;
    else if (yx[1] == yx[0]) axis = 1;
    else return -3;
    const double *along = axis ? yy : yx, *across = axis ? yx : yy;
    const double c = across[0];
    int sorted = 1;
    for (size_t t = 0; t < m; t++) {
        if (across[t] != c) return -3;
        tmp[t] = along[t];
        sorted &= t == 0 || tmp[t] >= tmp[t - 1];
    }
    if (!sorted) qsort(tmp, m, sizeof *tmp, cmp_double);
    /* The square in row coordinates: [a0, a1] along, [b0, b1] across. */
    const double a0 = axis ? S.y0 : S.x0, a1 = axis ? S.y1 : S.x1;
    const double b0 = axis ? S.x0 : S.y0, b1 = axis ? S.x1 : S.y1;
    const double db = c - b0 > b1 - c ? b0 : b1; /* the farther side across */
    double best = -1, ba = 0;
    size_t k = 0;
    for (size_t t = 0; t < m; t = k) {
        const double a = tmp[t];
        for (k = t + 1; k < m && tmp[k] == a; k++) {} /* repeats: one region */
        double lo = t > 0 ? 0.5 * (tmp[t - 1] + a) : -INFINITY, hi = k < m ? 0.5 * (a + tmp[k]) : INFINITY;
        lo = lo > a0 ? lo : a0;
        hi = hi < a1 ? hi : a1;
        if (lo > hi) continue;
        const double e = a - lo > hi - a ? lo : hi; /* the farther end along */
        const double d2 = (e - a) * (e - a) + (db - c) * (db - c);
        if (d2 > best) { best = d2; ba = e; }
    }
    if (best < 0) return -3;
    *cx = axis ? db : ba;
    *cy = axis ? ba : db;
    return cfpo_min_dist2(*cx, *cy, yx, yy, (int)m, -1);
}
