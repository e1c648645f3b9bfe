/* nufft_kernel.h - the spreading kernel of the differential-domain
 * spectrum's weighted type-1 non-uniform FFT (dda.c; the unweighted one of
 * the periodogram is the core's, src/solver/nufft.h, in fixed point): the
 * "exponential of semicircle"
 * phi(t) = exp(beta (sqrt(1 - (t/alpha)^2) - 1)) on |t| <= alpha = w/2,
 * beta = 2.30 w (Barnett, Magland and af Klinteberg 2019, FINUFFT), its
 * Fourier transform by Gauss-Legendre quadrature (src/solver/quadrature.h).
 * Owns these formulas only; what is spread and how is the callers'. */
#ifndef AN_NUFFT_KERNEL_H
#define AN_NUFFT_KERNEL_H

#include <math.h>

typedef struct {
    int w, M;           /* support in grid points; grid side */
    double alpha, beta;
} an_nk;

static inline double an_nk_at(const an_nk *k, double t)
{
    double s = 1.0 - (t / k->alpha) * (t / k->alpha);
    return s > 0 ? exp(k->beta * (sqrt(s) - 1.0)) : 0.0;
}

/* phihat(kk / M) for kk = 0..K: the integral of phi(t) cos(2 pi nu t). */
void an_nk_ft(const an_nk *k, int K, double *phihat);

/* The w kernel values of a point at grid coordinate u; returns its first
 * grid index (may be negative; callers wrap). */
static inline int an_nk_row(const an_nk *k, double u, double *v)
{
    int l0 = (int)ceil(u - k->alpha);
    for (int a = 0; a < k->w; a++) v[a] = an_nk_at(k, u - (double)(l0 + a));
    return l0;
}

#endif
