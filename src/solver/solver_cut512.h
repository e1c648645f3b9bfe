/* solver_cut512.h - layer 1, host only: the AVX-512 cut of a small
 * polygon (up to 8 vertices in two 8-lane registers) by one line, the
 * piece LocalCFPO's AVX-512 route (solver_avx512.c) and the density
 * solve's (src/density/dens_solve_avx512.c) share. Its bits are the plain
 * loop's (solver_avx512.c says why). Include only where
 * CFPO_SOLVER_AVX2 holds.
 * May include solver_simd.h. */
#ifndef CFPO_SOLVER_CUT512_H
#define CFPO_SOLVER_CUT512_H

#include "solver_simd.h"

#if CFPO_SOLVER_AVX2

#include <immintrin.h>

#define T512 __attribute__((target("avx2,avx512f,avx512dq,bmi2,popcnt")))

/* Bits v < n of an 8-lane mask (n <= 8). */
static inline __mmask8 first_lanes(int n) { return (__mmask8)((1u << n) - 1u); }

T512 static inline __m512d side8(__m512d X, __m512d Y, __m512d MX, __m512d MY, __m512d NX, __m512d NY)
{
    return _mm512_add_pd(_mm512_mul_pd(_mm512_sub_pd(X, MX), NX), _mm512_mul_pd(_mm512_sub_pd(Y, MY), NY));
}

/* The squared distance of each lane's point from (AX, AY). */
T512 static inline __m512d dist2_8(__m512d X, __m512d Y, __m512d AX, __m512d AY)
{
    const __m512d dx = _mm512_sub_pd(X, AX), dy = _mm512_sub_pd(Y, AY);
    return _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
}

/* The cut of the polygon of nv <= 8 vertices in lanes 0..nv-1 of *PX,
 * *PY by the bisector (m, n). Returns -1 when the bisector misses the
 * polygon, 0 when it removes all of it, else the output's vertex count:
 * up to 8 in *PX, *PY; more (at most 16) written to spx, spy (24 slots
 * each) instead. *far2: the output's largest squared distance from
 * (ax, ay). */
T512 static int cut8(__m512d *PX, __m512d *PY, int nv, double mx, double my, double nx, double ny, double ax,
                     double ay, double *spx, double *spy, double *far2)
{
    const __m512d MX = _mm512_set1_pd(mx), MY = _mm512_set1_pd(my);
    const __m512d NX = _mm512_set1_pd(nx), NY = _mm512_set1_pd(ny), Z = _mm512_setzero_pd();
    const __m512d X = *PX, Y = *PY;
    const __m512d S = side8(X, Y, MX, MY, NX, NY);
    const __mmask8 valid = first_lanes(nv);
    const __mmask8 pos = _mm512_cmp_pd_mask(S, Z, _CMP_GT_OQ) & valid;
    if (!pos) return -1; /* smax <= 0 */
    /* smin > 0: no side value at or below 0 (a NaN is neither) */
    const __mmask8 keep = _mm512_cmp_pd_mask(S, Z, _CMP_LE_OQ) & valid;
    if (!keep) return 0;
    const __mmask8 neg = _mm512_cmp_pd_mask(S, Z, _CMP_LT_OQ) & valid;
    /* Lane v: vertex v + 1, and vertex 0 in lane nv - 1. */
    const __m512i next = _mm512_maskz_mov_epi64(first_lanes(nv - 1), _mm512_set_epi64(8, 7, 6, 5, 4, 3, 2, 1));
    const __m512d W = _mm512_permutexvar_pd(next, X), V = _mm512_permutexvar_pd(next, Y);
    /* The next vertex's side, computed again from its coordinates: the
     * same operations on the same numbers as the plain loop's sd[w]. */
    const __m512d T = side8(W, V, MX, MY, NX, NY);
    const __mmask8 pos1 = _mm512_cmp_pd_mask(T, Z, _CMP_GT_OQ), neg1 = _mm512_cmp_pd_mask(T, Z, _CMP_LT_OQ);
    const __mmask8 cross = ((neg & pos1) | (pos & neg1)) & valid;
    const __m512d Q = _mm512_div_pd(S, _mm512_sub_pd(S, T));
    const __m512d I = _mm512_add_pd(X, _mm512_mul_pd(Q, _mm512_sub_pd(W, X)));
    const __m512d J = _mm512_add_pd(Y, _mm512_mul_pd(Q, _mm512_sub_pd(V, Y)));
    /* The farthest output vertex: max(d2, acc) keeps acc when d2 is NaN. */
    const __m512d AX = _mm512_set1_pd(ax), AY = _mm512_set1_pd(ay);
    __m512d acc = _mm512_mask_max_pd(Z, keep, dist2_8(X, Y, AX, AY), Z);
    acc = _mm512_mask_max_pd(acc, cross, dist2_8(I, J, AX, AY), acc);
    *far2 = _mm512_reduce_max_pd(acc);
    /* The output in vertex order: the 16 candidates v0, i0, v1, i1, ...
     * in two registers, each compressed to its kept lanes. */
    const unsigned both = _pdep_u32(keep, 0x5555u) | _pdep_u32(cross, 0xAAAAu);
    const __mmask8 mlo = (__mmask8)(both & 0xFFu), mhi = (__mmask8)(both >> 8);
    const int nlo = __builtin_popcount(mlo), nhi = __builtin_popcount(mhi);
    const __m512i lo = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), hi = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
    const __m512d LX = _mm512_maskz_compress_pd(mlo, _mm512_permutex2var_pd(X, lo, I));
    const __m512d HX = _mm512_maskz_compress_pd(mhi, _mm512_permutex2var_pd(X, hi, I));
    const __m512d LY = _mm512_maskz_compress_pd(mlo, _mm512_permutex2var_pd(Y, lo, J));
    const __m512d HY = _mm512_maskz_compress_pd(mhi, _mm512_permutex2var_pd(Y, hi, J));
    if (nlo + nhi <= 8) {
        const __mmask8 upper = (__mmask8)(first_lanes(nhi) << nlo);
        *PX = _mm512_mask_expand_pd(LX, upper, HX);
        *PY = _mm512_mask_expand_pd(LY, upper, HY);
    } else {
        _mm512_storeu_pd(spx, LX);
        _mm512_storeu_pd(spx + nlo, HX);
        _mm512_storeu_pd(spy, LY);
        _mm512_storeu_pd(spy + nlo, HY);
    }
    return nlo + nhi;
}

#endif

#endif
