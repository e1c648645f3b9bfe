/* dens_solve_avx2.c - layer 2, host only: the density solve's AVX2
 * route, the same bits as the plain route (dens_solve_plain.c), for CPUs
 * with AVX2 and without the AVX-512 route's instructions.
 *
 * The polygons are clipped as LocalCFPO's AVX2 route clips them: a
 * polygon of up to 8 vertices is cut in two 4-lane registers a coordinate
 * (solver_cut256.h), with the plain loop's operations in its order, so
 * every polygon is the same list of doubles. A polygon that grows past 8
 * vertices (rare) is written out and goes on with the plain cut
 * (dens_cut), as is one whose cut the plain loop would have cut short
 * (its output buffer's bound, vmax: never met in practice, kept exact).
 * The lines, the prunings and the vertex evaluation are the plain route's
 * own functions (dens_clip.h); a vertex's value takes four neighbours a
 * step, and so does f at a spot (cfpo_dens_value's AVX2 route). */
#include "dens_clip.h"
#include "solver_cut256.h"

#if CFPO_SOLVER_AVX2

/* dens_geo_plain four neighbours at a time: the same values (each lane's
 * term by the plain loop's operations; y_i's own lane gives the value geo
 * starts from, and min_pd(v, g) keeps g when v is NaN, as `v < geo`
 * does), the stop tested after each four. A value that stops the plain
 * loop stops this one by the end (the min only falls), and one that does
 * not is the same min. */
TGT static double geo4(double px, double py, const double *yx, const double *yy, const double *yr, int k, int i,
                       double geo, double qhi, double best)
{
    (void)i;
    const __m256d PX = _mm256_set1_pd(px), PY = _mm256_set1_pd(py);
    __m256d G = _mm256_set1_pd(geo);
    for (int j = 0; j < k; j += 4) {
        const int rest = k - j;
        const __m256i in = _mm256_cmpgt_epi64(_mm256_set1_epi64x(rest), _mm256_set_epi64x(3, 2, 1, 0));
        const __m256d dx = _mm256_sub_pd(PX, _mm256_maskload_pd(yx + j, in));
        const __m256d dy = _mm256_sub_pd(PY, _mm256_maskload_pd(yy + j, in));
        const __m256d v = _mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                        _mm256_maskload_pd(yr + j, in));
        G = _mm256_blendv_pd(G, _mm256_min_pd(v, G), _mm256_castsi256_pd(in));
        const __m128d m2 = _mm_min_pd(_mm256_castpd256_pd128(G), _mm256_extractf128_pd(G, 1));
        geo = _mm_cvtsd_f64(_mm_min_sd(_mm_unpackhi_pd(m2, m2), m2));
        if (!(geo * qhi > best)) break;
    }
    return geo;
}

TGT double cfpo_dens_value_avx2(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                                double cy)
{
    return geo4(cx, cy, yx, yy, yr, k, 0, INFINITY, 1, -INFINITY) * rc;
}

/* The polygon (x, y: nv vertices) written interleaved into poly. */
static inline void interleave(const double *x, const double *y, int nv, double *poly)
{
    for (int v = 0; v < nv; v++) {
        poly[2 * v] = x[v];
        poly[2 * v + 1] = y[v];
    }
}

TGT int cfpo_dens_solve_avx2(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                             cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                             double *cx, double *cy, double *f, double *scratch)
{
    const int vmax = k + 8;
    double *bufa = scratch, *bufb = bufa + 2 * (size_t)vmax, *tl = bufb + 3 * (size_t)vmax, *hl = tl + vmax;
    double best = floor_f, sxa[SMALL], sya[SMALL], sxb[SMALL], syb[SMALL];
    for (int v = 0; v < 8; v++) sxa[v] = sya[v] = sxb[v] = syb[v] = 0; /* the lanes a cut loads (past nv: masked) */
    int found = found0;
    for (int i = i0; i < m; i++) {
        const double ax = yx[i], ay = yy[i], wi = w[i];
        double corner[4][2];
        double far2 = dens_corners(S, ax, ay, corner);
        if (qhi * far2 * yr[i] <= best) continue;
        dens_lines(ax, ay, wi, yx, yy, w, k, tl, hl);
        double *x = sxa, *y = sya, *nx_ = sxb, *ny_ = syb, *poly = bufa, *next = bufb;
        for (int c = 0; c < 4; c++) {
            x[c] = corner[c][0];
            y[c] = corner[c][1];
        }
        int nv = 4, alive = 1, small = 1;
        for (int j = 0; j < k && alive; j++) {
            if (j == i || hl[j] >= far2) continue; /* the line misses the polygon */
            const double nx = yx[j] - ax, ny = yy[j] - ay, mx = ax + tl[j] * nx, my = ay + tl[j] * ny;
            int nn;
            if (small) {
                nn = cut_small(x, y, nv, mx, my, nx, ny, ax, ay, nx_, ny_, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
                if (nn + 1 >= vmax) { /* the plain cut stops at its bound: that cut, from the same polygon */
                    interleave(x, y, nv, poly);
                    small = 0;
                    nn = dens_cut(&poly, nv, mx, my, nx, ny, ax, ay, vmax, &next, &far2);
                } else if (nn > 8) { /* on in memory, interleaved, with the plain cut */
                    interleave(nx_, ny_, nn, poly);
                    small = 0;
                } else {
                    double *t = x; x = nx_; nx_ = t;
                    t = y; y = ny_; ny_ = t;
                }
            } else {
                if (nv > DENS_BIG) break;
                nn = dens_cut(&poly, nv, mx, my, nx, ny, ax, ay, vmax, &next, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
            }
            nv = nn;
            if (qhi * far2 * yr[i] <= best) alive = 0;
        }
        if (!alive) continue;
        if (small)
            found |= dens_eval(x, y, 1, nv, i, yx, yy, yr, k, S, d, qhi, ox, oy, &best, cx, cy, geo4);
        else
            found |= dens_eval(poly, poly + 1, 2, nv, i, yx, yy, yr, k, S, d, qhi, ox, oy, &best, cx, cy, geo4);
    }
    *f = found ? best : -1;
    return found;
}

#else

double cfpo_dens_value_avx2(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                            double cy)
{
    return cfpo_dens_value_plain(yx, yy, yr, k, rc, cx, cy);
}

int cfpo_dens_solve_avx2(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                         cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                         double *cx, double *cy, double *f, double *scratch)
{
    return cfpo_dens_solve_plain(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch);
}

#endif
