/* lct.c - the two properties of the Local Characterization Theorem for
 * one point x (certify.h says what they are): the farthest point of S(x)
 * from the points of D(x), and from those without x.
 *
 * Where D(x) holds few points (a well-spread set) each is one call of the
 * solver. Where it holds many, they are usually the same many for many
 * points (each point of a cluster has the whole cluster for D(x)): a
 * thread keeps the last few such sets, prepares one when it is seen again
 * (farprep.c), and from then on recognises it through the points' tree,
 * without collecting D(x) at all. */
#include <math.h>
#include <string.h>

#include "certwork.h"
#include "farthest.h"
#include "farthest_int.h"
#include "geom.h"
#include "lct.h"
#include "polygon.h"
#include "ptree.h"

/* Copies into sx/sy the collected images within Chebyshev H of (cx, cy),
 * leaving out the images of point `skip` (pass n to keep all). */
static int subset(const an_cert_work *w, double cx, double cy, double H, size_t skip, double *sx, double *sy)
{
    int m = 0;
    for (size_t t = 0; t < w->m; t++) {
        if (w->id[t] == skip || fabs(w->x[t] - cx) > H || fabs(w->y[t] - cy) > H) continue;
        sx[m] = w->x[t];
        sy[m] = w->y[t];
        m++;
    }
    return m;
}

/* The prepared set that is exactly D(x)'s, found without collecting: its
 * box lies in D(x) and D(x) holds as many images (2h < 1: one of x). */
static an_far_prep *covering_slot(const an_cert_ctx *C, an_cert_work *w, double x, double y, double h)
{
    if (!(h < 0.5)) return NULL;
    size_t count = 0;
    int counted = 0;
    for (int k = 0; k < AN_PREP_SLOTS; k++) {
        an_far_prep *P = &w->prep[k];
        if (!P->ready || fabs(P->x0 - x) > h || fabs(P->x1 - x) > h || fabs(P->y0 - y) > h || fabs(P->y1 - y) > h)
            continue;
        if (!counted) { count = an_ptree_count_box(C->tree, x, y, h); counted = 1; }
        if (count != P->m) continue;
        w->used[k] = ++w->clock;
        return P;
    }
    return NULL;
}

/* The slot holding the collected set sx/sy (m points) once it has been
 * seen AN_PREP_AFTER times, or NULL (after keeping it in the least
 * recently used slot if it is new); -1 in *err out of memory. */
static an_far_prep *remembered(an_cert_work *w, int m, int *err)
{
    int lru = 0;
    for (int k = 0; k < AN_PREP_SLOTS; k++) {
        if (an_far_prep_same(&w->prep[k], w->sx, w->sy, (size_t)m)) {
            w->used[k] = ++w->clock;
            if (w->seen[k] < AN_PREP_AFTER) w->seen[k]++;
            return w->seen[k] >= AN_PREP_AFTER ? &w->prep[k] : NULL;
        }
        if (w->used[k] < w->used[lru]) lru = k;
    }
    if (an_far_prep_set(&w->prep[lru], w->sx, w->sy, (size_t)m) != 0) *err = -1;
    w->used[lru] = ++w->clock;
    w->seen[lru] = 1;
    return NULL;
}

/* Polygon p cut to the half-plane a X + b Y <= c, into q (as
 * an_clip_bisector). */
static int cut_side(const double *p, int n, double *q, double *sd, double a, double b, double c)
{
    int out = 0;
    for (int v = 0; v < n; v++) {
        sd[v] = a * p[2 * v] + b * p[2 * v + 1] - c;
        out |= sd[v] > 0;
    }
    return out ? an_clip_sd(p, n, q, sd) : -1;
}

#define P2_NEAR 64 /* x's neighbours handled this way at most */

/* Property 2 from property 1's answer u = (ux, uy) (r2p1 = d(u, D)^2),
 * with w->sx/sy = Y = D(x) without x (m points). Outside x's Voronoi
 * region R in D nothing changes when x goes, so the largest distance
 * there is at most r2p1, and r2p1 itself if u is outside R; if u is in
 * R, the largest distance over R is at least d(u, Y) >= r2p1. So the
 * answer is the larger of r2p1 and the largest distance over R. Inside
 * R the nearest point of Y is a
 * Voronoi neighbour of x whose shared edge lies within |p - y0| <= G of
 * p in S (y0: x's nearest; the disk around p through its nearest shrunk
 * towards it first meets x on that edge), so R is cut out in the box of
 * half-side e + G, its neighbours are the points whose bisector touches
 * it, and R cut to S is split among them. The squared answer, or -3 when
 * this does not apply (a copy of x, many neighbours). */
static double p2_from_p1(an_cert_work *w, int m, double x, double y, cfpo_square S, double ux, double uy,
                         double r2p1, double *px, double *py)
{
    const double *sx = w->sx, *sy = w->sy;
    double d0 = INFINITY, x0 = 0, y0 = 0;
    for (int t = 0; t < m; t++) {
        const double dx = sx[t] - x, dy = sy[t] - y, d2 = dx * dx + dy * dy;
        if (d2 == 0) return -3;
        if (d2 < d0) { d0 = d2; x0 = sx[t]; y0 = sy[t]; }
    }
    if (m == 0) return -3;
    const double cx[4] = {S.x0, S.x1, S.x1, S.x0}, cy[4] = {S.y0, S.y0, S.y1, S.y1};
    double G2 = 0;
    for (int c = 0; c < 4; c++) {
        const double dx = cx[c] - x0, dy = cy[c] - y0, d2 = dx * dx + dy * dy;
        G2 = d2 > G2 ? d2 : G2;
    }
    const double H = (0.5 * (S.x1 - S.x0) + sqrt(G2)) * (1 + 1e-9);
    double *P = w->pa, *Q = w->pb;
    const double box[8] = {x - H, y - H, x + H, y - H, x + H, y + H, x - H, y + H};
    memcpy(P, box, sizeof box);
    int nv = 4;
    double far2 = 2 * H * H;
    for (int t = 0; t < m && nv > 0; t++) {
        const double dx = sx[t] - x, dy = sy[t] - y;
        if (dx * dx + dy * dy >= 4 * far2 * (1 + 1e-9)) continue;
        const int k = an_clip_bisector(P, nv, Q, w->sd, x, y, sx[t], sy[t]);
        if (k < 0) continue;
        nv = k;
        double *tmp = P; P = Q; Q = tmp;
        far2 = 0;
        for (int v = 0; v < nv; v++) {
            const double ex = P[2 * v] - x, ey = P[2 * v + 1] - y, e2 = ex * ex + ey * ey;
            far2 = e2 > far2 ? e2 : far2;
        }
    }
    if (nv == 0) return -3;
    /* The neighbours: bisectors touching R within rounding (vmax.c's test). */
    const double eps = an_touch_eps(P, nv, x, y);
    double nbx[P2_NEAR], nby[P2_NEAR];
    int k = 0;
    for (int t = 0; t < m; t++) {
        const int touch = an_touches(P, nv, x, y, sx[t], sy[t], eps);
        int seen = 0;
        for (int j = 0; j < k && touch && !seen; j++) seen = nbx[j] == sx[t] && nby[j] == sy[t];
        if (!touch || seen) continue;
        if (k == P2_NEAR) return -3;
        nbx[k] = sx[t];
        nby[k] = sy[t];
        k++;
    }
    /* R cut to S. */
    const double side[4][3] = {{1, 0, S.x1}, {-1, 0, -S.x0}, {0, 1, S.y1}, {0, -1, -S.y0}};
    for (int c = 0; c < 4 && nv > 0; c++) {
        const int r = cut_side(P, nv, Q, w->sd, side[c][0], side[c][1], side[c][2]);
        if (r < 0) continue;
        nv = r;
        double *tmp = P; P = Q; Q = tmp;
    }
    double bx = ux, by = uy;
    const double best = nv > 0 ? an_split_farthest(P, nv, nbx, nby, (size_t)k, w->scratch,
                                                   w->scratch + 4 * (w->cap + 8), w->sd, &bx, &by)
                               : -1;
    if (best >= 0) {
        bx = bx < S.x0 ? S.x0 : bx > S.x1 ? S.x1 : bx;
        by = by < S.y0 ? S.y0 : by > S.y1 ? S.y1 : by;
        const double v2 = cfpo_min_dist2(bx, by, sx, sy, m, -1);
        if (v2 > r2p1) { *px = bx; *py = by; return v2; }
    }
    *px = ux;
    *py = uy;
    return r2p1;
}

int an_lct(const an_cert_ctx *C, size_t i, an_cert_work *w, double h, double *p1, double *p2)
{
    const double x = C->xy[2 * i], y = C->xy[2 * i + 1];
    const double e = h - C->delta;
    const cfpo_square S = {x - e, y - e, x + e, y + e};
    double px, py, r2;
    an_far_prep *P = covering_slot(C, w, x, y, h);
    if (P) {
        r2 = an_far_prep_solve(P, S, 0, 0, 0, NULL, &px, &py, &w->far);
        if (r2 < 0) return -2;
        *p1 = sqrt(r2) - C->delta;
        const double dY2 = an_far_prep_nearest(P, x, y, 1, x, y), p1_at[2] = {px, py};
        r2 = an_far_prep_solve(P, S, 1, x, y, p1_at, &px, &py, &w->far);
        if (r2 == -3) { /* not for the prepared form: the set without x, collected */
            if (an_cert_collect(C, x, y, h, w) != 0) return -1;
            const int m = subset(w, x, y, h, i, w->sx, w->sy);
            r2 = an_farthest(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
        }
        if (r2 < 0) return -2;
        *p2 = sqrt(r2) - sqrt(dY2);
        return 0;
    }
    if (an_cert_collect(C, x, y, h, w) != 0) return -1;
    int m = subset(w, x, y, h, C->n, w->sx, w->sy);
    /* The set is kept, and prepared when seen AN_PREP_AFTER times (each
     * point of a cluster has the whole cluster for D(x)); until then it
     * may be a row (row.c) or a few points may decide it (farsub.c: a
     * segment's or an arc's D(x), which differs from point to point or
     * recurs a few times only). */
    r2 = -3;
    if (m > AN_FAR_SMALL) {
        int err = 0;
        P = remembered(w, m, &err);
        if (err) return -1;
        if (!P) r2 = an_farthest_quick(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, w->scratch);
        else if (!P->ready && an_far_prep_build(P) != 0) return -1;
    }
    if (r2 == -3)
        r2 = P ? an_far_prep_solve(P, S, 0, 0, 0, NULL, &px, &py, &w->far)
               : an_farthest_whole(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
    if (r2 < 0) return -2;
    *p1 = sqrt(r2) - C->delta;
    const int m1 = m;
    const double p1_r2 = r2;
    const double p1_at[2] = {px, py};
    m = subset(w, x, y, h, i, w->sx, w->sy);
    const double dY2 = cfpo_min_dist2(x, y, w->sx, w->sy, m, -1);
    r2 = -3;
    if (m > AN_FAR_SMALL && !P) { /* a row, a few points, else from property 1's answer */
        r2 = an_farthest_quick(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, w->scratch);
        if (r2 == -3) r2 = p2_from_p1(w, m, x, y, S, p1_at[0], p1_at[1], p1_r2, &px, &py);
    }
    if (r2 == -3 && P && m == m1 - 1 && m > AN_FAR_SMALL) r2 = an_far_prep_solve(P, S, 1, x, y, p1_at, &px, &py, &w->far);
    if (r2 == -3) r2 = an_farthest_whole(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
    if (r2 < 0) return -2;
    *p2 = sqrt(r2) - sqrt(dY2);
    return 0;
}
