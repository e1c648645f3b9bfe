/* nufft_kernel.c - see nufft_kernel.h. */
#include "nufft_kernel.h"

int an_nk_fft_size(int m)
{
    for (;; m++) {
        if (m & 1) continue;
        int r = m;
        static const int pr[] = {2, 3, 5, 7};
        for (int i = 0; i < 4; i++)
            while (r % pr[i] == 0) r /= pr[i];
        if (r == 1) return m;
    }
}

void an_nk_gauss_legendre(int q, double *z, double *wt)
{
    for (int i = 0; i < q; i++) {
        double x = cos(M_PI * (i + 0.75) / (q + 0.5)), dp = 1;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = x;
            for (int j = 2; j <= q; j++) {
                double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            dp = q * (x * p1 - p0) / (x * x - 1);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        z[i] = x;
        wt[i] = 2 / ((1 - x * x) * dp * dp);
    }
}

void an_nk_ft(const an_nk *k, int K, double *phihat)
{
    enum { Q = 96 };
    double z[Q], wt[Q], f[Q];
    an_nk_gauss_legendre(Q, z, wt);
    for (int i = 0; i < Q; i++) f[i] = wt[i] * an_nk_at(k, k->alpha * z[i]);
    for (int kk = 0; kk <= K; kk++) {
        double nu = (double)kk / k->M, s = 0;
        for (int i = 0; i < Q; i++) s += f[i] * cos(2 * M_PI * nu * k->alpha * z[i]);
        phihat[kk] = k->alpha * s;
    }
}
