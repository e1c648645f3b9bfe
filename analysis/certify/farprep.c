/* farprep.c - the farthest point of a square from a set prepared once
 * (farthest.h): what the certificate needs when one large neighbourhood
 * (a cluster) is solved again for each of its points, with other squares
 * and with one point left out.
 *
 * Preparing builds the tree of farthest.c over the set and, for each
 * position a, the reach r(a) of its Voronoi cell in the plane: the largest
 * distance from a of a point of the cell (infinite for a cell that is not
 * bounded within a box of a few diameters of the set). A region clipped to
 * any square lies inside the cell, so a position with r(a)^2 <= best
 * cannot raise it: a solve visits the positions by decreasing reach and
 * stops at the first that cannot. Leaving out a position e changes only
 * the cells of its Voronoi neighbours (a point of e's cell goes to its
 * second nearest, a Delaunay neighbour of e), all within 2 r(e) of e:
 * those are visited too. Each visit is farthest.c's exact clipping. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "farthest.h"
#include "farthest_int.h"
#include "geom.h"

#define NONE ((size_t)-1)

void an_far_prep_free(an_far_prep *P)
{
    an_far_free(&P->tree);
    free(P->reach2); free(P->cand); free(P->yx); free(P->yy); free(P->copies);
    memset(P, 0, sizeof *P);
}

int an_far_prep_same(const an_far_prep *P, const double *yx, const double *yy, size_t m)
{
    return P->m == m && m > 0 && memcmp(P->yx, yx, m * sizeof *yx) == 0 && memcmp(P->yy, yy, m * sizeof *yy) == 0;
}

int an_far_prep_set(an_far_prep *P, const double *yx, const double *yy, size_t m)
{
    P->ready = 0;
    P->m = 0;
    if (m > P->cap) {
        GROW(P->yx, m);
        GROW(P->yy, m);
        GROW(P->cand, m);
        GROW(P->reach2, m);
        GROW(P->copies, m);
        P->cap = m;
    }
    memcpy(P->yx, yx, m * sizeof *yx);
    memcpy(P->yy, yy, m * sizeof *yy);
    P->m = m;
    return 0;
}

/* Squared distance from (cx, cy) to the nearest position but excl, as
 * cfpo_min_dist2 computes it. */
static double nearest(const an_far_ws *T, double cx, double cy, size_t excl)
{
    double best = INFINITY;
    long stack[2 * KD_DEPTH + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const kd_node *n = &T->nodes[stack[--sp]];
        if (an_kd_box_d2(n, cx, cy) >= best) continue;
        if (n->left < 0) {
            for (size_t j = n->lo; j < n->hi; j++) {
                if (j == excl) continue;
                const double dx = cx - T->x[j], dy = cy - T->y[j], d2 = dx * dx + dy * dy;
                if (d2 < best) best = d2;
            }
            continue;
        }
        const double dl = an_kd_box_d2(&T->nodes[n->left], cx, cy), dr = an_kd_box_d2(&T->nodes[n->right], cx, cy);
        stack[sp++] = dl <= dr ? n->right : n->left;
        stack[sp++] = dl <= dr ? n->left : n->right;
    }
    return best;
}

/* The tree position holding (ex, ey), or NONE. */
static size_t find(const an_far_ws *T, double ex, double ey)
{
    long stack[2 * KD_DEPTH + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const kd_node *n = &T->nodes[stack[--sp]];
        if (ex < n->x0 || ex > n->x1 || ey < n->y0 || ey > n->y1) continue;
        if (n->left < 0) {
            for (size_t j = n->lo; j < n->hi; j++)
                if (T->x[j] == ex && T->y[j] == ey) return j;
            continue;
        }
        stack[sp++] = n->right;
        stack[sp++] = n->left;
    }
    return NONE;
}

int an_far_prep_build(an_far_prep *P)
{
    const size_t m = P->m;
    an_far_ws *T = &P->tree;
    if (an_far_reserve(T, m) != 0) return -1;
    memcpy(T->x, P->yx, m * sizeof *T->x);
    memcpy(T->y, P->yy, m * sizeof *T->y);
    double x0 = T->x[0], x1 = x0, y0 = T->y[0], y1 = y0;
    for (size_t t = 1; t < m; t++) {
        x0 = fmin(x0, T->x[t]); x1 = fmax(x1, T->x[t]);
        y0 = fmin(y0, T->y[t]); y1 = fmax(y1, T->y[t]);
    }
    T->nodes_used = 0;
    an_kd_build(T, 0, m, 0);
    an_hull_links(T);
    const double Rb = 4 * sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0));
    P->Rb = Rb;
    size_t u = 0;
    for (size_t k = 0; k < T->nodes_used; k++) {
        const kd_node *nd = &T->nodes[k];
        if (nd->left >= 0) continue;
        for (size_t j = nd->lo; j < nd->hi; j++) {
            const double ax = T->x[j], ay = T->y[j];
            double r2 = INFINITY;
            if (Rb > 0 && !(T->hull_ok && T->hull[2 * j] >= 0)) { /* a hull vertex's cell is unbounded */
                region R = {T->pa, T->pb, T->sd, 4, 2 * Rb * Rb};
                const double box[8] = {ax - Rb, ay - Rb, ax + Rb, ay - Rb, ax + Rb, ay + Rb, ax - Rb, ay + Rb};
                memcpy(R.P, box, sizeof box);
                if (!an_clip_region(T, j, NONE, &R, -1)) r2 = 0; /* empty: cannot happen for distinct positions */
                else {
                    int touches = 0;
                    for (int v = 0; v < R.nv; v++)
                        touches |= fabs(R.P[2 * v] - ax) >= Rb * (1 - 1e-9) ||
                                   fabs(R.P[2 * v + 1] - ay) >= Rb * (1 - 1e-9);
                    r2 = touches ? INFINITY : R.far2;
                }
            }
            P->reach2[j] = r2;
            T->key[2 * u] = -r2; /* by decreasing reach, then position */
            T->key[2 * u + 1] = (double)j;
            u++;
        }
    }
    qsort(T->key, u, 2 * sizeof *T->key, an_cmp_pair);
    for (size_t k = 0; k < u; k++) P->cand[k] = (size_t)T->key[2 * k + 1];
    for (size_t k = 0; k < u; k++) P->copies[P->cand[k]] = 0;
    for (size_t t = 0; t < m; t++) {
        const size_t j = find(T, P->yx[t], P->yy[t]);
        if (j == NONE) return -1; /* cannot happen: every point is in its leaf */
        P->copies[j]++;
    }
    P->x0 = x0;
    P->x1 = x1;
    P->y0 = y0;
    P->y1 = y1;
    P->u = u;
    P->ready = 1;
    return 0;
}

typedef struct {
    cfpo_square S;
    size_t excl;
    double best, bx, by;
} prep_state;

/* Position j's region in the square; its farthest vertex may raise best. */
static void visit(const an_far_prep *P, size_t j, prep_state *F, an_far_ws *ws)
{
    const an_far_ws *T = &P->tree;
    const cfpo_square S = F->S;
    const double corner[8] = {S.x0, S.y0, S.x1, S.y0, S.x1, S.y1, S.x0, S.y1};
    const double ax = T->x[j], ay = T->y[j];
    double ub = 0;
    for (int c = 0; c < 4; c++) {
        const double dx = corner[2 * c] - ax, dy = corner[2 * c + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > ub) ub = d2;
    }
    if (ub <= F->best) return;
    /* A hull vertex: its wedge, unless the point left out is one of the
     * neighbours that bound it. */
    if (T->hull_ok && T->hull[2 * j] >= 0 && (size_t)T->hull[2 * j] != F->excl &&
        (size_t)T->hull[2 * j + 1] != F->excl && an_wedge_bound(T, j, corner, 4) <= F->best)
        return;
    region R = {ws->pa, ws->pb, ws->sd, 4, ub};
    memcpy(R.P, corner, sizeof corner);
    if (!an_clip_region(T, j, F->excl, &R, F->best)) return;
    for (int v = 0; v < R.nv; v++) {
        const double dx = R.P[2 * v] - ax, dy = R.P[2 * v + 1] - ay, d2 = dx * dx + dy * dy;
        if (d2 > F->best) { F->best = d2; F->bx = R.P[2 * v]; F->by = R.P[2 * v + 1]; }
    }
}

/* Whether the box [x0, x1] x [y0, y1] meets one of the closed disks
 * around the nv vertices v of C through e (radius |v - e|, a little more). */
static int meets(const double *C, int nv, double ex, double ey, double x0, double y0, double x1, double y1)
{
    for (int v = 0; v < nv; v++) {
        const double vx = C[2 * v], vy = C[2 * v + 1], rx = vx - ex, ry = vy - ey;
        const double dx = vx < x0 ? x0 - vx : vx > x1 ? vx - x1 : 0;
        const double dy = vy < y0 ? y0 - vy : vy > y1 ? vy - y1 : 0;
        if (dx * dx + dy * dy <= (rx * rx + ry * ry) * (1 + 1e-9) + 1e-300) return 1;
    }
    return 0;
}

/* Visits the Voronoi neighbours of position e: the points a with
 * |v - a| = |v - e| at a vertex v of e's cell (the ends of their common
 * edge), found as the points in the disks around the cell's vertices
 * through e. The cell is e's region in the box of half-side Rb, bounded
 * (the caller checked its reach). */
static void visit_near(const an_far_prep *P, size_t e, prep_state *F, an_far_ws *ws)
{
    const an_far_ws *T = &P->tree;
    const double ex = T->x[e], ey = T->y[e], Rb = P->Rb;
    region R = {ws->pa, ws->pb, ws->sd, 4, 2 * Rb * Rb};
    const double box[8] = {ex - Rb, ey - Rb, ex + Rb, ey - Rb, ex + Rb, ey + Rb, ex - Rb, ey + Rb};
    memcpy(R.P, box, sizeof box);
    if (!an_clip_region(T, e, NONE, &R, -1)) return;
    double *cell = ws->scratch; /* visit clips in pa / pb */
    memcpy(cell, R.P, 2 * (size_t)R.nv * sizeof *cell);
    const int nv = R.nv;
    long stack[2 * KD_DEPTH + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const kd_node *n = &T->nodes[stack[--sp]];
        if (!meets(cell, nv, ex, ey, n->x0, n->y0, n->x1, n->y1)) continue;
        if (n->left < 0) {
            for (size_t j = n->lo; j < n->hi; j++)
                if (j != e && meets(cell, nv, ex, ey, T->x[j], T->y[j], T->x[j], T->y[j])) visit(P, j, F, ws);
            continue;
        }
        stack[sp++] = n->right;
        stack[sp++] = n->left;
    }
}

double an_far_prep_nearest(const an_far_prep *P, double x, double y, int exclude, double ex, double ey)
{
    if (!P->ready) return -1;
    size_t excl = NONE;
    if (exclude) {
        excl = find(&P->tree, ex, ey);
        if (excl != NONE && P->copies[excl] > 1) excl = NONE;
    }
    return nearest(&P->tree, x, y, excl);
}

double an_far_prep_solve(const an_far_prep *P, cfpo_square S, int exclude, double ex, double ey, const double *from,
                         double *cx, double *cy, an_far_ws *ws)
{
    const an_far_ws *T = &P->tree;
    if (!P->ready || an_far_reserve(ws, P->m) != 0) return -1;
    prep_state F = {S, NONE, -1, 0, 0};
    if (exclude) {
        const size_t e = find(T, ex, ey);
        if (e == NONE) return -3;
        if (P->copies[e] == 1) { /* else the positions left are the same */
            F.excl = e;
            if (!(P->reach2[e] < INFINITY)) return -3;
        }
    }
    const double corner[8] = {S.x0, S.y0, S.x1, S.y0, S.x1, S.y1, S.x0, S.y1};
    for (int c = 0; c < 4; c++) {
        const double d2 = nearest(T, corner[2 * c], corner[2 * c + 1], F.excl);
        if (d2 > F.best) { F.best = d2; F.bx = corner[2 * c]; F.by = corner[2 * c + 1]; }
    }
    if (!(F.best < INFINITY)) return -3; /* nothing left */
    if (exclude && from) {
        /* Leaving a point out moves every distance up or keeps it: the
         * answer with it, at `from`, is reached without it too, and only the
         * cells of its neighbours (visited below) change. Every other cell
         * was within that answer, so it needs no visit. */
        const double d2 = nearest(T, from[0], from[1], F.excl);
        if (d2 > F.best) { F.best = d2; F.bx = from[0]; F.by = from[1]; }
    }
    for (size_t k = 0; k < P->u && !(exclude && from); k++) {
        const size_t j = P->cand[k];
        if (P->reach2[j] * (1 + 1e-9) <= F.best) break;
        if (j != F.excl) visit(P, j, &F, ws);
    }
    if (F.excl != NONE) visit_near(P, F.excl, &F, ws);
    *cx = F.bx < S.x0 ? S.x0 : F.bx > S.x1 ? S.x1 : F.bx;
    *cy = F.by < S.y0 ? S.y0 : F.by > S.y1 ? S.y1 : F.by;
    return nearest(T, *cx, *cy, F.excl);
}
