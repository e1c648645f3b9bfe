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

/* Bits v < nv of an 8-lane mask. */
static inline unsigned lanes(int nv) { return (1u << nv) - 1u; }

/* Slots of a small polygon buffer: up to 8 vertices, the first repeated
 * after the last, and a cut writes up to 2 per vertex. */
enum { SMALL = 24 };

static inline __m256d side(__m256d X, __m256d Y, __m256d MX, __m256d MY, __m256d NX, __m256d NY) TGT;
static inline __m256d side(__m256d X, __m256d Y, __m256d MX, __m256d MY, __m256d NX, __m256d NY)
{
    return _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(X, MX), NX), _mm256_mul_pd(_mm256_sub_pd(Y, MY), NY));
}

static inline unsigned mask8(__m256d lo, __m256d hi) TGT;
static inline unsigned mask8(__m256d lo, __m256d hi)
{
    return (unsigned)_mm256_movemask_pd(lo) | (unsigned)_mm256_movemask_pd(hi) << 4;
}

/* The squared distances from (AX, AY) of lanes in `in` folded into acc by
 * max (max(d2, acc) keeps acc when d2 is NaN, as `d2 > far2` does). */
static inline __m256d far_fold(__m256d acc, __m256d X, __m256d Y, __m256d AX, __m256d AY, __m256d in) TGT;
static inline __m256d far_fold(__m256d acc, __m256d X, __m256d Y, __m256d AX, __m256d AY, __m256d in)
{
    const __m256d dx = _mm256_sub_pd(X, AX), dy = _mm256_sub_pd(Y, AY);
    const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    return _mm256_blendv_pd(acc, _mm256_max_pd(d2, acc), in);
}

/* Lanes of an 8-bit mask as two 4-lane masks. */
static inline void lanes_of(unsigned m, __m256d *lo, __m256d *hi) TGT;
static inline void lanes_of(unsigned m, __m256d *lo, __m256d *hi)
{
    const __m256i bit = _mm256_set_epi64x(8, 4, 2, 1);
    *lo = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(_mm256_set1_epi64x(m & 15u), bit), bit));
    *hi = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(_mm256_set1_epi64x(m >> 4), bit), bit));
}

/* The coordinate of vertex v + 1 in lane v (vertex 0 in lane nv - 1,
 * marked by l0, l1), by shuffles (a store and a wider load of it would
 * wait for the store). */
static inline void next_vertex(__m256d A0, __m256d A1, __m256d l0, __m256d l1, __m256d *N0, __m256d *N1) TGT;
static inline void next_vertex(__m256d A0, __m256d A1, __m256d l0, __m256d l1, __m256d *N0, __m256d *N1)
{
    const __m256d first = _mm256_permute4x64_pd(A0, 0), fifth = _mm256_permute4x64_pd(A1, 0);
    const __m256d r0 = _mm256_blend_pd(_mm256_permute4x64_pd(A0, _MM_SHUFFLE(0, 3, 2, 1)), fifth, 8);
    const __m256d r1 = _mm256_blend_pd(_mm256_permute4x64_pd(A1, _MM_SHUFFLE(0, 3, 2, 1)), first, 8);
    *N0 = _mm256_blendv_pd(r0, first, l0);
    *N1 = _mm256_blendv_pd(r1, first, l1);
}

/* The branch-free cut of a polygon of nv <= 8 vertices (x, y with room
 * for 8). Returns -1 when the bisector misses the polygon, 0 when it
 * removes all of it, else the count written to ox, oy (which may exceed 8)
 * and, in *far2, their largest squared distance from (ax, ay). The side
 * of the next vertex is computed again from its coordinates: the same
 * operations on the same numbers, so the same bits as the plain loop's
 * sd[w]. */
TGT static int cut_small(double *x, double *y, int nv, double mx, double my, double nx, double ny, double ax,
                         double ay, double *ox, double *oy, double *far2)
{
    const __m256d MX = _mm256_set1_pd(mx), MY = _mm256_set1_pd(my);
    const __m256d NX = _mm256_set1_pd(nx), NY = _mm256_set1_pd(ny), Z = _mm256_setzero_pd();
    const __m256d X0 = _mm256_loadu_pd(x), X1 = _mm256_loadu_pd(x + 4);
    const __m256d Y0 = _mm256_loadu_pd(y), Y1 = _mm256_loadu_pd(y + 4);
    const __m256d S0 = side(X0, Y0, MX, MY, NX, NY), S1 = side(X1, Y1, MX, MY, NX, NY);
    const unsigned valid = lanes(nv);
    const unsigned pos = mask8(_mm256_cmp_pd(S0, Z, _CMP_GT_OQ), _mm256_cmp_pd(S1, Z, _CMP_GT_OQ)) & valid;
    if (!pos) return -1; /* smax <= 0 */
    /* smin > 0: no side value at or below 0 (the plain loop's minimum
     * skips a NaN, and so does this test). */
    const unsigned keep = mask8(_mm256_cmp_pd(S0, Z, _CMP_LE_OQ), _mm256_cmp_pd(S1, Z, _CMP_LE_OQ)) & valid;
    if (!keep) return 0;
    const unsigned neg = mask8(_mm256_cmp_pd(S0, Z, _CMP_LT_OQ), _mm256_cmp_pd(S1, Z, _CMP_LT_OQ)) & valid;
    __m256d l0, l1;
    lanes_of(1u << (nv - 1), &l0, &l1);
    __m256d W0, W1, V0, V1;
    next_vertex(X0, X1, l0, l1, &W0, &W1);
    next_vertex(Y0, Y1, l0, l1, &V0, &V1);
    const __m256d T0 = side(W0, V0, MX, MY, NX, NY), T1 = side(W1, V1, MX, MY, NX, NY);
    /* Sign change: (s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0). */
    const unsigned pos1 = mask8(_mm256_cmp_pd(T0, Z, _CMP_GT_OQ), _mm256_cmp_pd(T1, Z, _CMP_GT_OQ));
    const unsigned neg1 = mask8(_mm256_cmp_pd(T0, Z, _CMP_LT_OQ), _mm256_cmp_pd(T1, Z, _CMP_LT_OQ));
    const unsigned cross = ((neg & pos1) | (pos & neg1)) & valid;
    const __m256d Q0 = _mm256_div_pd(S0, _mm256_sub_pd(S0, T0)), Q1 = _mm256_div_pd(S1, _mm256_sub_pd(S1, T1));
    const __m256d I0 = _mm256_add_pd(X0, _mm256_mul_pd(Q0, _mm256_sub_pd(W0, X0)));
    const __m256d I1 = _mm256_add_pd(X1, _mm256_mul_pd(Q1, _mm256_sub_pd(W1, X1)));
    const __m256d J0 = _mm256_add_pd(Y0, _mm256_mul_pd(Q0, _mm256_sub_pd(V0, Y0)));
    const __m256d J1 = _mm256_add_pd(Y1, _mm256_mul_pd(Q1, _mm256_sub_pd(V1, Y1)));
    /* The farthest output vertex: a maximum, so taken in any order. */
    const __m256d AX = _mm256_set1_pd(ax), AY = _mm256_set1_pd(ay);
    __m256d k0, k1, c0, c1;
    lanes_of(keep, &k0, &k1);
    lanes_of(cross, &c0, &c1);
    __m256d acc = far_fold(Z, X0, Y0, AX, AY, k0);
    acc = far_fold(acc, X1, Y1, AX, AY, k1);
    acc = far_fold(acc, I0, J0, AX, AY, c0);
    acc = far_fold(acc, I1, J1, AX, AY, c1);
    const __m128d m2 = _mm_max_pd(_mm256_castpd256_pd128(acc), _mm256_extractf128_pd(acc, 1));
    *far2 = _mm_cvtsd_f64(_mm_max_sd(_mm_unpackhi_pd(m2, m2), m2));
    double ix[8], iy[8];
    _mm256_storeu_pd(ix, I0);
    _mm256_storeu_pd(ix + 4, I1);
    _mm256_storeu_pd(iy, J0);
    _mm256_storeu_pd(iy + 4, J1);
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
