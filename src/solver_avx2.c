/* solver_avx2.c - LocalCFPO with AVX2 (host only, x86-64): the same
 * answer, bit for bit, as cfpo_local_solve_hd of solver_impl.h, which stays
 * the reference and the only code of the device and of other CPUs.
 * geom.c picks this one at run time where the CPU has AVX2.
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

#define TGT __attribute__((target("avx2")))

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

/* Bits v < nv of an 8-lane mask. */
static inline unsigned lanes(int nv) { return (1u << nv) - 1u; }

/* Slots of a small polygon buffer: up to 8 vertices, the first repeated
 * after the last, and a cut writes up to 2 per vertex. */
enum { SMALL = 24 };

/* The branch-free cut of a polygon of nv <= 8 vertices (x, y with room
 * for nv + 1). Returns -1 when the bisector misses the polygon, 0 when it
 * removes all of it, else the count written to ox, oy (which may exceed 8). */
TGT static int cut_small(double *x, double *y, int nv, double mx, double my, double nx, double ny, double *ox,
                         double *oy)
{
    const __m256d MX = _mm256_set1_pd(mx), MY = _mm256_set1_pd(my);
    const __m256d NX = _mm256_set1_pd(nx), NY = _mm256_set1_pd(ny), Z = _mm256_setzero_pd();
    __m256d X0 = _mm256_loadu_pd(x), X1 = _mm256_loadu_pd(x + 4);
    __m256d Y0 = _mm256_loadu_pd(y), Y1 = _mm256_loadu_pd(y + 4);
    __m256d S0 = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(X0, MX), NX), _mm256_mul_pd(_mm256_sub_pd(Y0, MY), NY));
    __m256d S1 = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(X1, MX), NX), _mm256_mul_pd(_mm256_sub_pd(Y1, MY), NY));
    const unsigned valid = lanes(nv);
    const unsigned pos = ((unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S0, Z, _CMP_GT_OQ)) |
                          (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S1, Z, _CMP_GT_OQ)) << 4) & valid;
    if (!pos) return -1; /* smax <= 0 */
    const unsigned keep = ((unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S0, Z, _CMP_LE_OQ)) |
                           (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S1, Z, _CMP_LE_OQ)) << 4) & valid;
    /* smin > 0: no side value below or at 0 that the plain loop's
     * minimum would take (a NaN it skips, and so does this test). */
    const unsigned neg = ((unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S0, Z, _CMP_LT_OQ)) |
                          (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(S1, Z, _CMP_LT_OQ)) << 4) & valid;
    if (!keep) return 0;
    /* The next vertex's side and coordinates (vertex 0 after the last). */
    double sd[SMALL];
    _mm256_storeu_pd(sd, S0);
    _mm256_storeu_pd(sd + 4, S1);
    sd[nv] = sd[0];
    x[nv] = x[0];
    y[nv] = y[0];
    const __m256d T0 = _mm256_loadu_pd(sd + 1), T1 = _mm256_loadu_pd(sd + 5);
    const __m256d W0 = _mm256_loadu_pd(x + 1), W1 = _mm256_loadu_pd(x + 5);
    const __m256d V0 = _mm256_loadu_pd(y + 1), V1 = _mm256_loadu_pd(y + 5);
    /* Sign change: (s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0). */
    const unsigned pos1 = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(T0, Z, _CMP_GT_OQ)) |
                          (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(T1, Z, _CMP_GT_OQ)) << 4;
    const unsigned neg1 = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(T0, Z, _CMP_LT_OQ)) |
                          (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(T1, Z, _CMP_LT_OQ)) << 4;
    const unsigned cross = ((neg & pos1) | (pos & neg1)) & valid;
    double ix[8], iy[8];
    const __m256d Q0 = _mm256_div_pd(S0, _mm256_sub_pd(S0, T0)), Q1 = _mm256_div_pd(S1, _mm256_sub_pd(S1, T1));
    _mm256_storeu_pd(ix, _mm256_add_pd(X0, _mm256_mul_pd(Q0, _mm256_sub_pd(W0, X0))));
    _mm256_storeu_pd(ix + 4, _mm256_add_pd(X1, _mm256_mul_pd(Q1, _mm256_sub_pd(W1, X1))));
    _mm256_storeu_pd(iy, _mm256_add_pd(Y0, _mm256_mul_pd(Q0, _mm256_sub_pd(V0, Y0))));
    _mm256_storeu_pd(iy + 4, _mm256_add_pd(Y1, _mm256_mul_pd(Q1, _mm256_sub_pd(V1, Y1))));
    int nn = 0;
    for (int v = 0; v < nv; v++) {
        ox[nn] = x[v];
        oy[nn] = y[v];
        nn += (int)(keep >> v & 1u);
        ox[nn] = ix[v];
        oy[nn] = iy[v];
        nn += (int)(cross >> v & 1u);
    }
    return nn;
}

/* The largest squared distance from (ax, ay) of the n <= 8 vertices. */
TGT static double far_small(const double *x, const double *y, int n, double ax, double ay)
{
    const __m256d AX = _mm256_set1_pd(ax), AY = _mm256_set1_pd(ay);
    const __m256i idx = _mm256_set_epi64x(3, 2, 1, 0), N = _mm256_set1_epi64x(n);
    __m256d acc = _mm256_setzero_pd();
    for (int h = 0; h < 8; h += 4) {
        const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(x + h), AX), dy = _mm256_sub_pd(_mm256_loadu_pd(y + h), AY);
        const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
        const __m256i in = _mm256_cmpgt_epi64(N, _mm256_add_epi64(idx, _mm256_set1_epi64x(h)));
        /* max(d2, acc) keeps acc when d2 is NaN, as `d2 > far2` does. */
        acc = _mm256_blendv_pd(acc, _mm256_max_pd(d2, acc), _mm256_castsi256_pd(in));
    }
    const __m128d m2 = _mm_max_pd(_mm256_castpd256_pd128(acc), _mm256_extractf128_pd(acc, 1));
    return _mm_cvtsd_f64(_mm_max_sd(_mm_unpackhi_pd(m2, m2), m2));
}

/* Does some bisector of (ax, ay) with another point put all of S strictly,
 * by the margin, on the other point's side? (See the proof above.) */
TGT static int cell_empty(const double *px, const double *py, int k, int i, double ax, double ay,
                          const double corner[4][2], double A)
{
    const __m256d AX = _mm256_set1_pd(ax), AY = _mm256_set1_pd(ay), H = _mm256_set1_pd(0.5);
    const __m256d AA = _mm256_set1_pd(A), EPS = _mm256_set1_pd(1e-12);
    const __m256d SIGN = _mm256_set1_pd(-0.0);
    for (int j0 = 0; j0 < k; j0 += 4) {
        double bx[4], by[4];
        for (int l = 0; l < 4; l++) {
            const int j = j0 + l < k ? j0 + l : i; /* lanes past k: y_i itself, never passes */
            bx[l] = px[j];
            by[l] = py[j];
        }
        const __m256d PX = _mm256_loadu_pd(bx), PY = _mm256_loadu_pd(by);
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
        if (_mm256_movemask_pd(all)) return 1;
    }
    return 0;
}

TGT double cfpo_local_solve_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                                 double hy, double floor2, double *cx, double *cy, double *scratch)
{
    const size_t cap = 2 * ((size_t)m + 8), half = (size_t)m + 8;
    double *px = scratch, *py = px + m, *key = py + m;
    double *bufa = key + m + 8, *bufb = bufa + cap, *sd = bufb + cap;
    int k = cfpo_order_by_hint_hd(yx, yy, m, skip, hx, hy, px, py, key);

    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) return INFINITY;

    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    const double A = fmax(fmax(fabs(S.x0), fabs(S.x1)), fmax(fabs(S.y0), fabs(S.y1)));
    double best = floor2;
    double bx = *cx, by = *cy;
    int found = 0;
    double sxa[SMALL] = {0}, sya[SMALL] = {0}, sxb[SMALL] = {0}, syb[SMALL] = {0};

    for (int i = 0; i < k; i++) {
        const double ax = px[i], ay = py[i];
        double ub = 0;
        for (int c = 0; c < 4; c++) {
            double dx = corner[c][0] - ax, dy = corner[c][1] - ay;
            double d2 = dx * dx + dy * dy;
            if (d2 > ub) ub = d2;
        }
        if (ub <= best) continue;
        if (cell_empty(px, py, k, i, ax, ay, corner, A)) continue;

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
            const double nx = px[j] - ax, ny = py[j] - ay;
            if (nx * nx + ny * ny >= 4 * far2) continue;
            const double mx = 0.5 * (px[j] + ax), my = 0.5 * (py[j] + ay);
            int nn;
            if (small) {
                nn = cut_small(x, y, nv, mx, my, nx, ny, ox, oy);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
            } else {
                double smax, smin;
                nn = cut_plain(x, y, nv, mx, my, nx, ny, sd, ox, oy, &smax, &smin);
                if (smax <= 0) continue;
                if (smin > 0) { alive = 0; break; }
            }
            if (nn <= 8) {
                far2 = far_small(ox, oy, nn, ax, ay);
            } else {
                far2 = 0;
                for (int v = 0; v < nn; v++) {
                    double dx = ox[v] - ax, dy = oy[v] - ay;
                    double d2 = dx * dx + dy * dy;
                    if (d2 > far2) far2 = d2;
                }
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
        for (int v = 0; v < nv; v++) {
            double dx = x[v] - ax, dy = y[v] - ay;
            double d2 = dx * dx + dy * dy;
            if (d2 > best) {
                best = d2;
                bx = x[v];
                by = y[v];
                found = 1;
            }
        }
    }
    if (!found) return -1.0;
    if (bx < S.x0) bx = S.x0;
    if (bx > S.x1) bx = S.x1;
    if (by < S.y0) by = S.y0;
    if (by > S.y1) by = S.y1;
    *cx = bx;
    *cy = by;
    return cfpo_min_dist2_hd(bx, by, yx, yy, m, skip);
}

int cfpo_solver_avx2_usable(void) { return __builtin_cpu_supports("avx2"); }

#else

double cfpo_local_solve_avx2(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                             double hy, double floor2, double *cx, double *cy, double *scratch)
{
    return cfpo_local_solve_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
}

int cfpo_solver_avx2_usable(void) { return 0; }

#endif
