/* dens_scan.c - layer 2: see dens_scan.h. */
#include "dens_scan.h"

#include "dens_solve.h"
#include "solver_simd.h"

#if CFPO_SOLVER_AVX2

#include <immintrin.h>

#define T512 __attribute__((target("avx2,avx512f,avx512dq,bmi"))) /* the AVX-512 route's CPU (dens_solve.h) */

T512 static int scan512(const double *bx, const double *by, const double *br, int m, int p, double px, double py,
                        double rc, double thr)
{
    const __m512d PX = _mm512_set1_pd(px), PY = _mm512_set1_pd(py), RC = _mm512_set1_pd(rc);
    const __m512d THR = _mm512_set1_pd(thr);
    for (int j0 = 0; j0 < m; j0 += 8) {
        const int nl = m - j0 < 8 ? m - j0 : 8;
        __mmask8 in = (__mmask8)((1u << nl) - 1u);
        if (p >= j0 && p < j0 + 8) in &= (__mmask8)~(1u << (p - j0));
        const __m512d ex = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, bx + j0), PX);
        const __m512d ey = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, by + j0), PY);
        const __m512d v = _mm512_mul_pd(
            _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)), _mm512_maskz_loadu_pd(in, br + j0)),
            RC);
        /* not above thr (a NaN is not): the scalar test's failure */
        const __mmask8 bad = (__mmask8)(in & ~_mm512_cmp_pd_mask(v, THR, _CMP_GT_OQ));
        if (bad) return j0 + __builtin_ctz((unsigned)bad);
    }
    return -1;
}

int cfpo_dens_scan_block(const double *bx, const double *by, const double *br, int m, int p, double px, double py,
                         double rc, double thr)
{
    if (m > 64 || cfpo_dens_route() != 2) return -2;
    return scan512(bx, by, br, m, p, px, py, rc, thr);
}

#else

int cfpo_dens_scan_block(const double *bx, const double *by, const double *br, int m, int p, double px, double py,
                         double rc, double thr)
{
    (void)bx; (void)by; (void)br; (void)m; (void)p; (void)px; (void)py; (void)rc; (void)thr;
    return -2;
}

#endif
