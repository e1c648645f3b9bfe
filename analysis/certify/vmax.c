/* vmax.c - T of the farthest point test: the largest distance to the rest
 * of the set over the Voronoi cell V(x) of x (certify.c says why that
 * decides the test), found through the points' tree, so that a point of
 * a cluster costs about log n and not one scan of every image. */
#include "vmax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cellradius.h"
#include "certwork.h"
#include "farthest.h"
#include "geom.h"
#include "polygon.h"

#define VMAX_DIRECT 64 /* touching points (or sides of V(x)) solved by clipping; more: hole_radius */
#define VMAX_CAND 1024 /* images met by the cell's walk since its last cut; more: hole_radius */

/* Sorts the m positions (sx, sy) and drops repeats; returns the count. */
static int unique_points(double *sx, double *sy, int m, double *tmp)
{
    for (int t = 0; t < m; t++) { tmp[2 * t] = sx[t]; tmp[2 * t + 1] = sy[t]; }
    qsort(tmp, (size_t)m, 2 * sizeof *tmp, an_cmp_pair);
    int k = 0;
    for (int t = 0; t < m; t++)
        if (k == 0 || tmp[2 * t] != sx[k - 1] || tmp[2 * t + 1] != sy[k - 1]) {
            sx[k] = tmp[2 * t];
            sy[k] = tmp[2 * t + 1];
            k++;
        }
    return k;
}

/* Walks on only through images within sqrt(fr2[v]) of some vertex v of
 * the polygon P: fr2[v] = |v - x|^2 (1 + 1e-9) + slack. An image y whose
 * bisector with x meets P has |v - y| < |v - x| at a vertex ((v - m).n =
 * (|v - x|^2 - |v - y|^2) / 2, linear in v, so largest at a vertex); on
 * a strip-like V(x) (a line of points) this passes over the whole line
 * that the distance bound alone would walk through. */
static void set_filter(an_cert_work *w, const double *P, int nv, double x, double y, double slack)
{
    for (int v = 0; v < nv; v++) {
        const double dx = P[2 * v] - x, dy = P[2 * v + 1] - y;
        w->fr2[v] = (dx * dx + dy * dy) * (1 + 1e-9) + slack + 1e-300;
    }
    an_pwalk_filter(&w->walk, P, w->fr2, nv);
}

/* The rounding slack of the touching test for polygon P (eps: an_touch_eps);
 * a vertex v with (v - m).n >= -eps |n| needs |n| <= 2 sqrt(far2) + 2 eps,
 * so |v - y|^2 <= |v - x|^2 + 2 eps |n| is met with 2 eps |n| at most
 * *slack; *radius bounds |n|. */
static void touch_slack(const double *P, int nv, double x, double y, double far2, double *eps, double *slack,
                        double *radius)
{
    *eps = an_touch_eps(P, nv, x, y);
    *radius = (2 * sqrt(far2) + 2 * *eps) * (1 + 1e-9) + 1e-300;
    *slack = 2 * *eps * (2 * sqrt(far2) + 2 * *eps) * (1 + 1e-9);
}

/* Keeps candidate (px, py, id) in w->cand. 0, or -1 out of memory. */
static int keep(an_cert_work *w, size_t k, double px, double py, size_t id)
{
    if (k == w->ccap) {
        const size_t cap = w->ccap ? 2 * w->ccap : 64;
        double *c = realloc(w->cand, 2 * cap * sizeof *c);
        if (c) w->cand = c;
        size_t *d = realloc(w->cand_id, cap * sizeof *d);
        if (d) w->cand_id = d;
        if (!c || !d) return -1;
        w->ccap = cap;
    }
    w->cand[2 * k] = px;
    w->cand[2 * k + 1] = py;
    w->cand_id[k] = id;
    return 0;
}

/* V(x): the square of half-side s around x clipped by the bisectors of x
 * and the images of the other points, nearest first, until the next one is
 * farther than any that could touch the polygon, or until the polygon has
 * more than VMAX_DIRECT sides (the end of a line of points, whose cell
 * has a side for each image of the line: then it still holds V(x)), or
 * the walk has met more than VMAX_CAND images in a row that may touch it
 * but cut nothing (points on a circle: every bisector passes through the
 * centre, a vertex of every cell); then *nv_out is minus the polygon's
 * count, and it holds V(x). Leaves the polygon in
 * w->pa (which = 0) or w->pb (1), its squared reach in *far2, and in
 * w->cand (*ncand) every image that may touch it: the walk's filter and
 * its end take the touching test's slack, and a point touching the final
 * polygon touches every polygon containing it (the test is linear, so it
 * holds at a vertex of the larger one), so no second walk is needed. */
static int cell_of(const an_cert_ctx *C, size_t i, an_cert_work *w, double x, double y, double s, double reach,
                   int *nv_out, int *which, double *far2, size_t *ncand)
{
    double *P = w->pa, *Q = w->pb;
    int nv = 4, in_b = 0;
    const double sq[8] = {x - s, y - s, x + s, y - s, x + s, y + s, x - s, y + s};
    memcpy(P, sq, sizeof sq);
    *far2 = 2 * s * s;
    double eps, slack, radius;
    touch_slack(P, nv, x, y, *far2, &eps, &slack, &radius);
    if (an_pwalk_start(&w->walk, C->tree, x, y, radius, i) != 0) return -1;
    set_filter(w, P, nv, x, y, slack);
    double lastx = NAN, lasty = NAN, px, py, d2;
    size_t id, k = 0, since = 0; /* since: the candidates when the cell was last cut */
    int got;
    while (nv > 0 && (got = an_pwalk_next(&w->walk, &px, &py, &id, &d2)) != 0) {
        if (got < 0) return -1;
        if (d2 > radius * radius) break;
        if (id == i || fabs(px - x) > reach || fabs(py - y) > reach) continue;
        if (px == lastx && py == lasty) continue; /* the same bisector again, the same images */
        lastx = px;
        lasty = py;
        if (keep(w, k++, px, py, id) != 0) return -1;
        if (k - since > VMAX_CAND) { *nv_out = -nv; *which = in_b; *ncand = k; return 0; } /* still holds V(x) */
        if (px == x && py == y) continue;        /* a coincident point: no bisector */
        if (d2 >= 4 * *far2 * (1 + 1e-9)) continue; /* too far to cut */
        if ((size_t)nv + 1 > w->cap + 8) {
            if (an_cert_reserve(w, 2 * w->cap) != 0) return -1;
            P = in_b ? w->pb : w->pa;
            Q = in_b ? w->pa : w->pb;
            set_filter(w, P, nv, x, y, slack); /* the buffers it read have moved */
        }
        const int cut = an_clip_bisector(P, nv, Q, w->sd, x, y, px, py);
        if (cut < 0) continue; /* nothing cut off */
        nv = cut;
        since = k;
        double *tmp = P; P = Q; Q = tmp;
        in_b = !in_b;
        *far2 = 0;
        for (int v = 0; v < nv; v++) {
            const double dx = P[2 * v] - x, dy = P[2 * v + 1] - y, e2 = dx * dx + dy * dy;
            *far2 = e2 > *far2 ? e2 : *far2;
        }
        if (nv > VMAX_DIRECT) break; /* a many-sided cell: the caller goes by the grid's cells */
        touch_slack(P, nv, x, y, *far2, &eps, &slack, &radius);
        set_filter(w, P, nv, x, y, slack);
        if (w->walk.len > 64) an_pwalk_prune(&w->walk);
    }
    *nv_out = nv;
    *which = in_b;
    *ncand = k;
    return 0;
}

/* 0 when the square [x0, x0 + L] x [y0, y0 + L] lies wholly outside an
 * edge of the counter-clockwise convex polygon P (n vertices), with a
 * margin against rounding; 1 when it may meet it. */
static int meets(double x0, double y0, double L, const double *P, int n)
{
    for (int e = 0; e < n; e++) {
        const int f = e + 1 == n ? 0 : e + 1;
        const double ex = P[2 * f] - P[2 * e], ey = P[2 * f + 1] - P[2 * e + 1];
        const double tol = 1e-9 * (fabs(ex) + fabs(ey)) * (L + fabs(x0) + fabs(y0) + 1);
        int out = 1;
        for (int c = 0; c < 4 && out; c++) {
            const double qx = x0 + (c & 1) * L - P[2 * e], qy = y0 + (c >> 1) * L - P[2 * e + 1];
            out = ex * qy - ey * qx < -tol; /* right of the edge: outside */
        }
        if (out) return 0;
    }
    return 1;
}

/* max(rho, T) for point i at once: the largest empty circle of X \ {x},
 * as the covering radius itself is found (certify.c), over the grid's
 * cells that meet V(x) (P, nv vertices, or a polygon holding it; elsewhere
 * nothing changes when x goes). A cell's radius is at most its centre's
 * distance to X \ {x} plus its half-diagonal, so cells are solved exactly
 * by that bound, largest first, until it falls below the largest radius
 * found.
 * For V(x) with thousands of touching points (the end of a line of
 * points, its cell reaching along every image of the line) this solves a
 * few cells instead of V(x)'s partition among those points. *T = -1 when
 * no cell beats rho. 0, -1 out of memory, -2 the solver found nothing. */
static int hole_radius(const an_cert_ctx *C, size_t i, an_cert_work *w, const double *P, int nv, double *T,
                       double *tx, double *ty)
{
    double box[4] = {P[0], P[0], P[1], P[1]};
    for (int v = 1; v < nv; v++) {
        box[0] = fmin(box[0], P[2 * v]); box[1] = fmax(box[1], P[2 * v]);
        box[2] = fmin(box[2], P[2 * v + 1]); box[3] = fmax(box[3], P[2 * v + 1]);
    }
    const long g = (long)C->G.g;
    const double L = C->G.L;
    long ix0 = (long)floor(box[0] * (double)g), ix1 = (long)floor(box[1] * (double)g);
    long iy0 = (long)floor(box[2] * (double)g), iy1 = (long)floor(box[3] * (double)g);
    /* Cells are tested against V(x) where they are taken unwrapped, as V(x)
     * is; a box across the whole torus takes every cell once, untested. */
    const int test = ix1 - ix0 + 1 < g && iy1 - iy0 + 1 < g;
    if (ix1 - ix0 + 1 >= g) { ix0 = 0; ix1 = g - 1; }
    if (iy1 - iy0 + 1 >= g) { iy0 = 0; iy1 = g - 1; }
    an_cell_key *cand = malloc((size_t)(ix1 - ix0 + 1) * (size_t)(iy1 - iy0 + 1) * sizeof *cand);
    if (!cand) return -1;
    size_t k = 0;
    for (long iy = iy0; iy <= iy1; iy++)
        for (long ix = ix0; ix <= ix1; ix++) {
            if (test && !meets((double)ix * L, (double)iy * L, L, P, nv)) continue;
            const long wx = ((ix % g) + g) % g, wy = ((iy % g) + g) % g;
            const size_t c = (size_t)(wy * g + wx);
            const double ub = an_cell_bound(C, c, i);
            if (ub > C->rho) cand[k++] = (an_cell_key){ub, c};
        }
    qsort(cand, k, sizeof *cand, an_cell_key_desc);
    double best = C->rho;
    *T = -1;
    int status = 0;
    for (size_t t = 0; t < k && cand[t].r > best && status == 0; t++) {
        double r, at[2];
        status = an_cell_radius(C, cand[t].c, cand[t].r, i, w, &r, at);
        if (status == 0 && r > best) {
            best = r;
            *T = r;
            *tx = at[0];
            *ty = at[1];
        }
    }
    free(cand);
    return status;
}

int an_vmax(const an_cert_ctx *C, size_t i, an_cert_work *w, double x, double y, double s, double Hg, double *T,
            double *tx, double *ty)
{
    const double reach = (s + C->rho) * (1 + 1e-9) + 1e-12;
    *T = -1;
    int nv, in_b;
    double far2;
    size_t ncand;
    if (cell_of(C, i, w, x, y, s, reach, &nv, &in_b, &far2, &ncand) != 0) return -1;
    if (nv == 0) return 0;
    if (nv < 0) return hole_radius(C, i, w, in_b ? w->pb : w->pa, -nv, T, tx, ty);
    /* For p in V(x), d(p, X \ {x}) <= |p - x| + d(x): when even that stays
     * below rho, T < rho and the test needs no more. */
    if ((sqrt(far2) + C->nn[i]) * (1 + 1e-9) < C->rho) return 0;
    const double *P = in_b ? w->pb : w->pa;
    if (nv > VMAX_DIRECT) return hole_radius(C, i, w, P, nv, T, tx, ty); /* P holds V(x) */
    /* Points whose bisector touches V(x) (within rounding eps), by id,
     * among the walk's candidates: (v - m).n >= -eps |n| at a vertex. */
    double eps, slack, radius;
    touch_slack(P, nv, x, y, far2, &eps, &slack, &radius);
    if (!w->mark) {
        w->mark = calloc(C->n, 1);
        w->marked = malloc(C->n * sizeof *w->marked);
        if (!w->mark || !w->marked) return -1;
    }
    size_t nmarked = 0;
    for (size_t c = 0; c < ncand; c++) {
        const double px = w->cand[2 * c], py = w->cand[2 * c + 1];
        const size_t id = w->cand_id[c];
        if (w->mark[id] || !an_touches(P, nv, x, y, px, py, eps)) continue;
        w->mark[id] = 1;
        w->marked[nmarked++] = id;
    }
    if (nmarked > VMAX_DIRECT) { /* many touching points: by the grid's cells instead */
        for (size_t t = 0; t < nmarked; t++) w->mark[w->marked[t]] = 0;
        return hole_radius(C, i, w, P, nv, T, tx, ty);
    }
    /* Every image of those points within Hg of x. */
    size_t k = 0;
    for (size_t t = 0; t < nmarked; t++) {
        const size_t j = w->marked[t];
        const double xj = C->xy[2 * j], yj = C->xy[2 * j + 1];
        for (double oy = ceil(y - Hg - yj) - 1; oy <= floor(y + Hg - yj) + 1; oy++)
            for (double ox = ceil(x - Hg - xj) - 1; ox <= floor(x + Hg - xj) + 1; ox++) {
                const double X = xj + ox, Y = yj + oy;
                if (fabs(X - x) > Hg || fabs(Y - y) > Hg) continue;
                if (an_cert_reserve(w, k + (size_t)nv + 1) != 0) return -1;
                P = in_b ? w->pb : w->pa;
                w->sx[k] = X;
                w->sy[k] = Y;
                k++;
            }
        w->mark[j] = 0;
    }
    if (an_cert_reserve(w, k + (size_t)nv + 8) != 0) return -1;
    P = in_b ? w->pb : w->pa;
    k = (size_t)unique_points(w->sx, w->sy, (int)k, w->scratch);
    /* The largest distance to those points over V(x): for each of them,
     * V(x) clipped to its own cell among them, at a vertex; by the grid's
     * cells when they are many (the far ends of a line of points, where
     * V(x) has a vertex for each image of the line). */
    if (k > VMAX_DIRECT) return hole_radius(C, i, w, P, nv, T, tx, ty);
    /* V(x) cut by k more bisectors: at most nv + k <= cap + 8 vertices. */
    double bx = x, by = y;
    const double best = an_split_farthest(P, nv, w->sx, w->sy, k, w->scratch, w->scratch + 4 * (w->cap + 8), w->sd,
                                          &bx, &by);
    if (best < 0) return 0;
    /* The value from the distances themselves, not the clipping. */
    *T = sqrt(cfpo_min_dist2(bx, by, w->sx, w->sy, (int)k, -1));
    *tx = cfpo_wrap01(bx);
    *ty = cfpo_wrap01(by);
    return 0;
}
