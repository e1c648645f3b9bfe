/* dens_order.c - layer 2: see dens_order.h. */
#include "dens_order.h"

#include "dens_solve.h"
#include "solver_simd.h"

int cfpo_dens_order(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj)
{
    int kk = 0;
    for (int i = 0; i < cnt; i++) {
        const double d2 = ck[i];
        const int j = (int)cj[i];
        if (kk == kmax && (d2 > key[kmax - 1] || (d2 == key[kmax - 1] && j > nj[kmax - 1]))) continue;
        int t = kk < kmax ? kk++ : kmax - 1;
        while (t > 0 && (key[t - 1] > d2 || (key[t - 1] == d2 && nj[t - 1] > j))) {
            key[t] = key[t - 1];
            nj[t] = nj[t - 1];
            t--;
        }
        key[t] = d2;
        nj[t] = j;
    }
    return kk;
}

#if CFPO_SOLVER_AVX2

#include <immintrin.h>

#define T512 __attribute__((target("avx2,avx512f,avx512dq,bmi,popcnt"))) /* the AVX-512 route's CPU (dens_solve.h) */

/* The place of the candidate (k, j) among the ng groups of eight: the
 * candidates before it in the order (key, then index). */
T512 static inline int rank512(const __m512d *K, const __m512d *J, int ng, __m512d k, __m512d j)
{
    int r = 0;
    for (int h = 0; h < ng; h++) {
        const __mmask8 lt = _mm512_cmp_pd_mask(K[h], k, _CMP_LT_OQ);
        const __mmask8 tie = _mm512_cmp_pd_mask(K[h], k, _CMP_EQ_OQ) & _mm512_cmp_pd_mask(J[h], j, _CMP_LT_OQ);
        r += __builtin_popcount((unsigned)(lt | tie));
    }
    return r;
}

/* m <= 64 points in up to eight 8-lane registers: each lane's key (+inf
 * where the point is no candidate: it then counts before no candidate,
 * whose keys are finite), its index as a double; each candidate's place
 * is the count of the candidates before it in (key, index). */
T512 static int order_block512(const double *bx, const double *by, const double *br, int m, int p, double ax,
                               double ay, double T, int kmax, double *key, int *nj)
{
    const __m512d AX = _mm512_set1_pd(ax), AY = _mm512_set1_pd(ay), TT = _mm512_set1_pd(T);
    const __m512d INF = _mm512_set1_pd(__builtin_inf());
    const __m512d LANE = _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0);
    __m512d K[8], J[8];
    __mmask8 C[8];
    const int ng = (m + 7) / 8;
    for (int g = 0; g < ng; g++) {
        const int j0 = 8 * g, nl = m - j0 < 8 ? m - j0 : 8;
        const __mmask8 in = (__mmask8)((1u << nl) - 1u);
        const __m512d ex = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, bx + j0), AX);
        const __m512d ey = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, by + j0), AY);
        const __m512d d2 = _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)),
                                         _mm512_maskz_loadu_pd(in, br + j0));
        __mmask8 c = _mm512_mask_cmp_pd_mask(in, d2, TT, _CMP_LT_OQ);
        if (p >= j0 && p < j0 + 8) c &= (__mmask8)~(1u << (p - j0));
        C[g] = c;
        K[g] = _mm512_mask_blend_pd(c, INF, d2);
        J[g] = _mm512_add_pd(LANE, _mm512_set1_pd((double)j0));
    }
    int cnt = 0;
    for (int g = 0; g < ng; g++)
        for (unsigned c = C[g]; c; c &= c - 1) {
            const int l = __builtin_ctz(c);
            const __m512i sel = _mm512_set1_epi64(l);
            const __m512d k = _mm512_permutexvar_pd(sel, K[g]), j = _mm512_permutexvar_pd(sel, J[g]);
            const int r = rank512(K, J, ng, k, j);
            if (r < kmax) {
                key[r] = _mm512_cvtsd_f64(k);
                nj[r] = 8 * g + l;
            }
            cnt++;
        }
    return cnt < kmax ? cnt : kmax;
}

/* The same count over cnt <= 64 candidates given in memory. */
T512 static int order_list512(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj)
{
    const __m512d INF = _mm512_set1_pd(__builtin_inf());
    __m512d K[8], J[8];
    const int ng = (cnt + 7) / 8;
    for (int g = 0; g < ng; g++) {
        const int nl = cnt - 8 * g < 8 ? cnt - 8 * g : 8;
        const __mmask8 in = (__mmask8)((1u << nl) - 1u);
        K[g] = _mm512_mask_loadu_pd(INF, in, ck + 8 * g); /* +inf past the end: before no candidate */
        J[g] = _mm512_maskz_loadu_pd(in, cj + 8 * g);
    }
    for (int g = 0; g < ng; g++) {
        const int nl = cnt - 8 * g < 8 ? cnt - 8 * g : 8;
        for (int l = 0; l < nl; l++) {
            const __m512i sel = _mm512_set1_epi64(l);
            const __m512d k = _mm512_permutexvar_pd(sel, K[g]), j = _mm512_permutexvar_pd(sel, J[g]);
            const int r = rank512(K, J, ng, k, j);
            if (r < kmax) {
                key[r] = _mm512_cvtsd_f64(k);
                nj[r] = (int)_mm512_cvtsd_f64(j);
            }
        }
    }
    return cnt < kmax ? cnt : kmax;
}

int cfpo_dens_order_fast(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj)
{
    if (cnt > 64 || cfpo_dens_route() != 2) return cfpo_dens_order(ck, cj, cnt, kmax, key, nj);
    return order_list512(ck, cj, cnt, kmax, key, nj);
}

int cfpo_dens_order_block(const double *bx, const double *by, const double *br, int m, int p, double ax, double ay,
                          double T, int kmax, double *key, int *nj)
{
    if (m > 64 || cfpo_dens_route() != 2) return -1;
    return order_block512(bx, by, br, m, p, ax, ay, T, kmax, key, nj);
}

#else

int cfpo_dens_order_fast(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj)
{
    return cfpo_dens_order(ck, cj, cnt, kmax, key, nj);
}

int cfpo_dens_order_block(const double *bx, const double *by, const double *br, int m, int p, double ax, double ay,
                          double T, int kmax, double *key, int *nj)
{
    (void)bx; (void)by; (void)br; (void)m; (void)p; (void)ax; (void)ay; (void)T; (void)kmax; (void)key; (void)nj;
    return -1;
}

#endif
