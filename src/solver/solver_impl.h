/* solver_impl.h - layer 1: the one source of LocalCFPO, compiled for the
 * host (geom.c) and, where the CUDA toolkit exists, for the device
 * (src/cuda/solver_device.cu). Both sides build without fused
 * multiply-adds (-ffp-contract=off, --fmad=false) and with IEEE division
 * and square root, so both give the same bits. Include only from those two
 * files; everyone else calls cfpo_local_solve and cfpo_min_dist2 of geom.h.
 * May include geom.h.
 *
 * LocalCFPO by clipping: for each y_i, its Voronoi cell restricted to S is
 * S cut by the bisector half-planes {c : |c - y_i| <= |c - y_j|}. On that
 * convex polygon the objective equals |c - y_i|, a convex function, so its
 * maximum is at a vertex. The maximum over S is the largest of these vertex
 * values. Every vertex is a corner of S, a point where a bisector (a Voronoi
 * edge) meets the boundary of S, or where two bisectors meet (a Voronoi
 * vertex): exactly the candidates of the paper's section 3.4, with no
 * triangulation to maintain. m is about 10, so O(m^2) clips are cheap, and
 * two prunings cut most of them: a cell whose polygon is already no farther
 * than the best value found is abandoned, and points are visited nearest to
 * the hint first so a good value is found early. */
#ifndef CFPO_SOLVER_IMPL_H
#define CFPO_SOLVER_IMPL_H

#include "geom.h"

#ifdef __CUDACC__
#define CFPO_HD __host__ __device__
#else
#define CFPO_HD
#endif

CFPO_HD static inline double cfpo_min_dist2_hd(double cx, double cy, const double *yx, const double *yy, int m, int skip)
{
    double best = INFINITY;
    for (int j = 0; j < m; j++) {
        if (j == skip) continue;
        double dx = cx - yx[j], dy = cy - yy[j];
        double d2 = dx * dx + dy * dy;
        if (d2 < best) best = d2;
    }
    return best;
}

/* Copies Y (minus skip) into px/py ordered by distance to the hint; ties
 * keep the given order (a stable sort). Returns the count. tmp: 2 m
 * doubles. Each point's place is counted (the keys below it, and the equal
 * keys before it): no data-dependent branches, where an insertion sort
 * mispredicts on most moves. If NaN keys make the places no permutation,
 * an insertion sort decides, as it did alone before; both give the same
 * order whenever the keys are numbers. */
CFPO_HD static inline int cfpo_order_by_hint_hd(const double *yx, const double *yy, int m, int skip, double hx, double hy,
                         double *px, double *py, double *key, double *tmp)
{
    int k = 0;
    for (int j = 0; j < m; j++) {
        if (j == skip) continue;
        double dx = yx[j] - hx, dy = yy[j] - hy;
        key[k] = dx * dx + dy * dy;
        tmp[k] = yx[j];
        tmp[m + k] = yy[j];
        k++;
    }
    if (k <= 64) {
        unsigned long long used = 0;
        for (int i = 0; i < k; i++) {
            const double ki = key[i];
            int r = 0;
            for (int j = 0; j < k; j++) r += (key[j] < ki) | ((key[j] == ki) & (j < i));
            px[r] = tmp[i];
            py[r] = tmp[m + i];
            used |= 1ULL << r;
        }
        if (used == (k == 64 ? ~0ULL : (1ULL << k) - 1)) return k;
    }
    for (int i = 0; i < k; i++) {
        const double d2 = key[i];
        int t = i;
        while (t > 0 && key[t - 1] > d2) {
            key[t] = key[t - 1];
            px[t] = px[t - 1];
            py[t] = py[t - 1];
            t--;
        }
        key[t] = d2;
        px[t] = tmp[i];
        py[t] = tmp[m + i];
    }
    return k;
}

/* The farthest point of S from (ax, ay) is a corner: its squared
 * distance bounds every point of y_i's cell. */
CFPO_HD static inline double cfpo_corner_far2_hd(const double corner[4][2], double ax, double ay)
{
    double ub = 0;
    for (int c = 0; c < 4; c++) {
        double dx = corner[c][0] - ax, dy = corner[c][1] - ay;
        double d2 = dx * dx + dy * dy;
        if (d2 > ub) ub = d2;
    }
    return ub;
}

/* The bisector of y_i = (ax, ay) and (bx, by): normal n = y_j - y_i,
 * midpoint m. 0 when y_j is 2 sqrt(far2) or more away: then it cannot cut
 * a polygon within sqrt(far2) of y_i. */
CFPO_HD static inline int cfpo_bisector_hd(double bx, double by, double ax, double ay, double far2, double *nx,
                                           double *ny, double *mx, double *my)
{
    *nx = bx - ax;
    *ny = by - ay;
    if (*nx * *nx + *ny * *ny >= 4 * far2) return 0;
    *mx = 0.5 * (bx + ax);
    *my = 0.5 * (by + ay);
    return 1;
}

/* The answer (bx, by) into S (clip rounding can leave a vertex a hair
 * outside), stored in *cx, *cy; returns its value from Y. */
CFPO_HD static inline double cfpo_solve_finish_hd(double bx, double by, cfpo_square S, const double *yx,
                                                  const double *yy, int m, int skip, double *cx, double *cy)
{
    if (bx < S.x0) bx = S.x0;
    if (bx > S.x1) bx = S.x1;
    if (by < S.y0) by = S.y0;
    if (by > S.y1) by = S.y1;
    *cx = bx;
    *cy = by;
    return cfpo_min_dist2_hd(bx, by, yx, yy, m, skip);
}

/* LocalCFPO over the Voronoi cells of the first `cells` points of Y in
 * hint order (all of them: the exact solver; one: the near solve, see
 * geom.h). */
CFPO_HD static inline double cfpo_solve_cells_hd(const double *yx, const double *yy, int m, int skip,
                                                 cfpo_square S, double hx, double hy, double floor2,
                                                 double *cx, double *cy, double *scratch, int cells)
{
    const size_t cap = 2 * ((size_t)m + 8);
    double *px = scratch, *py = px + m, *key = py + m;
    double *bufa = key + m + 8, *bufb = bufa + cap, *sd = bufb + cap;
    int k = cfpo_order_by_hint_hd(yx, yy, m, skip, hx, hy, px, py, key, bufa);

    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) return INFINITY;

    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    double best = floor2;
    double bx = *cx, by = *cy;
    int found = 0;

    const int kc = cells < k ? cells : k;
    for (int i = 0; i < kc; i++) {
        const double ax = px[i], ay = py[i];
        const double ub = cfpo_corner_far2_hd(corner, ax, ay);
        if (ub <= best) continue;

        double *poly = bufa, *next = bufb;
        int nv = 4;
        for (int c = 0; c < 4; c++) {
            poly[2 * c] = corner[c][0];
            poly[2 * c + 1] = corner[c][1];
        }
        int alive = 1;
        double far2 = ub;
        for (int j = 0; j < k && alive; j++) {
            if (j == i) continue;
            double nx, ny, mx, my;
            if (!cfpo_bisector_hd(px[j], py[j], ax, ay, far2, &nx, &ny, &mx, &my)) continue;
            /* Signed side of each vertex: <= 0 keeps it (closer to y_i). */
            double smax = -INFINITY, smin = INFINITY;
            for (int v = 0; v < nv; v++) {
                double s = (poly[2 * v] - mx) * nx + (poly[2 * v + 1] - my) * ny;
                sd[v] = s;
                if (s > smax) smax = s;
                if (s < smin) smin = s;
            }
            if (smax <= 0) continue;      /* bisector misses the polygon */
            if (smin > 0) { alive = 0; break; } /* polygon entirely closer to y_j */
            int nn = 0;
            far2 = 0;
            for (int v = 0; v < nv; v++) {
                int w = (v + 1 == nv) ? 0 : v + 1;
                double s0 = sd[v], s1 = sd[w];
                if (s0 <= 0) {
                    next[2 * nn] = poly[2 * v];
                    next[2 * nn + 1] = poly[2 * v + 1];
                    nn++;
                }
                if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
                    double t = s0 / (s0 - s1);
                    next[2 * nn] = poly[2 * v] + t * (poly[2 * w] - poly[2 * v]);
                    next[2 * nn + 1] = poly[2 * v + 1] + t * (poly[2 * w + 1] - poly[2 * v + 1]);
                    nn++;
                }
            }
            for (int v = 0; v < nn; v++) {
                double dx = next[2 * v] - ax, dy = next[2 * v + 1] - ay;
                double d2 = dx * dx + dy * dy;
                if (d2 > far2) far2 = d2;
            }
            double *t = poly;
            poly = next;
            next = t;
            nv = nn;
            if (nv == 0 || far2 <= best) alive = 0;
        }
        if (!alive) continue;
        for (int v = 0; v < nv; v++) {
            double dx = poly[2 * v] - ax, dy = poly[2 * v + 1] - ay;
            double d2 = dx * dx + dy * dy;
            if (d2 > best) {
                best = d2;
                bx = poly[2 * v];
                by = poly[2 * v + 1];
                found = 1;
            }
        }
    }
    if (!found) return -1.0;
    return cfpo_solve_finish_hd(bx, by, S, yx, yy, m, skip, cx, cy);
}

CFPO_HD static inline double cfpo_local_solve_hd(const double *yx, const double *yy, int m, int skip,
                                                cfpo_square S, double hx, double hy, double floor2,
                                                double *cx, double *cy, double *scratch)
{
    return cfpo_solve_cells_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, m);
}

#endif
