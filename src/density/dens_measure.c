/* dens_measure.c - layer 2: see dens_measure.h. Grid of about 2 points per
 * cell at the mean density; a point looks at rings of cells outward until
 * no unvisited point can be nearer in m: every such point is at least k L
 * away (k the rings seen), so its d^2 q_j is at least (k L)^2 q_lo with
 * q_lo the smallest q (= sqrt(rho)) it can have. Beyond R, with R^2 q_min
 * = the best d^2 q_j so far (q_min the density's smallest non-zero q), no
 * point can win, so q_lo is the smallest q over the box of half-side R
 * around the point (a pyramid of minima, dens_qbound.h); the density's
 * global q_min alone made a point of a dense region beside a sparse one
 * scan rings until (k L)^2 q_min passed its value, 17% of an iteration at
 * a million points on the shipped image. A ring's stop also counts the
 * point's own distance to its cell's side (every point past ring k is at
 * least (k + that) L away). The result is the exact minimum, whatever the
 * rings seen. Once the rings cover the torus every cell has
 * been seen once. The bound from the point's own cell's best also skips
 * the cells of ring 1 whose box lies too far to hold a winner. */
#include "dens_measure.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "dens_qbound.h"
#include "geom.h"
#include "omp_compat.h"

static inline double wrapd(double d) { return d - rint(d); }

void cfpo_dens_nn_near_free(cfpo_dens_nn_near *c)
{
    free(c->q);
    *c = (cfpo_dens_nn_near){0};
}

/* near's bounds for the grid g over qlow (kept when they are for it);
 * 0, or -1 when out of memory. */
static int near_fit(cfpo_dens_nn_near *c, const cfpo_dens_qbound *qlow, int64_t g)
{
    if (c->q && c->g == g && c->qlow == qlow) return 0;
    float *v = realloc(c->q, (size_t)(g * g) * sizeof *v);
    if (!v) return -1;
    c->q = v;
    const double L = 1.0 / (double)g, K = CFPO_DENS_NN_NEAR;
    for (int64_t cy = 0; cy < g; cy++)
        for (int64_t cx = 0; cx < g; cx++) { /* a float at most the least q there */
            const double x0 = ((double)cx - K) * L, y0 = ((double)cy - K) * L;
            const double m = cfpo_dens_qbound_box_finer(qlow, x0, y0, x0 + (2 * K + 1) * L, y0 + (2 * K + 1) * L,
                                                        CFPO_DENS_NN_FINER);
            const float f = (float)m;
            v[cy * g + cx] = (double)f > m ? nextafterf(f, 0) : f;
        }
    c->g = g;
    c->qlow = qlow;
    return 0;
}

int cfpo_dens_nn_first(const cfpo_density *d, const cfpo_dens_qbound *qlow, cfpo_dens_nn_near *near, const double *xy,
                            const double *q, size_t n, size_t k, double D, double *mm, int nthreads)
{
    const int nt = nthreads > 0 ? nthreads : omp_get_max_threads();
    cfpo_dens_qbound own;
    if (!qlow) {
        if (cfpo_dens_qbound_build_min(&own, d) != 0) return -1;
        qlow = &own;
    }
    int64_t g = (int64_t)floor(sqrt((double)n / 2));
    if (g < 1) g = 1;
    if (g > 4096) g = 4096;
    const double L = 1.0 / (double)g;
    size_t *start = calloc((size_t)(g * g) + 1, sizeof *start), *fill = malloc((size_t)(g * g) * sizeof *fill);
    size_t *idx = malloc((n ? n : 1) * sizeof *idx);
    double *rho = malloc((n ? n : 1) * sizeof *rho);
    int64_t *cell = malloc((n ? n : 1) * sizeof *cell);
    /* the points in cell order (x, y, q a slot) and each one's slot: the
     * scan reads its cells' points one after another */
    double *pt = malloc((n ? n : 1) * 3 * sizeof *pt);
    int rc = -1;
    if (!start || !fill || !idx || !rho || !cell || !pt || (near && near_fit(near, qlow, g) != 0)) goto done;
    const float *nq = near ? near->q : NULL;
    const double nreach = (CFPO_DENS_NN_NEAR - 0.5) * L; /* a reach within this stays inside a cell's near cells */
    for (size_t i = 0; i < n; i++) {
        int64_t cx = (int64_t)(xy[2 * i] * (double)g), cy = (int64_t)(xy[2 * i + 1] * (double)g);
        cx = cx < 0 ? 0 : cx >= g ? g - 1 : cx;
        cy = cy < 0 ? 0 : cy >= g ? g - 1 : cy;
        cell[i] = cy * g + cx;
        start[cell[i] + 1]++;
        rho[i] = q ? q[i] : sqrt(cfpo_density_at(d, xy[2 * i], xy[2 * i + 1])); /* q = sqrt(rho) */
    }
    for (int64_t c = 0; c < g * g; c++) start[c + 1] += start[c];
    for (int64_t c = 0; c < g * g; c++) fill[c] = start[c];
    for (size_t i = 0; i < n; i++) {
        const size_t s = fill[cell[i]]++;
        idx[i] = s;
        pt[3 * s] = xy[2 * i];
        pt[3 * s + 1] = xy[2 * i + 1];
        pt[3 * s + 2] = rho[i];
    }
    const double lo = sqrt(d->rho_min);
#pragma omp parallel for num_threads(nt) schedule(dynamic, 1024)
    for (size_t i = 0; i < k; i++) {
        const double x = xy[2 * i], y = xy[2 * i + 1], ri = rho[i];
        const size_t si = idx[i];
        if (!(ri > 0)) { mm[i] = 0; continue; }
        const int64_t cy = cell[i] / g, cx = cell[i] - cy * g;
        /* the point's place in its cell, in cells: with ql, the smallest q
         * a winner can have, a cell of ring 1 whose box is too far to hold
         * one is skipped */
        const double fx = x * (double)g - (double)cx, fy = y * (double)g - (double)cy;
        /* every point past ring k is at least (k + fm) L away: fm the
         * point's distance to its cell's nearest side, in cells */
        double fm = fx < 1 - fx ? fx : 1 - fx;
        fm = fy < fm ? fy : fm;
        fm = 1 - fy < fm ? 1 - fy : fm;
        fm = fm > 0 ? fm : 0;
        double best = INFINITY; /* d^2 q_j, the smallest so far */
        double ql = lo, qlbest = INFINITY; /* ql bounds q over the box of the reach of qlbest */
        /* rings 0 and 1 at once where they wrap no index: three runs of
         * slots (rows cy - 1 .. cy + 1, cells cx - 1 .. cx + 1), every
         * point's value as the ring scan computes it (no wrap of the
         * differences, as there), with no test per cell; the minimum is
         * the same, and the scan goes on from ring 2 only when the tests
         * after ring 1 cannot stop it */
        const int64_t k0 = g >= 5 && cx >= 1 && cx + 1 < g && cy >= 1 && cy + 1 < g;
        if (k0) {
            double b0 = INFINITY, b1 = INFINITY;
            for (int64_t dy = -1; dy <= 1; dy++) {
                const size_t *row = start + (cy + dy) * g;
                const size_t s1 = row[cx + 2];
                size_t s = row[cx - 1];
                for (; s + 1 < s1; s += 2) { /* two running minima, as the ring scan keeps */
                    const double ex0 = pt[3 * s] - x, ey0 = pt[3 * s + 1] - y;
                    const double ex1 = pt[3 * s + 3] - x, ey1 = pt[3 * s + 4] - y;
                    const double v0 = (ex0 * ex0 + ey0 * ey0) * pt[3 * s + 2];
                    const double v1 = (ex1 * ex1 + ey1 * ey1) * pt[3 * s + 5];
                    b0 = s == si ? b0 : v0 < b0 ? v0 : b0;
                    b1 = s + 1 == si ? b1 : v1 < b1 ? v1 : b1;
                }
                if (s < s1) {
                    const double ex = pt[3 * s] - x, ey = pt[3 * s + 1] - y;
                    const double v = (ex * ex + ey * ey) * pt[3 * s + 2];
                    b0 = s == si ? b0 : v < b0 ? v : b0;
                }
            }
            best = b0 < b1 ? b0 : b1;
        }
        for (int64_t k = k0;; k++) {
            const int all = 2 * k + 1 >= g;
            const int64_t kk = all ? (g - 1) / 2 : k, kx0 = all ? -kk : -k, kx1 = all ? g - 1 - kk : k;
            /* two running minima (cells of even and odd dx), so that the
             * compares of one cell need not wait for the last cell's; the
             * minimum is the same */
            double b0 = best, b1 = best;
            if (!(k0 && k == 1)) { /* rings 0 and 1 were scanned above */
                /* rings that wrap no cell index: every point seen is within
                 * (k + 1) L < 0.5 of (x, y) along each axis, so wrapd would
                 * subtract rint = 0 (the same bits) */
                const int wr = all || 2 * (k + 1) >= g || cx < k || cx + k >= g || cy < k || cy + k >= g;
                for (int64_t dy = kx0; dy <= kx1; dy++) {
                    /* cy + dy lies in (-g, 2g): one wrap, no division */
                    int64_t yy = cy + dy;
                    yy = yy < 0 ? yy + g : yy >= g ? yy - g : yy;
                    const size_t *row = start + yy * g;
                    for (int64_t dx = kx0; dx <= kx1; dx++) {
                        if (!all && k > 0 && dx > -k && dx < k && dy > -k && dy < k) { dx = k - 1; continue; } /* inner rings done */
                        if (all && k > 0) {
                            /* cells seen in rings below k are skipped */
                            const int64_t ring = llabs(dx) > llabs(dy) ? llabs(dx) : llabs(dy);
                            if (ring < k) continue;
                        }
                        if (k == 1 && !all) { /* the box's distance, in cells, rounded down a little */
                            const double ex = dx > 0 ? 1 - fx : dx < 0 ? fx : 0, ey = dy > 0 ? 1 - fy : dy < 0 ? fy : 0;
                            const double e = (ex * ex + ey * ey) * L * L * (1 - 1e-9);
                            if (e * ql > (b0 < b1 ? b0 : b1) * (1 + 1e-9)) continue;
                        }
                        int64_t xx = cx + dx;
                        xx = xx < 0 ? xx + g : xx >= g ? xx - g : xx;
                        double bb = INFINITY;
                        for (size_t s = row[xx]; s < row[xx + 1]; s++) {
                            double ex = pt[3 * s] - x, ey = pt[3 * s + 1] - y;
                            if (wr) { ex = wrapd(ex); ey = wrapd(ey); }
                            const double v = (ex * ex + ey * ey) * pt[3 * s + 2];
                            bb = s == si ? bb : v < bb ? v : bb;
                        }
                        if (dx & 1) b1 = bb < b1 ? bb : b1;
                        else b0 = bb < b0 ? bb : b0;
                    }
                }
            }
            best = b0 < b1 ? b0 : b1;
            if (all) break;
            const double reach = ((double)k + fm) * L * (1 - 1e-9);
            if (reach * reach * lo >= best) break;
            if (best < INFINITY) {
                /* past R no point can win; q over that box bounds the
                 * winner's, for ring 1's cells and the stop. A bound from
                 * an older best (a wider box) holds too; it is made again
                 * only when it cannot stop the scan */
                if (k > 0 && reach * reach * ql >= best * (1 + 1e-9)) break;
                if (best < qlbest && (k > 0 || ri > 1.2 * lo)) { /* after ring 0 only where it can prune */
                    const double R = sqrt(best / lo) * (1 + 1e-9) + L;
                    ql = nq && R <= nreach ? (double)nq[cell[i]]
                                           : cfpo_dens_qbound_box_finer(qlow, x - R, y - R, x + R, y + R, CFPO_DENS_NN_FINER);
                    if (ql < lo) ql = lo;
                    qlbest = best;
                    if (k > 0 && reach * reach * ql >= best * (1 + 1e-9)) break;
                }
            }
        }
        mm[i] = sqrt(best * ri) / D; /* d (q_i q_j)^(1/2) / Delta */
    }
    rc = 0;
done:
    free(start); free(fill); free(idx); free(rho); free(cell); free(pt);
    if (qlow == &own) cfpo_dens_qbound_free(&own);
    return rc;
}

int cfpo_dens_nn(const cfpo_density *d, const double *xy, size_t n, double *m, double *delta_min, double *delta_avg)
{
    return cfpo_dens_nn_q(d, NULL, NULL, xy, NULL, n, m, delta_min, delta_avg, 0);
}

int cfpo_dens_nn_q(const cfpo_density *d, const cfpo_dens_qbound *qlow, cfpo_dens_nn_near *near, const double *xy,
                        const double *q, size_t n, double *m, double *delta_min, double *delta_avg, int nthreads)
{
    double *mm = m ? m : malloc(n * sizeof *mm);
    if (!mm || cfpo_dens_nn_first(d, qlow, near, xy, q, n, n, cfpo_delta_bound((double)n), mm, nthreads) != 0) {
        if (!m) free(mm);
        return -1;
    }
    cfpo_dens_nn_sum(mm, n, delta_min, delta_avg);
    if (!m) free(mm);
    return 0;
}

void cfpo_dens_nn_sum(const double *mm, size_t n, double *delta_min, double *delta_avg)
{
    double mn = INFINITY, sum = 0;
    for (size_t i = 0; i < n; i++) {
        if (mm[i] < mn) mn = mm[i];
        sum += mm[i];
    }
    *delta_min = mn;
    *delta_avg = sum / (double)n;
}
