/* hull.c - the convex hull of a workspace's positions (the leaves of its
 * tree), as links from each hull vertex to the vertices before and after
 * it. A hull vertex's Voronoi cell is unbounded, so nothing bounds its
 * reach; but the cell lies between its bisectors with those two
 * neighbours, and that wedge, cut to a square, bounds the region from
 * above in a few operations (an_wedge_bound): on a set whose every point
 * is on the hull (points on a circle) most regions need no clipping. */
#include <math.h>
#include <stdlib.h>

#include "farthest_int.h"
#include "polygon.h"

/* (x, y, index) triples, by x, then y. */
static int by_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return p[1] < q[1] ? -1 : (p[1] > q[1]);
}

static double cross(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

void an_hull_links(an_far_ws *ws)
{
    size_t k = 0;
    double *t = ws->hbuf;
    for (size_t nd = 0; nd < ws->nodes_used; nd++) {
        const kd_node *n = &ws->nodes[nd];
        if (n->left >= 0) continue;
        for (size_t j = n->lo; j < n->hi; j++) {
            t[3 * k] = ws->x[j];
            t[3 * k + 1] = ws->y[j];
            t[3 * k + 2] = (double)j;
            k++;
        }
    }
    for (size_t j = 0; j < 2 * ws->cap; j++) ws->hull[j] = -1;
    ws->hull_ok = 1;
    if (k < 3) return;
    qsort(t, k, 3 * sizeof *t, by_xy);
    /* Andrew's monotone chain, strict turns: the lower hull left to right,
     * then the upper hull right to left, into h (indices into t). */
    size_t *h = (size_t *)(void *)ws->key; /* 2 cap doubles: room for 2 k + 1 indices */
    size_t m = 0;
    for (size_t i = 0; i < k; i++) {
        while (m >= 2 && cross(t + 3 * h[m - 2], t + 3 * h[m - 1], t + 3 * i) <= 0) m--;
        h[m++] = i;
    }
    for (size_t i = k - 1, lower = m + 1; i-- > 0;) {
        while (m >= lower && cross(t + 3 * h[m - 2], t + 3 * h[m - 1], t + 3 * i) <= 0) m--;
        h[m++] = i;
    }
    m--; /* the first point closes the chain */
    if (m < 3) return; /* collinear: no wedge bounds anything */
    for (size_t v = 0; v < m; v++) {
        const long me = (long)t[3 * h[v] + 2];
        ws->hull[2 * me] = (long)t[3 * h[(v + m - 1) % m] + 2];
        ws->hull[2 * me + 1] = (long)t[3 * h[(v + 1) % m] + 2];
    }
}

/* Keeps the side of polygon p (n vertices, into q) nearer a than b. */
static int keep_near(const double *p, int n, double *q, double ax, double ay, double bx, double by)
{
    double sd[16];
    const double nx = bx - ax, ny = by - ay, mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    for (int v = 0; v < n; v++) sd[v] = (p[2 * v] - mx) * nx + (p[2 * v + 1] - my) * ny;
    return an_clip_sd(p, n, q, sd);
}

double an_wedge_bound(const an_far_ws *ws, size_t i, const double *dom, int ndom)
{
    const long pv = ws->hull[2 * i], nx = ws->hull[2 * i + 1];
    if (!ws->hull_ok || pv < 0 || ndom > 8) return INFINITY;
    double a[32], b[32];
    const double ax = ws->x[i], ay = ws->y[i];
    int n = keep_near(dom, ndom, a, ax, ay, ws->x[pv], ws->y[pv]);
    n = keep_near(a, n, b, ax, ay, ws->x[nx], ws->y[nx]);
    double far2 = 0;
    for (int v = 0; v < n; v++) {
        const double dx = b[2 * v] - ax, dy = b[2 * v + 1] - ay;
        far2 = fmax(far2, dx * dx + dy * dy);
    }
    return far2 * (1 + 1e-9); /* above the rounding of the clipping */
}
