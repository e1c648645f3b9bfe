/* nufft.c - the periodogram by a type-1 non-uniform FFT (see power.h).
 *
 * f(k) = sum_j exp(-2 pi i k.x_j) for |kx|, |ky| <= K, in three steps:
 *  1. spread: b[l] = sum_j phi(M x_j - l) on an M x M grid, M >= 2(2K+1)
 *     (oversampling 2), phi the "exponential of semicircle" kernel
 *     phi(t) = exp(beta (sqrt(1 - (t/alpha)^2) - 1)) on |t| <= alpha = w/2,
 *     beta = 2.30 w (Barnett, Magland and af Klinteberg 2019, FINUFFT);
 *  2. one real-to-complex FFT of b through FFTW (forward sign);
 *  3. deconvolve: f(k) = B(k) / (phihat(kx/M) phihat(ky/M)), phihat the
 *     kernel's Fourier transform, computed by Gauss-Legendre quadrature.
 * By Poisson summation B(k) = phihat(k/M) f(k) plus aliased copies weighted
 * by phihat(m - k/M) with |m - k/M| >= 3/4, about 10^-(w-1) times smaller.
 *
 * Parallel spreading with no atomics and no dependence on the thread
 * count: grid rows are cut into S strips (S even, each at least w rows); a
 * point belongs to the strip holding its first row and writes only into
 * that strip and the next one. Even strips run concurrently, then odd ones;
 * inside a strip points go in index order. Every grid value is therefore
 * summed in one fixed order, whatever the number of threads.
 *
 * FFTW's planner is not thread-safe (only fftw_execute is): planning and
 * destroying a plan hold one process-wide lock, so several threads of a
 * program (the Python package's callers) may compute spectra at once. */
#include "power.h"

#include <fftw3.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nufft_kernel.h"

typedef an_nk kernel;

static inline int first_row(const kernel *k, double y)
{
    int l0 = (int)ceil(y * k->M - k->alpha);
    return l0 < 0 ? l0 + k->M : l0;
}

static inline int strip_begin(int s, int S, int M) { return (int)((int64_t)s * M / S); }

static int strip_of(int row, int S, int M)
{
    int s = (int)((int64_t)row * S / M);
    while (s + 1 < S && strip_begin(s + 1, S, M) <= row) s++;
    while (s > 0 && strip_begin(s, S, M) > row) s--;
    return s;
}

static void spread_point(const kernel *k, double x, double y, double *grid, size_t stride)
{
    double vx[32], vy[32];
    const int M = k->M, w = k->w;
    int lx = an_nk_row(k, x * M, vx), ly = an_nk_row(k, y * M, vy);
    int inside = lx >= 0 && lx + w <= M;
    for (int b = 0; b < w; b++) {
        int row = ly + b;
        row = row < 0 ? row + M : (row >= M ? row - M : row);
        double *r = grid + (size_t)row * stride;
        const double c = vy[b];
        if (inside) {
            double *rr = r + lx;
            for (int a = 0; a < w; a++) rr[a] += c * vx[a];
        } else {
            for (int a = 0; a < w; a++) {
                int col = lx + a;
                col = col < 0 ? col + M : (col >= M ? col - M : col);
                r[col] += c * vx[a];
            }
        }
    }
}

static int spread(const kernel *k, const double *xy, size_t n, double *grid, size_t stride)
{
    const int M = k->M;
    int S = M / k->w;
    if (S > 128) S = 128;
    S &= ~1;
    if (S < 2) S = 2; /* M >= 2w guarantees strips of at least w rows */
    size_t *start = calloc((size_t)S + 1, sizeof *start);
    size_t *order = malloc((n ? n : 1) * sizeof *order);
    if (!start || !order) { free(start); free(order); return -1; }
    for (size_t j = 0; j < n; j++) start[strip_of(first_row(k, xy[2 * j + 1]), S, M) + 1]++;
    for (int s = 0; s < S; s++) start[s + 1] += start[s];
    for (size_t j = 0; j < n; j++) order[start[strip_of(first_row(k, xy[2 * j + 1]), S, M)]++] = j;
    for (int s = S; s > 0; s--) start[s] = start[s - 1];
    start[0] = 0;
    for (int parity = 0; parity < 2; parity++) {
#pragma omp parallel for schedule(dynamic, 1)
        for (int s = parity; s < S; s += 2)
            for (size_t q = start[s]; q < start[s + 1]; q++) {
                size_t j = order[q];
                spread_point(k, xy[2 * j], xy[2 * j + 1], grid, stride);
            }
    }
    free(start);
    free(order);
    return 0;
}

/* |B(k)|^2 / (phihat^2 n) into P, using P(-k) = P(k). */
static void deconvolve(const kernel *k, int K, const double *phihat, const fftw_complex *c,
                       size_t n, double *P)
{
    const int M = k->M;
    const size_t cs = (size_t)M / 2 + 1;
#pragma omp parallel for schedule(static)
    for (int ky = -K; ky <= K; ky++) {
        const fftw_complex *row = c + (size_t)(ky < 0 ? ky + M : ky) * cs;
        const double py = phihat[ky < 0 ? -ky : ky];
        for (int kx = ky < 0; kx <= K; kx++) { /* (0, ky < 0) is written by (0, -ky) */
            double d = py * phihat[kx];
            double re = row[kx][0] / d, im = row[kx][1] / d;
            double p = (re * re + im * im) / (double)n;
            P[an_pidx(K, kx, ky)] = p;
            P[an_pidx(K, -kx, -ky)] = p;
        }
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
    kernel k = {.w = width, .alpha = 0.5 * width, .beta = 2.30 * width};
    int M = 2 * (2 * K + 1);
    if (M < 2 * width) M = 2 * width;
    k.M = M = an_nk_fft_size(M);
    const size_t stride = 2 * ((size_t)M / 2 + 1);
    double *grid = fftw_malloc(sizeof(double) * (size_t)M * stride);
    double *phihat = malloc(((size_t)K + 1) * sizeof *phihat);
    if (!grid || !phihat) {
        fftw_free(grid);
        free(phihat);
        snprintf(err, errlen, "nufft: out of memory for a %d x %d grid", M, M);
        return -1;
    }
    double t0 = cli_now();
#pragma omp parallel for schedule(static)
    for (int r = 0; r < M; r++) memset(grid + (size_t)r * stride, 0, stride * sizeof *grid);
    if (spread(&k, xy, n, grid, stride) != 0) {
        fftw_free(grid);
        free(phihat);
        snprintf(err, errlen, "nufft: out of memory");
        return -1;
    }
    double t1 = cli_now();
    static pthread_mutex_t planner = PTHREAD_MUTEX_INITIALIZER;
    pthread_mutex_lock(&planner);
    fftw_plan plan = fftw_plan_dft_r2c_2d(M, M, grid, (fftw_complex *)grid, FFTW_ESTIMATE);
    pthread_mutex_unlock(&planner);
    if (!plan) {
        fftw_free(grid);
        free(phihat);
        snprintf(err, errlen, "nufft: FFTW could not plan a %d x %d transform", M, M);
        return -1;
    }
    fftw_execute(plan);
    pthread_mutex_lock(&planner);
    fftw_destroy_plan(plan);
    pthread_mutex_unlock(&planner);
    double t2 = cli_now();
    an_nk_ft(&k, K, phihat);
    deconvolve(&k, K, phihat, (const fftw_complex *)grid, n, P);
    if (info) {
        info->width = width;
        info->grid = M;
        info->beta = k.beta;
        info->seconds_spread = t1 - t0;
        info->seconds_fft = t2 - t1;
    }
    fftw_free(grid);
    free(phihat);
    return 0;
}
