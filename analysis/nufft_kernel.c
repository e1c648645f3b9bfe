/* nufft_kernel.c - see nufft_kernel.h. */
#include "nufft_kernel.h"

#include "quadrature.h"

void an_nk_ft(const an_nk *k, int K, double *phihat)
{
    enum { Q = 96 };
    double z[Q], wt[Q], f[Q];
    cfpo_gauss_legendre(Q, z, wt);
    for (int i = 0; i < Q; i++) f[i] = wt[i] * an_nk_at(k, k->alpha * z[i]);
    for (int kk = 0; kk <= K; kk++) {
        double nu = (double)kk / k->M, s = 0;
        for (int i = 0; i < Q; i++) s += f[i] * cos(2 * M_PI * nu * k->alpha * z[i]);
        phihat[kk] = k->alpha * s;
    }
}
