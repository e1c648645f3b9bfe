/* measures3_w6.c - see measures3_w6.h. */
#include "measures3_w6.h"

#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nn3.h"

static double fact(int k) { return k < 0 ? NAN : tgamma(k + 1.0); }

double cfpo3_wigner666(int m1, int m2, int m3)
{
    const int j = 6;
    if (m1 + m2 + m3 != 0 || abs(m1) > j || abs(m2) > j || abs(m3) > j) return 0;
    const double tri = fact(j) * fact(j) * fact(j) / fact(3 * j + 1);
    const double pre = sqrt(tri * fact(j + m1) * fact(j - m1) * fact(j + m2) * fact(j - m2) * fact(j + m3) * fact(j - m3));
    double s = 0;
    for (int t = 0; t <= 3 * j; t++) {
        const int a[6] = {t, t + m1, t - m2, j - t, j - t - m1, j - t + m2}; /* j3-j2+t+m1 = t+m1, j3-j1+t-m2 = t-m2 */
        int ok = 1;
        for (int i = 0; i < 6; i++) ok &= a[i] >= 0;
        if (!ok) continue;
        double d = 1;
        for (int i = 0; i < 6; i++) d *= fact(a[i]);
        s += ((t & 1) ? -1.0 : 1.0) / d;
    }
    /* (-1)^(j1 - j2 - m3) = (-1)^(-m3) */
    return ((m3 & 1) ? -1.0 : 1.0) * pre * s;
}

/* Y_6m(direction d) for m = 0..6 (negative m from Y_6,-m = (-1)^m conj Y_6m). */
static void ylm6(const double *d, double complex *y)
{
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double x = d[2] / r, s = sqrt(fmax(0.0, 1.0 - x * x)), phi = atan2(d[1], d[0]);
    /* associated Legendre P_6^m(x) by the standard recurrences (Condon-Shortley phase) */
    for (int m = 0; m <= 6; m++) {
        double pmm = 1;
        for (int i = 1; i <= m; i++) pmm *= -(2 * i - 1) * s;
        double plm = pmm;
        if (m < 6) {
            double pm1 = x * (2 * m + 1) * pmm, pm0 = pmm;
            plm = pm1;
            for (int l = m + 2; l <= 6; l++) {
                const double pl = (x * (2 * l - 1) * pm1 - (l + m - 1) * pm0) / (l - m);
                pm0 = pm1, pm1 = pl;
                plm = pl;
            }
        }
        const double N = sqrt(13.0 / (4 * M_PI) * fact(6 - m) / fact(6 + m));
        y[m] = N * plm * cexp(I * m * phi);
    }
}

static double w6_of(const double complex *Q) /* Q[m + 6] */
{
    double norm = 0;
    for (int m = -6; m <= 6; m++) norm += creal(Q[m + 6] * conj(Q[m + 6]));
    if (norm <= 0) return NAN;
    double complex w = 0;
    for (int m1 = -6; m1 <= 6; m1++)
        for (int m2 = -6; m2 <= 6; m2++) {
            const int m3 = -m1 - m2;
            if (m3 < -6 || m3 > 6) continue;
            w += cfpo3_wigner666(m1, m2, m3) * Q[m1 + 6] * Q[m2 + 6] * Q[m3 + 6];
        }
    return creal(w) / pow(norm, 1.5);
}

int cfpo3_w6(const double *p, size_t n, int k, cfpo3_w6_result *r)
{
    int64_t *idx = malloc(n * (size_t)k * sizeof *idx);
    if (!idx || cfpo3_knn(p, n, k, idx, NULL) != 0) {
        free(idx);
        return -1;
    }
    double complex Qg[13] = {0};
    double wl = 0;
    for (size_t i = 0; i < n; i++) {
        double complex Qi[13] = {0};
        for (int a = 0; a < k; a++) {
            const size_t j = (size_t)idx[i * (size_t)k + (size_t)a];
            const double d[3] = {cfpo3_pdiff(p[3 * j], p[3 * i]), cfpo3_pdiff(p[3 * j + 1], p[3 * i + 1]),
                                 cfpo3_pdiff(p[3 * j + 2], p[3 * i + 2])};
            double complex y[7];
            ylm6(d, y);
            for (int m = 0; m <= 6; m++) {
                Qi[6 + m] += y[m];
                if (m) Qi[6 - m] += ((m & 1) ? -1.0 : 1.0) * conj(y[m]);
            }
        }
        for (int m = 0; m < 13; m++) Qg[m] += Qi[m];
        const double w = w6_of(Qi);
        wl += isnan(w) ? 0 : w;
    }
    double norm = 0;
    for (int m = 0; m < 13; m++) {
        Qg[m] /= (double)n * (double)k;
        norm += creal(Qg[m] * conj(Qg[m]));
    }
    r->q6 = sqrt(4 * M_PI / 13 * norm);
    r->w6 = w6_of(Qg);
    r->w6_local = wl / (double)n;
    free(idx);
    return 0;
}
