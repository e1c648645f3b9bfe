/* dens_solve_avx512.c - layer 2, host only: the density solve's AVX-512
 * route, the same bits as the plain route (dens_solve_plain.c).
 *
 * The polygons are clipped as LocalCFPO's AVX-512 route clips them: a
 * polygon of up to 8 vertices lives in two 8-lane registers and each cut
 * is one pass of lane operations (solver_cut512.h), with the plain loop's
 * operations in its order, so every polygon is the same list of doubles.
 * A polygon that grows past 8 vertices (rare) is written out and goes on
 * with the plain cut. The lines, the prunings and the vertex evaluation
 * are the plain route's own functions (dens_clip.h). */
#include "dens_clip.h"
#include "solver_cut512.h"

#if CFPO_SOLVER_AVX2

/* dens_geo_plain eight neighbours at a time: the same values (each lane's
 * term by the plain loop's operations; y_i's own lane gives the value geo
 * starts from, and min_pd(v, g) keeps g when v is NaN, as `v < geo`
 * does), the stop tested after each eight. */
T512 static double geo8(double px, double py, const double *yx, const double *yy, const double *yr, int k, int i,
                        double geo, double qhi, double best)
{
    (void)i;
    const __m512d PX = _mm512_set1_pd(px), PY = _mm512_set1_pd(py);
    __m512d G = _mm512_set1_pd(geo);
    for (int j = 0; j < k; j += 8) {
        const __mmask8 m = first_lanes(k - j < 8 ? k - j : 8);
        const __m512d dx = _mm512_sub_pd(PX, _mm512_maskz_loadu_pd(m, yx + j));
        const __m512d dy = _mm512_sub_pd(PY, _mm512_maskz_loadu_pd(m, yy + j));
        const __m512d v = _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)),
                                        _mm512_maskz_loadu_pd(m, yr + j));
        G = _mm512_mask_min_pd(G, m, v, G);
        geo = _mm512_reduce_min_pd(G);
        if (!(geo * qhi > best)) break;
    }
    return geo;
}

T512 double cfpo_dens_value_avx512(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                                  double cy)
{
    return geo8(cx, cy, yx, yy, yr, k, 0, INFINITY, 1, -INFINITY) * rc;
}

T512 int cfpo_dens_solve_avx512(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                                cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy,
                                double floor_f, double *cx, double *cy, double *f, double *scratch)
{
    const int vmax = k + 8;
    double *bufa = scratch, *bufb = bufa + 2 * (size_t)vmax, *tl = bufb + 3 * (size_t)vmax, *hl = tl + vmax;
    const __m512d SX = _mm512_set_pd(0, 0, 0, 0, S.x0, S.x1, S.x1, S.x0);
    const __m512d SY = _mm512_set_pd(0, 0, 0, 0, S.y1, S.y1, S.y0, S.y0);
    double best = floor_f, spx[24], spy[24];
    int found = found0;
    for (int i = i0; i < m; i++) {
        const double ax = yx[i], ay = yy[i], wi = w[i];
        double corner[4][2];
        double far2 = dens_corners(S, ax, ay, corner);
        if (qhi * far2 * yr[i] <= best) continue;
        dens_lines(ax, ay, wi, yx, yy, w, k, tl, hl);
        __m512d PX = SX, PY = SY;
        double *poly = bufa, *next = bufb;
        int nv = 4, alive = 1, small = 1;
        for (int j = 0; j < k && alive; j++) {
            if (j == i || hl[j] >= far2) continue; /* the line misses the polygon */
            const double nx = yx[j] - ax, ny = yy[j] - ay, mx = ax + tl[j] * nx, my = ay + tl[j] * ny;
            int nn;
            if (small) {
                nn = cut8(&PX, &PY, nv, mx, my, nx, ny, ax, ay, spx, spy, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
                if (nn > 8) { /* on in memory, interleaved, with the plain cut */
                    for (int v = 0; v < nn; v++) {
                        poly[2 * v] = spx[v];
                        poly[2 * v + 1] = spy[v];
                    }
                    small = 0;
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
        if (small) {
            _mm512_storeu_pd(spx, PX);
            _mm512_storeu_pd(spy, PY);
            found |= dens_eval(spx, spy, 1, nv, i, yx, yy, yr, k, S, d, qhi, ox, oy, &best, cx, cy, geo8);
        } else {
            found |= dens_eval(poly, poly + 1, 2, nv, i, yx, yy, yr, k, S, d, qhi, ox, oy, &best, cx, cy, geo8);
        }
    }
    *f = found ? best : -1;
    return found;
}

#else

double cfpo_dens_value_avx512(const double *yx, const double *yy, const double *yr, int k, double rc, double cx,
                              double cy)
{
    return cfpo_dens_value_plain(yx, yy, yr, k, rc, cx, cy);
}

int cfpo_dens_solve_avx512(const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m, int found0,
                           cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                           double *cx, double *cy, double *f, double *scratch)
{
    return cfpo_dens_solve_plain(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch);
}

#endif
