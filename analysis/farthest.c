/* farthest.c - see farthest.h. */
#include "farthest.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define GROW(p, n)                                                                                                     \
    do {                                                                                                               \
        void *q_ = realloc((p), (n) * sizeof *(p));                                                                    \
        if (!q_) return -1;                                                                                            \
        (p) = q_;                                                                                                      \
    } while (0)

static int reserve(an_far_ws *ws, size_t m)
{
    if (m <= ws->cap) return 0;
    size_t cap = ws->cap ? ws->cap : 256;
    while (cap < m) cap *= 2;
    GROW(ws->ux, cap);
    GROW(ws->uy, cap);
    GROW(ws->key, 2 * cap);
    GROW(ws->pa, 2 * (cap + 8));
    GROW(ws->pb, 2 * (cap + 8));
    GROW(ws->sd, cap + 8);
    GROW(ws->scratch, cfpo_solver_scratch(cap));
    ws->cap = cap;
    return 0;
}

static int reserve_cells(an_far_ws *ws, size_t cells)
{
    if (cells <= ws->cells_cap) return 0;
    GROW(ws->cell_start, cells + 1);
    ws->cells_cap = cells;
    return 0;
}

void an_far_free(an_far_ws *ws)
{
    free(ws->ux); free(ws->uy); free(ws->key);
    free(ws->pa); free(ws->pb); free(ws->sd); free(ws->scratch); free(ws->cell_start);
    memset(ws, 0, sizeof *ws);
}

static int by_pair(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return p[1] < q[1] ? -1 : (p[1] > q[1]);
}

/* The grid over the points' bounding box: G x G cells of side c from
 * (x0, y0). */
typedef struct {
    size_t G;
    double x0, y0, c;
} far_grid;

static size_t grid_coord(double v, double v0, double c, size_t G)
{
    const double t = (v - v0) / c;
    if (!(t > 0)) return 0;
    const size_t i = (size_t)t;
    return i >= G ? G - 1 : i;
}

static size_t cell_of(const far_grid *g, double x, double y)
{
    return grid_coord(y, g->y0, g->c, g->G) * g->G + grid_coord(x, g->x0, g->c, g->G);
}

static int before(double ax, double ay, double bx, double by) { return ax < bx || (ax == bx && ay < by); }

/* Sorts the points [lo, hi) of ux/uy by (x, y) and drops repeats; returns
 * the new end. Insertion sort: cells hold a few points, or many copies of
 * a few (already in order); qsort for a crowded cell of distinct points. */
static size_t sort_unique(an_far_ws *ws, size_t lo, size_t hi)
{
    double *x = ws->ux, *y = ws->uy;
    if (hi - lo > 32) {
        for (size_t t = lo; t < hi; t++) { ws->key[2 * t] = x[t]; ws->key[2 * t + 1] = y[t]; }
        qsort(ws->key + 2 * lo, hi - lo, 2 * sizeof *ws->key, by_pair);
        for (size_t t = lo; t < hi; t++) { x[t] = ws->key[2 * t]; y[t] = ws->key[2 * t + 1]; }
    } else {
        for (size_t t = lo + 1; t < hi; t++) {
            const double vx = x[t], vy = y[t];
            size_t u = t;
            while (u > lo && before(vx, vy, x[u - 1], y[u - 1])) { x[u] = x[u - 1]; y[u] = y[u - 1]; u--; }
            x[u] = vx;
            y[u] = vy;
        }
    }
    size_t k = lo;
    for (size_t t = lo; t < hi; t++)
        if (k == lo || x[t] != x[k - 1] || y[t] != y[k - 1]) { x[k] = x[t]; y[k] = y[t]; k++; }
    return k;
}

/* Buckets Y on the grid over its bounding box and keeps each distinct
 * position once (the distance to a set does not depend on how often a
 * position occurs): ux/uy cell by cell, cell_start the ranges. Returns
 * the count of distinct positions, or -1 (out of memory). */
static long grid_build(const double *yx, const double *yy, size_t m, an_far_ws *ws, far_grid *g)
{
    double x0 = yx[0], x1 = x0, y0 = yy[0], y1 = y0;
    for (size_t t = 1; t < m; t++) {
        if (yx[t] < x0) x0 = yx[t];
        if (yx[t] > x1) x1 = yx[t];
        if (yy[t] < y0) y0 = yy[t];
        if (yy[t] > y1) y1 = yy[t];
    }
    const double ext = x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0;
    size_t G = (size_t)sqrt((double)m / 2.0);
    if (G < 1 || !(ext > 0)) G = 1;
    g->G = G;
    g->x0 = x0;
    g->y0 = y0;
    g->c = ext > 0 ? ext / (double)G : 1;
    if (reserve_cells(ws, G * G) != 0) return -1;
    size_t *st = ws->cell_start;
    memset(st, 0, (G * G + 1) * sizeof *st);
    for (size_t t = 0; t < m; t++) st[cell_of(g, yx[t], yy[t]) + 1]++;
    for (size_t c = 0; c < G * G; c++) st[c + 1] += st[c];
    for (size_t t = 0; t < m; t++) {
        const size_t q = st[cell_of(g, yx[t], yy[t])]++;
        ws->ux[q] = yx[t];
        ws->uy[q] = yy[t];
    }
    /* st[c] is now the end of cell c: sort and squeeze each cell. */
    size_t k = 0, lo = 0;
    for (size_t c = 0; c < G * G; c++) {
        const size_t hi = st[c];
        const size_t first = k;
        for (size_t t = lo; t < hi; t++) { ws->ux[k + t - lo] = ws->ux[t]; ws->uy[k + t - lo] = ws->uy[t]; }
        k = sort_unique(ws, first, first + (hi - lo));
        st[c] = first;
        lo = hi;
    }
    st[G * G] = k;
    return (long)k;
}

/* Region of point i: the polygon in P (nv vertices), clipped by the other
 * points of the grid ring by ring. Returns the new count (0: nothing left
 * or abandoned), with *far2 its largest squared distance from point i. */
typedef struct {
    double *P, *Q, *sd;
    int nv;
    double far2;
} region;

static int clip_by(region *R, double ax, double ay, double bx, double by)
{
    const double nx = bx - ax, ny = by - ay;
    if (nx * nx + ny * ny >= 4 * R->far2) return 1; /* cannot cut */
    const double mx = 0.5 * (bx + ax), my = 0.5 * (by + ay);
    double smax = -INFINITY, smin = INFINITY;
    for (int v = 0; v < R->nv; v++) {
        const double s = (R->P[2 * v] - mx) * nx + (R->P[2 * v + 1] - my) * ny;
        R->sd[v] = s;
        if (s > smax) smax = s;
        if (s < smin) smin = s;
    }
    if (smax <= 0) return 1;
    if (smin > 0) { R->nv = 0; return 0; }
    int nn = 0;
    for (int v = 0; v < R->nv; v++) {
        const int w = v + 1 == R->nv ? 0 : v + 1;
        const double s0 = R->sd[v], s1 = R->sd[w];
        if (s0 <= 0) {
            R->Q[2 * nn] = R->P[2 * v];
            R->Q[2 * nn + 1] = R->P[2 * v + 1];
            nn++;
        }
        if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
            const double t = s0 / (s0 - s1);
            R->Q[2 * nn] = R->P[2 * v] + t * (R->P[2 * w] - R->P[2 * v]);
            R->Q[2 * nn + 1] = R->P[2 * v + 1] + t * (R->P[2 * w + 1] - R->P[2 * v + 1]);
            nn++;
        }
    }
    double *t = R->P;
    R->P = R->Q;
    R->Q = t;
    R->nv = nn;
    R->far2 = 0;
    for (int v = 0; v < nn; v++) {
        const double dx = R->P[2 * v] - ax, dy = R->P[2 * v + 1] - ay;
        const double d2 = dx * dx + dy * dy;
        if (d2 > R->far2) R->far2 = d2;
    }
    return nn > 0;
}

/* Clips point i's region by the points of the cells at Chebyshev ring r
 * around (ci, cj); 0 once it is empty or no farther than best. */
static int clip_ring(const an_far_ws *ws, const far_grid *g, size_t i, long ci, long cj, long r, region *R,
                     double best)
{
    const long G = (long)g->G;
    for (long cy = cj - r; cy <= cj + r; cy++) {
        if (cy < 0 || cy >= G) continue;
        const int edge = cy == cj - r || cy == cj + r;
        for (long cx = ci - r; cx <= ci + r; cx += edge || r == 0 ? 1 : 2 * r) {
            if (cx >= 0 && cx < G) {
                const size_t c = (size_t)(cy * G + cx);
                for (size_t j = ws->cell_start[c]; j < ws->cell_start[c + 1]; j++) {
                    if (j == i) continue;
                    if (!clip_by(R, ws->ux[i], ws->uy[i], ws->ux[j], ws->uy[j]) || R->far2 <= best) return 0;
                }
            }
        }
    }
    return 1;
}

typedef struct {
    cfpo_square S;
    double best, bx, by;
    int found;
} far_state;

/* Point i's region: S clipped by the other points, nearest rings first,
 * stopped when the next ring is too far to cut; its farthest vertex from
 * point i may raise the best. */
static void visit(const an_far_ws *ws, const far_grid *g, size_t i, far_state *F)
{
    const cfpo_square S = F->S;
    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    const double ax = ws->ux[i], ay = ws->uy[i];
    double ub = 0;
    for (int c = 0; c < 4; c++) {
        const double dx = corner[c][0] - ax, dy = corner[c][1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > ub) ub = d2;
    }
    if (ub <= F->best) return;
    region R = {ws->pa, ws->pb, ws->sd, 4, ub};
    for (int c = 0; c < 4; c++) { R.P[2 * c] = corner[c][0]; R.P[2 * c + 1] = corner[c][1]; }
    const long ci = (long)grid_coord(ax, g->x0, g->c, g->G), cj = (long)grid_coord(ay, g->y0, g->c, g->G);
    for (long r = 0; r <= (long)g->G; r++) {
        /* Every point of ring r >= 2 is at least (r - 1) c away (a cell of
         * slack for rounding): if that is twice the reach, none cuts. */
        if (r >= 2) {
            const double dr = (double)(r - 2) * g->c;
            if (dr * dr >= 4 * R.far2) break;
        }
        if (!clip_ring(ws, g, i, ci, cj, r, &R, F->best)) return;
    }
    for (int v = 0; v < R.nv; v++) {
        const double dx = R.P[2 * v] - ax, dy = R.P[2 * v + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > F->best) { F->best = d2; F->bx = R.P[2 * v]; F->by = R.P[2 * v + 1]; F->found = 1; }
    }
}

static double farthest_grid(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy,
                            double *cx, double *cy, an_far_ws *ws)
{
    far_grid g;
    if (grid_build(yx, yy, m, ws, &g) < 0) return -1;
    far_state F = {S, -1, 0.5 * (S.x0 + S.x1), 0.5 * (S.y0 + S.y1), 0};
    /* Points by rings of cells around the hint's cell: near the hint first,
     * so a good value is found early and prunes the rest. */
    const long G = (long)g.G;
    const long hi = (long)grid_coord(hx, g.x0, g.c, g.G), hj = (long)grid_coord(hy, g.y0, g.c, g.G);
    for (long r = 0; r <= G; r++)
        for (long cyy = hj - r; cyy <= hj + r; cyy++) {
            if (cyy < 0 || cyy >= G) continue;
            const int edge = cyy == hj - r || cyy == hj + r;
            for (long cxx = hi - r; cxx <= hi + r; cxx += edge || r == 0 ? 1 : 2 * r) {
                if (cxx < 0 || cxx >= G) continue;
                const size_t c = (size_t)(cyy * G + cxx);
                for (size_t i = ws->cell_start[c]; i < ws->cell_start[c + 1]; i++) visit(ws, &g, i, &F);
            }
        }
    if (!F.found) return -1;
    *cx = F.bx < S.x0 ? S.x0 : F.bx > S.x1 ? S.x1 : F.bx;
    *cy = F.by < S.y0 ? S.y0 : F.by > S.y1 ? S.y1 : F.by;
    return cfpo_min_dist2(*cx, *cy, yx, yy, (int)m, -1);
}

double an_farthest(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy, double *cx,
                   double *cy, an_far_ws *ws)
{
    if (m == 0) { /* as the core solver: nothing to be far from */
        *cx = 0.5 * (S.x0 + S.x1);
        *cy = 0.5 * (S.y0 + S.y1);
        return INFINITY;
    }
    if (m > (size_t)INT32_MAX / 4 || reserve(ws, m) != 0) return -1;
    if (m <= AN_FAR_SMALL) return cfpo_local_solve(yx, yy, (int)m, -1, S, hx, hy, -1, cx, cy, ws->scratch);
    return farthest_grid(yx, yy, m, S, hx, hy, cx, cy, ws);
}
