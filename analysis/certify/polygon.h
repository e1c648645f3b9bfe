/* polygon.h - the convex-polygon primitives of the certificate: a polygon
 * cut by a half-plane or by a bisector, a polygon split among a few points
 * (its farthest vertex from its point), and the touching test of a
 * bisector with a polygon. Polygons are arrays of (x, y) pairs, counter-
 * clockwise. A layer below their users (farthest.c, hull.c, lct.c,
 * vmax.c), which call nothing of one another through it. */
#ifndef AN_POLYGON_H
#define AN_POLYGON_H

#include <stddef.h>

/* The polygon p of n vertices cut to the side where the signed distances
 * sd[v] of its vertices are <= 0 (a half-plane), into q; the new count
 * (at most n + 1). Inline: the inner step of every region's clipping. */
static inline int an_clip_sd(const double *p, int n, double *q, const double *sd)
{
    int k = 0;
    for (int v = 0; v < n; v++) {
        const int u = v + 1 == n ? 0 : v + 1;
        if (sd[v] <= 0) { q[2 * k] = p[2 * v]; q[2 * k + 1] = p[2 * v + 1]; k++; }
        if ((sd[v] < 0 && sd[u] > 0) || (sd[v] > 0 && sd[u] < 0)) {
            const double t = sd[v] / (sd[v] - sd[u]);
            q[2 * k] = p[2 * v] + t * (p[2 * u] - p[2 * v]);
            q[2 * k + 1] = p[2 * v + 1] + t * (p[2 * u + 1] - p[2 * v + 1]);
            k++;
        }
    }
    return k;
}

/* Polygon p (n vertices) cut to the side of the bisector of a and b
 * nearer a, into q: the new count, or -1 when no vertex is cut off (q
 * untouched). sd: room for n values. */
int an_clip_bisector(const double *p, int n, double *q, double *sd, double ax, double ay, double bx, double by);

/* The convex polygon P (nv vertices) split among the k points (qx, qy)
 * (each point's part: P cut by its bisectors with the others): the
 * largest squared distance from a point to a vertex of its part, at
 * (*bx, *by), or -1 when every part is empty. R, U: room for polygons of
 * nv + k vertices; sd: for nv + k values. */
double an_split_farthest(const double *P, int nv, const double *qx, const double *qy, size_t k, double *R,
                         double *U, double *sd, double *bx, double *by);

/* The touching test of a bisector with a convex polygon P: eps = 1e-9 of
 * P's extent from (x, y), and whether the bisector of (x, y) and (px, py)
 * meets P within eps, (v - m).n >= -eps |n| at a vertex v. */
double an_touch_eps(const double *P, int nv, double x, double y);
int an_touches(const double *P, int nv, double x, double y, double px, double py, double eps);

#endif
