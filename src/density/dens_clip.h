/* dens_clip.h - layer 2: the pieces of the density solve that its plain
 * route (dens_solve_plain.c) and its AVX-512 route (dens_solve_avx512.c)
 * share, so that both give the same bits: the lines, the cut, the
 * vertices' values; and q at a spot, which the engine reads too.
 * May include density.h and geom.h. */
#ifndef CFPO_DENS_CLIP_H
#define CFPO_DENS_CLIP_H

#include <math.h>

#include "density.h"
#include "geom.h"

/* q = sqrt(rho) at the local point (cx, cy) of the frame at (ox, oy). */
static inline double cfpo_dens_local_q(const cfpo_density *d, double ox, double oy, double cx, double cy)
{
    return sqrt(cfpo_density_at(d, cfpo_wrap01(ox + cx), cfpo_wrap01(oy + cy)));
}

#define DENS_CELLS 10 /* the polygons of the DENS_CELLS nearest neighbours (given nearest first) */
#define DENS_BIG 64   /* a polygon of more vertices is not cut further (rounding's pathology) */

/* The cut of the polygon *pp (nv <= DENS_BIG vertices, x y interleaved)
 * by the line through (mx, my) with normal (nx, ny), keeping the side
 * s <= 0, into *pn (at most vmax vertices), which then becomes *pp (the
 * two buffers swap). -1 when the line misses it (every s <= 0), 0 when it
 * removes all of it (every s > 0), else the count, and in *far2 the
 * largest squared distance of the output from (ax, ay). */
static inline int dens_cut(double **pp, int nv, double mx, double my, double nx, double ny, double ax, double ay,
                           int vmax, double **pn, double *far2)
{
    const double *poly = *pp;
    double *next = *pn;
    double smax = -INFINITY, smin = INFINITY, sd[DENS_BIG];
    for (int v = 0; v < nv; v++) {
        const double s = (poly[2 * v] - mx) * nx + (poly[2 * v + 1] - my) * ny;
        sd[v] = s;
        if (s > smax) smax = s;
        if (s < smin) smin = s;
    }
    if (smax <= 0) return -1;
    if (smin > 0) return 0;
    int nn = 0;
    for (int v = 0; v < nv && nn + 2 <= vmax; v++) {
        const int w = v + 1 == nv ? 0 : v + 1;
        const double s0 = sd[v], s1 = sd[w];
        if (s0 <= 0) {
            next[2 * nn] = poly[2 * v];
            next[2 * nn + 1] = poly[2 * v + 1];
            nn++;
        }
        if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
            const double tt = s0 / (s0 - s1);
            next[2 * nn] = poly[2 * v] + tt * (poly[2 * w] - poly[2 * v]);
            next[2 * nn + 1] = poly[2 * v + 1] + tt * (poly[2 * w + 1] - poly[2 * v + 1]);
            nn++;
        }
    }
    double f = 0;
    for (int v = 0; v < nn; v++) {
        const double dx = next[2 * v] - ax, dy = next[2 * v + 1] - ay;
        if (dx * dx + dy * dy > f) f = dx * dx + dy * dy;
    }
    *far2 = f;
    *pn = *pp;
    *pp = next;
    return nn;
}

/* The lines of every y_j against y_i: each passes through the point
 * dividing y_i y_j in the ratio w_j : w_i (w = rho^(1/4)), at t_j = w_j /
 * (w_i + w_j) of the way, normal y_j - y_i; h_j = t_j^2 |y_j - y_i|^2 is
 * its squared distance from y_i, so it cannot meet a polygon whose
 * vertices lie within sqrt(far2) of y_i when h_j >= far2. One pass with
 * no branches (the compiler vectorises it), before the cuts. */
static inline void dens_lines(double ax, double ay, double wi, const double *yx, const double *yy, const double *w,
                              int k, double *t, double *h)
{
    for (int j = 0; j < k; j++) {
        const double ux = yx[j] - ax, uy = yy[j] - ay;
        const double tj = w[j] / (wi + w[j]), n2 = ux * ux + uy * uy;
        t[j] = tj;
        h[j] = tj * tj * n2;
    }
}

/* The squared measure's geometric part at (px, py): the min over the k
 * neighbours of |c - y_j|^2 q_j, given y_i's own term geo; the scan
 * stops once even qhi cannot lift it above best (a value that fails
 * then fails at the end: the min only falls). */
static inline double dens_geo_plain(double px, double py, const double *yx, const double *yy, const double *yr, int k,
                                    int i, double geo, double qhi, double best)
{
    for (int j = 0; j < k && geo * qhi > best; j++) {
        if (j == i) continue;
        const double dx = px - yx[j], dy = py - yy[j];
        const double val = (dx * dx + dy * dy) * yr[j];
        if (val < geo) geo = val;
    }
    return geo;
}

typedef double (*dens_geo_fn)(double px, double py, const double *yx, const double *yy, const double *yr, int k,
                              int i, double geo, double qhi, double best);

/* Evaluates the polygon of y_i (vertices (x[v s], y[v s]), v < nv) into
 * the running best: each vertex clamped to S, f there exactly (the min
 * over all neighbours of |c - y_j|^2 q_j by geo_of, times q(c) from its
 * pixel), abandoned as soon as even qhi cannot lift it above *best (y_i's
 * own term first), then as soon as q there cannot (rounding is monotone,
 * so the min is the same bits in any order and a value abandoned early
 * would not have passed). Returns whether a vertex replaced *best. */
static inline int dens_eval(const double *x, const double *y, int s, int nv, int i, const double *yx,
                            const double *yy, const double *yr, int k, cfpo_square S, const cfpo_density *d,
                            double qhi, double ox, double oy, double *best, double *cx, double *cy, dens_geo_fn geo_of)
{
    int found = 0;
    const double ax = yx[i], ay = yy[i];
    for (int v = 0; v < nv; v++) {
        double px = x[v * s], py = y[v * s];
        if (px < S.x0) px = S.x0;
        if (px > S.x1) px = S.x1;
        if (py < S.y0) py = S.y0;
        if (py > S.y1) py = S.y1;
        const double ex = px - ax, ey = py - ay;
        double geo = (ex * ex + ey * ey) * yr[i];
        if (!(geo * qhi > *best)) continue;
        /* q at the vertex itself (at most qhi) bounds the scan over the
         * other neighbours: it stops where the value cannot pass, which
         * the bound qhi only says later; a scan it does not stop gives
         * the whole min, as with qhi */
        const double rc = cfpo_dens_local_q(d, ox, oy, px, py);
        if (!(rc > 0) || !(geo * rc > *best)) continue;
        geo = geo_of(px, py, yx, yy, yr, k, i, geo, rc, *best);
        const double val = geo * rc;
        if (val > *best) {
            *best = val;
            *cx = px;
            *cy = py;
            found = 1;
        }
    }
    return found;
}

/* The squared distance from (ax, ay) of S's farthest corner, and S's
 * corners in order into c. */
static inline double dens_corners(cfpo_square S, double ax, double ay, double c[4][2])
{
    c[0][0] = S.x0; c[0][1] = S.y0;
    c[1][0] = S.x1; c[1][1] = S.y0;
    c[2][0] = S.x1; c[2][1] = S.y1;
    c[3][0] = S.x0; c[3][1] = S.y1;
    double far2 = 0;
    for (int q = 0; q < 4; q++) {
        const double dx = c[q][0] - ax, dy = c[q][1] - ay;
        if (dx * dx + dy * dy > far2) far2 = dx * dx + dy * dy;
    }
    return far2;
}

/* The plain, AVX-512 and AVX2 routes (call the AVX-512 one only where
 * cfpo_solver_avx512_usable() says 1, the AVX2 one where
 * cfpo_solver_avx2_usable() does): cfpo_dens_solve's arguments, k > 0,
 * w[j] = sqrt(yr[j]) given, the polygons i0 .. m - 1 (m <= k); found0 says
 * that polygons before i0 gave the best vertex so far, floor_f its value
 * and (*cx, *cy) its place (cfpo_dens_solve_from); scratch holds 8 (k + 8)
 * doubles, w among them at 4 (k + 8). */
int cfpo_dens_solve_plain(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                          cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                          double *cx, double *cy, double *f, double *scratch);
int cfpo_dens_solve_avx512(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                           cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                           double *cx, double *cy, double *f, double *scratch);
int cfpo_dens_solve_avx2(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                         cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                         double *cx, double *cy, double *f, double *scratch);

/* cfpo_dens_value (dens_solve.h) by the AVX-512 and AVX2 routes (the same
 * conditions): the same min over the same terms, so the same bits. */
double cfpo_dens_value_avx512(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                              double cy);
double cfpo_dens_value_avx2(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                            double cy);
double cfpo_dens_value_plain(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                             double cy);

#endif /* CFPO_DENS_CLIP_H */
