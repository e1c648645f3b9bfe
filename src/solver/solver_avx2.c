/* solver_avx2.c - LocalCFPO with AVX2 (host only, x86-64): the same
 * answer, bit for bit, as cfpo_local_solve_hd of solver_impl.h, which stays
 * the reference and the only code of the device and of other CPUs.
 * geom.c picks this one at run time where the CPU has AVX2 but not the
 * AVX-512 route's instructions (solver_avx512.c, which shares this file's
 * proof, its plain cut of large polygons and its prefilter).
 *
 * What changes, and why the bits do not:
 *
 * 1. A polygon of up to 8 vertices is cut by a bisector without branches:
 *    the 8 side values in two 4-lane registers, the crossing points of all
 *    edges at once, then the kept vertices and crossings written in vertex
 *    order (a store at every step, the write index advanced by 0 or 1).
 *    Each value is computed by the same operations in the same order as
 *    the plain loop (a multiply and an add are never fused: the build uses
 *    -ffp-contract=off and these functions enable no FMA), the same tests
 *    (<= 0 keeps a vertex, strict sign change makes a crossing) and the
 *    same vertex order, so every polygon is the same list of doubles.
 *    The farthest vertex is a maximum, whatever the order it is taken in.
 *    Larger polygons (rare) go through the plain cut on the same data.
 *
 * 2. A prefilter skips the cell of y_i when one bisector (with y_j) puts
 *    all four corners of S strictly on y_j's side by a margin: then the
 *    plain loop kills the cell (no vertex of it is ever compared to the
 *    best), so skipping it changes nothing. Proof: the side function
 *    s(c) = (c_x - m_x) n_x + (c_y - m_y) n_y is affine, n and m computed
 *    by the same expressions in both, so its minimum over S is at a
 *    corner. Every vertex the plain loop holds is a corner of S or a
 *    point p + t (q - p), t in [0, 1], of two earlier vertices: it lies
 *    in S up to a few units in the last place of A = max|corner coord|
 *    per cut, and its computed side differs from the exact one by a few
 *    units in the last place of T = (A + |m_x|) |n_x| + (A + |m_y|) |n_y|.
 *    The margin, s(corner) > 1e-12 T at all four corners as computed,
 *    exceeds these errors by orders of magnitude (a polygon is cut fewer
 *    than 10^3 times; 10^3 cuts drift by about 10^-13 A), so when the
 *    plain loop reaches bisector j every vertex has s > 0: smin > 0, the
 *    cell dies. If it is not reached, or skipped for distance (which
 *    cannot happen here: a polygon within sqrt(far2) of y_i lies on y_i's
 *    side of a bisector 2 sqrt(far2) away), the cell died or was cut away
 *    before. NaN or infinite inputs never pass the test. */
#include "geom.h"

#include "solver_impl.h"
#include "solver_simd.h"

#if CFPO_SOLVER_AVX2

#include <immintrin.h>
#include <string.h>

#include "solver_cut256.h"

/* The plain cut (solver_impl.h's loop) on a polygon stored as x[], y[]:
 * writes the kept part into ox, oy, returns its count; *smax, *smin as the
 * plain loop has them. */
static int cut_plain(const double *x, const double *y, int nv, double mx, double my, double nx, double ny,
                     double *sd, double *ox, double *oy, double *smax_, double *smin_)
{
    double smax = -INFINITY, smin = INFINITY;
    for (int v = 0; v < nv; v++) {
        double s = (x[v] - mx) * nx + (y[v] - my) * ny;
        sd[v] = s;
        if (s > smax) smax = s;
        if (s < smin) smin = s;
    }
    *smax_ = smax;
    *smin_ = smin;
    if (smax <= 0 || smin > 0) return nv;
    int nn = 0;
    for (int v = 0; v < nv; v++) {
        int w = (v + 1 == nv) ? 0 : v + 1;
        double s0 = sd[v], s1 = sd[w];
        if (s0 <= 0) {
            ox[nn] = x[v];
            oy[nn] = y[v];
            nn++;
        }
        if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
            double t = s0 / (s0 - s1);
            ox[nn] = x[v] + t * (x[w] - x[v]);
            oy[nn] = y[v] + t * (y[w] - y[v]);
            nn++;
        }
    }
    return nn;
}

int cfpo_simd_cut_large(const double *x, const double *y, int nv, double mx, double my, double nx, double ny,
                        double ax, double ay, double *sd, double *ox, double *oy, double *far2)
{
    double smax, smin;
    const int nn = cut_plain(x, y, nv, mx, my, nx, ny, sd, ox, oy, &smax, &smin);
    if (smax <= 0) return -1;
    if (smin > 0) return 0;
    double f = 0;
    for (int v = 0; v < nn; v++) {
        double dx = ox[v] - ax, dy = oy[v] - ay;
        double d2 = dx * dx + dy * dy;
        if (d2 > f) f = d2;
    }
    *far2 = f;
    return nn;
}

/* Does some bisector of (ax, ay) with another point put all of S strictly,
 * by the margin, on the other point's side? (See the proof above.) The
 * AVX-512 route's prefilter too. */
TGT int cfpo_simd_cell_empty(const double *px, const double *py, int k, double ax, double ay,
                         const double corner[4][2], double A)
{
    const __m256d AX = _mm256_set1_pd(ax), AY = _mm256_set1_pd(ay), H = _mm256_set1_pd(0.5);
    const __m256d AA = _mm256_set1_pd(A), EPS = _mm256_set1_pd(1e-12);
    const __m256d SIGN = _mm256_set1_pd(-0.0);
    for (int j0 = 0; j0 < k; j0 += 4) {
        /* lanes past k read the scratch after px (py) and after py (the
         * keys): numbers the lane mask below throws away */
        const __m256d PX = _mm256_loadu_pd(px + j0), PY = _mm256_loadu_pd(py + j0);
        const __m256d NX = _mm256_sub_pd(PX, AX), NY = _mm256_sub_pd(PY, AY);
        const __m256d MX = _mm256_mul_pd(H, _mm256_add_pd(PX, AX)), MY = _mm256_mul_pd(H, _mm256_add_pd(PY, AY));
        const __m256d T = _mm256_add_pd(_mm256_mul_pd(_mm256_add_pd(AA, _mm256_andnot_pd(SIGN, MX)), _mm256_andnot_pd(SIGN, NX)),
                                        _mm256_mul_pd(_mm256_add_pd(AA, _mm256_andnot_pd(SIGN, MY)), _mm256_andnot_pd(SIGN, NY)));
        const __m256d thr = _mm256_mul_pd(EPS, T);
        __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        for (int c = 0; c < 4; c++) {
            const __m256d s = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(corner[c][0]), MX), NX),
                                            _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(corner[c][1]), MY), NY));
            all = _mm256_and_pd(all, _mm256_cmp_pd(s, thr, _CMP_GT_OQ));
        }
        const int rest = k - j0;
        if ((unsigned)_mm256_movemask_pd(all) & (rest >= 4 ? 15u : lanes(rest))) return 1;
    }
    return 0;
}

/* cfpo_solve_cells_hd of solver_impl.h, bit for bit. */
TGT double cfpo_solve_cells_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                                 double hy, double floor2, double *cx, double *cy, double *scratch, int cells)
{
    const size_t cap = 2 * ((size_t)m + 8), half = (size_t)m + 8;
    double *px = scratch, *py = px + m, *key = py + m;
    double *bufa = key + m + 8, *bufb = bufa + cap, *sd = bufb + cap;
    int k = cfpo_order_by_hint_hd(yx, yy, m, skip, hx, hy, px, py, key, bufa);

    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) return INFINITY;

    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    const double A = fmax(fmax(fabs(S.x0), fabs(S.x1)), fmax(fabs(S.y0), fabs(S.y1)));
    double best = floor2;
    double bx = *cx, by = *cy;
    int found = 0;
    double sxa[SMALL] = {0}, sya[SMALL] = {0}, sxb[SMALL] = {0}, syb[SMALL] = {0};

    const int kc = cells < k ? cells : k;
    for (int i = 0; i < kc; i++) {
        const double ax = px[i], ay = py[i];
        const double ub = cfpo_corner_far2_hd(corner, ax, ay);
        if (ub <= best) continue;
        if (cells > 1 && cfpo_simd_cell_empty(px, py, k, ax, ay, corner, A)) continue;

        /* The polygon: small (<= 8 vertices) in sx, sy; else in the
         * scratch buffers (x at 0, y at half). */
        double *x = sxa, *y = sya, *ox = sxb, *oy = syb;
        int small = 1, nv = 4;
        for (int c = 0; c < 4; c++) {
            x[c] = corner[c][0];
            y[c] = corner[c][1];
        }
        int alive = 1;
        double far2 = ub;
        for (int j = 0; j < k && alive; j++) {
            if (j == i) continue;
            double nx, ny, mx, my;
            if (!cfpo_bisector_hd(px[j], py[j], ax, ay, far2, &nx, &ny, &mx, &my)) continue;
            int nn;
            if (small) {
                nn = cut_small(x, y, nv, mx, my, nx, ny, ax, ay, ox, oy, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
            } else {
                nn = cfpo_simd_cut_large(x, y, nv, mx, my, nx, ny, ax, ay, sd, ox, oy, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
            }
            if (small && nn > 8) { /* move to the large buffers */
                memcpy(bufa, ox, (size_t)nn * sizeof *ox);
                memcpy(bufa + half, oy, (size_t)nn * sizeof *oy);
                x = bufa, y = bufa + half, ox = bufb, oy = bufb + half;
                small = 0;
            } else {
                double *t = x; x = ox; ox = t;
                t = y; y = oy; oy = t;
            }
            nv = nn;
            if (far2 <= best) alive = 0;
        }
        if (!alive) continue;
        found |= cfpo_simd_best_vertex(x, y, nv, ax, ay, &best, &bx, &by);
    }
    if (!found) return -1.0;
    return cfpo_solve_finish_hd(bx, by, S, yx, yy, m, skip, cx, cy);
}

int cfpo_solver_avx2_usable(void) { return __builtin_cpu_supports("avx2"); }

#else

double cfpo_solve_cells_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                             double hy, double floor2, double *cx, double *cy, double *scratch, int cells)
{
    return cfpo_solve_cells_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
}

int cfpo_solver_avx2_usable(void) { return 0; }

#endif

double cfpo_local_solve_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                             double hy, double floor2, double *cx, double *cy, double *scratch)
{
    return cfpo_solve_cells_avx2(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, m);
}
