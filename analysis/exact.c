/* exact.c - the periodogram by direct summation (see power.h): the
 * reference the NUFFT is tested against, and `cfpo-analyze --exact`.
 *
 * exp(-2 pi i k.x) = exp(-2 pi i kx x) exp(-2 pi i ky y); each factor comes
 * from sin and cos of the phase kx*x reduced to [-1/2, 1/2], so every term
 * is correct to a few ulps (no recurrences). Each thread owns a band of
 * rows ky >= 0 and runs through the points in blocks of B on its own (it
 * tabulates the x factors of a block itself): no barrier at all, and every
 * row is summed in point order, so the result does not depend on the
 * number of threads. Rows ky < 0 follow from P(-k) = P(k). */
#define _GNU_SOURCE
#include "power.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "omp_compat.h"

enum { B = 64 };

static void factors(double x, int k0, int k1, double *re, double *im)
{
    for (int k = k0; k <= k1; k++) {
        double t = (double)k * x;
        t -= nearbyint(t);
        double s, c;
        sincos(2 * M_PI * t, &s, &c);
        re[k - k0] = c;
        im[k - k0] = -s;
    }
}

/* Row ky of the sum += the nb points of the block, two at a time. */
static void accumulate_row(int ky, int nb, size_t side, size_t ystride, const double *exr,
                           const double *exi, const double *eyr, const double *eyi, double *fr,
                           double *fi)
{
    int b = 0;
    for (; b + 1 < nb; b += 2) {
        const double c1 = eyr[b * ystride + ky], s1 = eyi[b * ystride + ky];
        const double c2 = eyr[(b + 1) * ystride + ky], s2 = eyi[(b + 1) * ystride + ky];
        const double *ar = exr + b * side, *ai = exi + b * side;
        const double *br = ar + side, *bi = ai + side;
        for (size_t t = 0; t < side; t++) {
            fr[t] += (c1 * ar[t] - s1 * ai[t]) + (c2 * br[t] - s2 * bi[t]);
            fi[t] += (c1 * ai[t] + s1 * ar[t]) + (c2 * bi[t] + s2 * br[t]);
        }
    }
    for (; b < nb; b++) {
        const double c = eyr[b * ystride + ky], s = eyi[b * ystride + ky];
        const double *ar = exr + b * side, *ai = exi + b * side;
        for (size_t t = 0; t < side; t++) {
            fr[t] += c * ar[t] - s * ai[t];
            fi[t] += c * ai[t] + s * ar[t];
        }
    }
}

/* The rows [ky0, ky1) of the sum, over all points. */
static int band(const double *xy, size_t n, int K, int ky0, int ky1, double *Fr, double *Fi,
                an_progress_fn progress, void *user)
{
    const size_t side = an_side(K), rows = (size_t)(ky1 - ky0);
    double *exr = malloc(B * side * sizeof *exr), *exi = malloc(B * side * sizeof *exi);
    double *eyr = malloc(B * (rows + 1) * sizeof *eyr), *eyi = malloc(B * (rows + 1) * sizeof *eyi);
    int ok = exr && exi && eyr && eyi;
    for (size_t j0 = 0; ok && j0 < n; j0 += B) {
        const int nb = (int)(n - j0 < B ? n - j0 : B);
        for (int b = 0; b < nb; b++) {
            factors(xy[2 * (j0 + b)], -K, K, exr + b * side, exi + b * side);
            factors(xy[2 * (j0 + b) + 1], ky0, ky1 - 1, eyr + b * rows, eyi + b * rows);
        }
        for (int ky = ky0; ky < ky1; ky++)
            accumulate_row(ky - ky0, nb, side, rows, exr, exi, eyr, eyi, Fr + (size_t)ky * side,
                           Fi + (size_t)ky * side);
        if (progress) progress((double)(j0 + nb) / (double)n, user);
    }
    free(exr); free(exi); free(eyr); free(eyi);
    return ok ? 0 : -1;
}

int an_power_exact(const double *xy, size_t n, int K, double *P, an_progress_fn progress,
                   void *user, char *err, size_t errlen)
{
    if (n == 0 || K < 1 || K > AN_KMAX) {
        snprintf(err, errlen, "exact: bad request (n=%zu, K=%d)", n, K);
        return -1;
    }
    const size_t side = an_side(K), half = (size_t)K + 1;
    double *Fr = calloc(half * side, sizeof *Fr), *Fi = calloc(half * side, sizeof *Fi);
    int bad = !Fr || !Fi;
    if (!bad) {
#pragma omp parallel reduction(| : bad)
        {
            const int T = omp_get_num_threads(), t = omp_get_thread_num();
            const int ky0 = (int)((int64_t)(K + 1) * t / T), ky1 = (int)((int64_t)(K + 1) * (t + 1) / T);
            if (ky1 > ky0)
                bad |= band(xy, n, K, ky0, ky1, Fr, Fi, t == 0 ? progress : NULL, user) != 0;
        }
    }
    if (bad) {
        free(Fr); free(Fi);
        snprintf(err, errlen, "exact: out of memory");
        return -1;
    }
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            size_t t = (size_t)ky * side + (size_t)(kx + K);
            double p = (Fr[t] * Fr[t] + Fi[t] * Fi[t]) / (double)n;
            P[an_pidx(K, kx, ky)] = p;
            P[an_pidx(K, -kx, -ky)] = p;
        }
    free(Fr); free(Fi);
    return 0;
}

double an_power_maxdiff(const double *P, const double *Pref, int K)
{
    const size_t N = an_side(K) * an_side(K);
    double worst = 0;
    for (size_t t = 0; t < N; t++) {
        double d = fabs(P[t] - Pref[t]) / fmax(Pref[t], 1.0);
        if (!(d <= worst)) worst = d; /* NaN propagates */
    }
    return worst;
}
