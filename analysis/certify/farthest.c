/* farthest.c - see farthest.h. */
#include "farthest.h"
#include "farthest_int.h"
#include "polygon.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>


#define KD_LEAF 8

int an_far_reserve(an_far_ws *ws, size_t m)
{
    if (m <= ws->cap) return 0;
    size_t cap = ws->cap ? ws->cap : 256;
    while (cap < m) cap *= 2;
    GROW(ws->x, cap);
    GROW(ws->y, cap);
    GROW(ws->key, 2 * cap);
    GROW(ws->fx, cap);
    GROW(ws->fy, cap);
    GROW(ws->pa, 2 * (cap + 8));
    GROW(ws->pb, 2 * (cap + 8));
    GROW(ws->sd, cap + 8);
    GROW(ws->scratch, cfpo_solver_scratch(cap));
    GROW(ws->nodes, 2 * cap + 1);
    GROW(ws->hull, 2 * cap);
    GROW(ws->hbuf, 3 * cap);
    ws->hull_ok = 0;
    ws->cap = cap;
    return 0;
}

void an_far_free(an_far_ws *ws)
{
    free(ws->x); free(ws->y); free(ws->key); free(ws->fx); free(ws->fy); free(ws->pa); free(ws->pb); free(ws->sd); free(ws->scratch);
    free(ws->nodes); free(ws->hull); free(ws->hbuf);
    memset(ws, 0, sizeof *ws);
}

int an_cmp_pair(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return p[1] < q[1] ? -1 : (p[1] > q[1]);
}

/* Drops repeated positions from [lo, hi), keeping the first of each;
 * returns the new end. Sorts first unless the range is small. */
static size_t sort_unique(an_far_ws *ws, size_t lo, size_t hi)
{
    double *x = ws->x, *y = ws->y, *key = ws->key;
    if (hi - lo <= 2 * KD_LEAF) {
        size_t k = lo;
        for (size_t t = lo; t < hi; t++) {
            size_t u = lo;
            while (u < k && (x[u] != x[t] || y[u] != y[t])) u++;
            if (u == k) { x[k] = x[t]; y[k] = y[t]; k++; }
        }
        return k;
    }
    for (size_t t = lo; t < hi; t++) { key[2 * t] = x[t]; key[2 * t + 1] = y[t]; }
    qsort(key + 2 * lo, hi - lo, 2 * sizeof *key, an_cmp_pair);
    size_t k = lo;
    for (size_t t = lo; t < hi; t++)
        if (k == lo || key[2 * t] != x[k - 1] || key[2 * t + 1] != y[k - 1]) { x[k] = key[2 * t]; y[k] = key[2 * t + 1]; k++; }
    return k;
}

/* The tree over x/y[lo, hi): split at the middle of the wider side of the
 * bounding box (so a cluster gets depth where it needs it). A leaf keeps
 * each position once (the distance to a set does not depend on how often
 * a position occurs); equal positions always fall on the same side. */
long an_kd_build(an_far_ws *ws, size_t lo, size_t hi, int depth)
{
    double *x = ws->x, *y = ws->y;
    const long id = (long)ws->nodes_used++;
    kd_node nd = {x[lo], y[lo], x[lo], y[lo], lo, hi, -1, -1};
    for (size_t t = lo + 1; t < hi; t++) {
        if (x[t] < nd.x0) nd.x0 = x[t];
        if (x[t] > nd.x1) nd.x1 = x[t];
        if (y[t] < nd.y0) nd.y0 = y[t];
        if (y[t] > nd.y1) nd.y1 = y[t];
    }
    if (nd.x0 == nd.x1 && nd.y0 == nd.y1) { /* one position, perhaps repeated */
        nd.hi = lo + 1;
        ws->nodes[id] = nd;
        return id;
    }
    size_t split = lo;
    if (hi - lo > KD_LEAF && depth < KD_DEPTH) {
        const int ax = nd.x1 - nd.x0 >= nd.y1 - nd.y0;
        double *v = ax ? x : y;
        const double mid = ax ? nd.x0 + 0.5 * (nd.x1 - nd.x0) : nd.y0 + 0.5 * (nd.y1 - nd.y0);
        size_t a = lo, b = hi;
        while (a < b) {
            if (v[a] < mid) { a++; continue; }
            b--;
            const double tx = x[a], ty = y[a];
            x[a] = x[b]; y[a] = y[b];
            x[b] = tx; y[b] = ty;
        }
        split = a;
    }
    if (split == lo || split == hi) {
        nd.hi = sort_unique(ws, lo, hi);
        ws->nodes[id] = nd;
        return id;
    }
    ws->nodes[id] = nd;
    const long left = an_kd_build(ws, lo, split, depth + 1);
    const long right = an_kd_build(ws, split, hi, depth + 1);
    ws->nodes[id].left = left;
    ws->nodes[id].right = right;
    return id;
}

/* Squared distance from (ax, ay) to a node's box, rounded down a little
 * (the box's sides are its points' own coordinates). */
double an_kd_box_d2(const kd_node *n, double ax, double ay)
{
    const double dx = ax < n->x0 ? n->x0 - ax : ax > n->x1 ? ax - n->x1 : 0;
    const double dy = ay < n->y0 ? n->y0 - ay : ay > n->y1 ? ay - n->y1 : 0;
    return (dx * dx + dy * dy) * (1 - 1e-12);
}

/* Clips the region by the bisector of (ax, ay) and (bx, by), keeping the
 * side of a: 0 when nothing is left. */
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
    const int nn = an_clip_sd(R->P, R->nv, R->Q, R->sd);
    double *t = R->P;
    R->P = R->Q;
    R->Q = t;
    R->nv = nn;
    R->far2 = 0;
    for (int v = 0; v < nn; v++) {
        const double dx = R->P[2 * v] - ax, dy = R->P[2 * v + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > R->far2) R->far2 = d2;
    }
    return nn > 0;
}

/* Pushes the children of node n, the nearer to (ax, ay) on top. */
static void push_children(const kd_node *N, const kd_node *n, double ax, double ay, long *stack, int *sp)
{
    const double dl = an_kd_box_d2(&N[n->left], ax, ay), dr = an_kd_box_d2(&N[n->right], ax, ay);
    stack[(*sp)++] = dl <= dr ? n->right : n->left;
    stack[(*sp)++] = dl <= dr ? n->left : n->right;
}

/* Whether box n can hold a point y whose bisector with a cuts the region:
 * (v - m).n = (|v - a|^2 - |v - y|^2) / 2 is linear in v, so such a y has
 * |v - y| < |v - a| at a vertex v. A far vertex's disk bulges into a
 * cluster only by a thin sliver, so the wide regions of a cluster's rim
 * pass over the rest of it. */
static int can_cut(const region *R, const kd_node *n, double ax, double ay)
{
    for (int v = 0; v < R->nv; v++) {
        const double vx = R->P[2 * v], vy = R->P[2 * v + 1], dx = vx - ax, dy = vy - ay;
        if (an_kd_box_d2(n, vx, vy) < (dx * dx + dy * dy) * (1 + 1e-9)) return 1;
    }
    return 0;
}

int an_clip_region(const an_far_ws *ws, size_t i, size_t excl, region *R, double best)
{
    const kd_node *N = ws->nodes;
    const double ax = ws->x[i], ay = ws->y[i];
    long stack[2 * KD_DEPTH + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const kd_node *n = &N[stack[--sp]];
        if (an_kd_box_d2(n, ax, ay) >= 4 * R->far2 || !can_cut(R, n, ax, ay)) continue;
        if (n->left >= 0) { push_children(N, n, ax, ay, stack, &sp); continue; }
        for (size_t j = n->lo; j < n->hi; j++) {
            if (j == i || j == excl) continue;
            if (!clip_by(R, ax, ay, ws->x[j], ws->y[j]) || R->far2 <= best) return 0;
        }
    }
    return 1;
}

typedef struct {
    const double *dom; /* the square searched, its corners CCW */
    int ndom;
    double best, bx, by;
    int found;
    double oct[16]; /* a convex polygon inside the points' hull, CCW */
    int noct;
    double edge[24]; /* its edges' inward unit normals and offsets */
    double w2;      /* the squared diameter of the points' box */
    int flat;       /* the octagon has no area: the points lie on a line */
} far_state;

/* The octagon's edges as inward unit normals (nx, ny) and offsets c: the
 * distance of a point inside from an edge's line is nx x + ny y - c. */
static void octagon_edges(far_state *F)
{
    for (int e = 0; e < F->noct; e++) {
        const int f = e + 1 == F->noct ? 0 : e + 1;
        const double ex = F->oct[2 * f] - F->oct[2 * e], ey = F->oct[2 * f + 1] - F->oct[2 * e + 1];
        const double len = sqrt(ex * ex + ey * ey);
        F->edge[3 * e] = -ey / len;
        F->edge[3 * e + 1] = ex / len;
        F->edge[3 * e + 2] = F->edge[3 * e] * F->oct[2 * e] + F->edge[3 * e + 1] * F->oct[2 * e + 1];
    }
}

/* The points extreme in the eight directions of 45-degree steps, in
 * counter-clockwise order (repeats dropped): a convex polygon inside the
 * convex hull of the points. */
static void octagon(const double *yx, const double *yy, size_t m, far_state *F)
{
    static const double dir[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    double x0 = yx[0], x1 = x0, y0 = yy[0], y1 = y0;
    size_t arg[8] = {0};
    double top[8];
    for (int d = 0; d < 8; d++) top[d] = dir[d][0] * yx[0] + dir[d][1] * yy[0];
    for (size_t t = 1; t < m; t++) {
        if (yx[t] < x0) x0 = yx[t];
        if (yx[t] > x1) x1 = yx[t];
        if (yy[t] < y0) y0 = yy[t];
        if (yy[t] > y1) y1 = yy[t];
        for (int d = 0; d < 8; d++) {
            const double v = dir[d][0] * yx[t] + dir[d][1] * yy[t];
            if (v > top[d]) { top[d] = v; arg[d] = t; }
        }
    }
    F->w2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
    F->noct = 0;
    for (int d = 0; d < 8; d++) {
        const double px = yx[arg[d]], py = yy[arg[d]];
        if (F->noct > 0 && px == F->oct[2 * F->noct - 2] && py == F->oct[2 * F->noct - 1]) continue;
        if (F->noct > 0 && px == F->oct[0] && py == F->oct[1]) continue;
        F->oct[2 * F->noct] = px;
        F->oct[2 * F->noct + 1] = py;
        F->noct++;
    }
    octagon_edges(F);
    double area2 = 0; /* twice the octagon's area: about 0 on a line of points */
    for (int e = 0; e < F->noct; e++) {
        const int f = e + 1 == F->noct ? 0 : e + 1;
        area2 += F->oct[2 * e] * F->oct[2 * f + 1] - F->oct[2 * f] * F->oct[2 * e + 1];
    }
    F->flat = !(fabs(area2) > 1e-9 * F->w2);
}

/* How deep (ax, ay) lies inside the octagon: its least distance to an
 * edge's line, negative outside; -1 for a polygon of fewer than 3. */
static double depth(const far_state *F, double ax, double ay)
{
    if (F->noct < 3) return -1;
    double dmin = INFINITY;
    for (int e = 0; e < F->noct; e++) {
        const double d = F->edge[3 * e] * ax + F->edge[3 * e + 1] * ay - F->edge[3 * e + 2];
        if (d < dmin) dmin = d;
    }
    return dmin;
}

/* 1 when point (ax, ay)'s region cannot reach sqrt(best). If a point p
 * of the region lies at t > rho = sqrt(best) from it, the open disk of
 * radius t around p holds no point, so with u = (p - a) / t every point j
 * has (j - a).u <= |j - a|^2 / (2 t) < W^2 / (2 rho) = sigma (W the
 * points' diameter): the whole hull lies below that line, and a is less
 * than sigma deep inside it. A point deeper than sigma inside the octagon
 * (inside the hull) is deeper in the hull: its region stays within rho. */
static int deep_inside(const far_state *F, double ax, double ay)
{
    if (!(F->best > 0)) return 0;
    const double sigma = F->w2 / (2 * sqrt(F->best));
    return depth(F, ax, ay) > sigma * (1 + 1e-9) + 1e-12 * sqrt(F->w2);
}

/* Point i's region in the domain; its farthest vertex may raise the
 * best. */
static void visit(const an_far_ws *ws, size_t i, far_state *F)
{
    const double *corner = F->dom;
    const int nc = F->ndom;
    const double ax = ws->x[i], ay = ws->y[i];
    double ub = 0;
    for (int c = 0; c < nc; c++) {
        const double dx = corner[2 * c] - ax, dy = corner[2 * c + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > ub) ub = d2;
    }
    if (ub <= F->best) return;
    if (deep_inside(F, ax, ay)) return;
    if (an_wedge_bound(ws, i, corner, nc) <= F->best) return;
    region R = {ws->pa, ws->pb, ws->sd, nc, ub};
    memcpy(R.P, corner, 2 * (size_t)nc * sizeof *corner);
    if (!an_clip_region(ws, i, (size_t)-1, &R, F->best)) return;
    for (int v = 0; v < R.nv; v++) {
        const double dx = R.P[2 * v] - ax, dy = R.P[2 * v + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > F->best) { F->best = d2; F->bx = R.P[2 * v]; F->by = R.P[2 * v + 1]; F->found = 1; }
    }
}

/* The regions of the k points in x/y (copied in), on a tree, raising F. */
static void solve_on(an_far_ws *ws, size_t k, far_state *F)
{
    ws->nodes_used = 0;
    an_kd_build(ws, 0, k, 0);
    ws->hull_ok = 0;
    if (!F->flat) an_hull_links(ws); /* else the points lie on a line: no wedge */
    /* The leaves in tree order; a box whose four corners are deep inside
     * the hull holds only such points (depth is a minimum of linear
     * functions, least at a corner of a box): it is passed over whole. */
    long stack[2 * KD_DEPTH + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const kd_node *n = &ws->nodes[stack[--sp]];
        if (deep_inside(F, n->x0, n->y0) && deep_inside(F, n->x1, n->y0) && deep_inside(F, n->x0, n->y1) &&
            deep_inside(F, n->x1, n->y1))
            continue;
        if (n->left < 0) {
            for (size_t i = n->lo; i < n->hi; i++) visit(ws, i, F);
            continue;
        }
        stack[sp++] = n->right;
        stack[sp++] = n->left;
    }
}

/* The answer, kept inside the square's sides against rounding. */
static void clamp_to(const cfpo_square *S, const far_state *F, double *cx, double *cy)
{
    *cx = F->bx < S->x0 ? S->x0 : F->bx > S->x1 ? S->x1 : F->bx;
    *cy = F->by < S->y0 ? S->y0 : F->by > S->y1 ? S->y1 : F->by;
}

/* First on the points that are not deep inside the hull (the band R, the
 * hull's vertices among them): the answer U over R bounds the answer over
 * all points from above (fewer points, larger distances), and if no deep
 * point is nearer to U's point than R is, U is reached over all points
 * too: it is the answer. In exact arithmetic a deep point never is (deep
 * points exist only when the diameter W < rho; a disk of radius >= rho
 * free of the hull's vertices holds none of the hull deeper than
 * W^2 / (2 rho), the sagitta of a chord of length W), so the whole set is
 * solved again only as a guard against rounding. */
/* The points of (yx, yy) that may be the nearest to some point of S,
 * into ws->fx/fy: their count. A guard g (a point nearest to a corner of
 * S or its centre) nearer than y to all four corners of S is nearer to
 * every point of S (the points nearer to g than to y form a half-plane),
 * so y is never the nearest there and its region misses S (a small square
 * far from a line of points: all but the stretch of the line facing it). */
static size_t near_square(const double *yx, const double *yy, size_t m, const cfpo_square *S, an_far_ws *ws)
{
    const double probe[5][2] = {{S->x0, S->y0}, {S->x1, S->y0}, {S->x1, S->y1}, {S->x0, S->y1},
                                {0.5 * (S->x0 + S->x1), 0.5 * (S->y0 + S->y1)}};
    size_t guard[5];
    an_nearest_each(yx, yy, m, probe, 5, guard);
    double g2[5][4]; /* squared distances from each guard to each corner, raised against rounding */
    for (int k = 0; k < 5; k++)
        for (int c = 0; c < 4; c++) {
            const double dx = yx[guard[k]] - probe[c][0], dy = yy[guard[k]] - probe[c][1];
            g2[k][c] = (dx * dx + dy * dy) * (1 + 1e-9) + 1e-300;
        }
    size_t n = 0;
    for (size_t t = 0; t < m; t++) {
        double d2[4];
        for (int c = 0; c < 4; c++) {
            const double dx = yx[t] - probe[c][0], dy = yy[t] - probe[c][1];
            d2[c] = dx * dx + dy * dy;
        }
        int dominated = 0;
        for (int k = 0; k < 5 && !dominated; k++)
            dominated = g2[k][0] < d2[0] && g2[k][1] < d2[1] && g2[k][2] < d2[2] && g2[k][3] < d2[3];
        if (dominated) continue;
        ws->fx[n] = yx[t];
        ws->fy[n] = yy[t];
        n++;
    }
    return n;
}

static double farthest_tree(const double *ax, const double *ay, size_t am, const cfpo_square *Sq, double *cx,
                            double *cy, an_far_ws *ws)
{
    /* Solved on the points that may be nearest in the square: the same
     * distances to the set everywhere in it. */
    const size_t m = near_square(ax, ay, am, Sq, ws);
    const double *yx = ws->fx, *yy = ws->fy;
    const double dom[8] = {Sq->x0, Sq->y0, Sq->x1, Sq->y0, Sq->x1, Sq->y1, Sq->x0, Sq->y1};
    const int ndom = 4;
    far_state F = {dom, ndom, -1, 0.5 * (Sq->x0 + Sq->x1), 0.5 * (Sq->y0 + Sq->y1), 0, {0}, 0, {0}, 0, 0};
    octagon(yx, yy, m, &F);
    /* The corners of the domain are in it: the farthest of them from the
     * points is a value the answer reaches, known before any region is
     * clipped. */
    for (int c = 0; c < ndom; c++) {
        const double d2 = cfpo_min_dist2(dom[2 * c], dom[2 * c + 1], yx, yy, (int)m, -1);
        if (d2 > F.best) { F.best = d2; F.bx = dom[2 * c]; F.by = dom[2 * c + 1]; F.found = 1; }
    }
    const far_state F0 = F;
    size_t k = 0;
    for (size_t t = 0; t < m; t++)
        if (!deep_inside(&F0, yx[t], yy[t])) { ws->x[k] = yx[t]; ws->y[k] = yy[t]; k++; }
    if (k < m) {
        if (k > 0) solve_on(ws, k, &F);
        if (!F.found) return -1;
        clamp_to(Sq, &F, cx, cy);
        /* x/y[0, k) still hold only band points (the tree reorders them
         * and its leaves drop repeats, leaving copies of band points). */
        const double d_all = cfpo_min_dist2(*cx, *cy, yx, yy, (int)m, -1);
        const double d_band = k > 0 ? cfpo_min_dist2(*cx, *cy, ws->x, ws->y, (int)k, -1) : INFINITY;
        if (k == 0 || d_band == d_all) return d_all; /* k = 0: every region is within the corner's value */
        F = F0;
    }
    memcpy(ws->x, yx, m * sizeof *yx);
    memcpy(ws->y, yy, m * sizeof *yy);
    solve_on(ws, m, &F);
    if (!F.found) return -1;
    clamp_to(Sq, &F, cx, cy);
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
    if (m > (size_t)INT32_MAX / 4 || an_far_reserve(ws, m) != 0) return -1;
    if (m <= AN_FAR_SMALL) return cfpo_local_solve(yx, yy, (int)m, -1, S, hx, hy, -1, cx, cy, ws->scratch);
    const double r2 = an_farthest_quick(yx, yy, m, S, hx, hy, cx, cy, ws->scratch);
    if (r2 != -3) return r2;
    return farthest_tree(yx, yy, m, &S, cx, cy, ws);
}

double an_farthest_whole(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy,
                         double *cx, double *cy, an_far_ws *ws)
{
    if (m <= AN_FAR_SMALL) return an_farthest(yx, yy, m, S, hx, hy, cx, cy, ws);
    if (m > (size_t)INT32_MAX / 4 || an_far_reserve(ws, m) != 0) return -1;
    return farthest_tree(yx, yy, m, &S, cx, cy, ws);
}

double an_farthest_quick(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy,
                         double *cx, double *cy, double *scratch)
{
    const double r2 = an_farthest_row(yx, yy, m, S, cx, cy, scratch);
    return r2 != -3 ? r2 : an_farthest_sub(yx, yy, m, S, hx, hy, cx, cy, scratch);
}
