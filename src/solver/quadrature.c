/* quadrature.c - see quadrature.h: Gauss-Legendre nodes and weights. */
#include "quadrature.h"

#include <math.h>

void cfpo_gauss_legendre(int q, double *z, double *w)
{
    for (int i = 0; i < q; i++) {
        double x = cos(M_PI * (i + 0.75) / (q + 0.5)), dp = 1;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = x;
            for (int j = 2; j <= q; j++) {
                const double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            dp = q * (x * p1 - p0) / (x * x - 1);
            const double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        z[i] = x;
        w[i] = 2 / ((1 - x * x) * dp * dp);
    }
}
