/* nufft.c - the periodogram by the type-1 non-uniform FFT (see power.h):
 * f(k) = sum_j exp(-2 pi i k.x_j) from the core library's NUFFT (src/solver/nufft.h:
 * the exponential-of-semicircle kernel, oversampling 2, fixed-point
 * spreading, FFTW), then P(k) = |f(k)|^2 / n. The result does not depend
 * on the number of threads (nufft.h says why). */
#include "power.h"

#include <stdint.h>
#include <stdio.h>

#include "cli.h"
#include "nufft.h"

/* |f(k)|^2 / n into P, using P(-k) = P(k). */
static void periodogram(const cfpo_nufft *U, int K, size_t n, double *P)
{
#pragma omp parallel for schedule(static)
    for (int ky = -K; ky <= K; ky++)
        for (int kx = ky < 0; kx <= K; kx++) { /* (0, ky < 0) is written by (0, -ky) */
            double re, im;
            cfpo_nufft_coef(U, kx, ky, &re, &im);
            double p = (re * re + im * im) / (double)n;
            P[an_pidx(K, kx, ky)] = p;
            P[an_pidx(K, -kx, -ky)] = p;
        }
}

int an_power_nufft(const double *xy, size_t n, int K, int width, double *P, an_nufft_info *info,
                   char *err, size_t errlen)
{
    if (width == 0) width = AN_NUFFT_WIDTH;
    if (n == 0 || K < 1 || K > AN_KMAX || width < 4 || width > 16) {
        snprintf(err, errlen, "nufft: bad request (n=%zu, K=%d, width=%d)", n, K, width);
        return -1;
    }
    cfpo_nufft U;
    if (cfpo_nufft_init(&U, K, width, CFPO_NUFFT_TYPE1, 0, err, errlen) != 0) return -1;
    double t0 = cli_now();
    if (cfpo_nufft_spread(&U, xy, xy + 1, 2, n, (int64_t)n) != 0) {
        cfpo_nufft_free(&U);
        snprintf(err, errlen, "nufft: out of memory");
        return -1;
    }
    double t1 = cli_now();
    cfpo_nufft_type1_finish(&U, (int64_t)n);
    double t2 = cli_now();
    periodogram(&U, K, n, P);
    if (info) {
        info->width = width;
        info->grid = U.M;
        info->beta = U.beta;
        info->seconds_spread = t1 - t0;
        info->seconds_fft = t2 - t1;
    }
    cfpo_nufft_free(&U);
    return 0;
}
