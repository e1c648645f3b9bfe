/* solver_cut256.h - layer 1, host only: the AVX2 cut of a small polygon
 * (up to 8 vertices in two 4-lane registers a coordinate) by one line,
 * the piece LocalCFPO's AVX2 route (solver_avx2.c) and the density
 * solve's (src/density/dens_solve_avx2.c) share. Its bits are the plain
 * loop's (solver_avx2.c, item 1, says why). Include only where
 * CFPO_SOLVER_AVX2 holds.
 * May include solver_simd.h. */
#ifndef CFPO_SOLVER_CUT256_H
#define CFPO_SOLVER_CUT256_H

#include "solver_simd.h"

#if CFPO_SOLVER_AVX2

#include <immintrin.h>

#define TGT __attribute__((target("avx2")))

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

#endif

#endif
