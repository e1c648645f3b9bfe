/* nufft.h - layer 1 (includes nothing of the project): the non-uniform FFT
 * on the unit torus, both directions, through FFTW.
 *
 * Type 1 (points -> coefficients): f(k) = sum_j exp(-2 pi i k.x_j) for
 * |kx|, |ky| <= K. Type 2 (coefficients -> points):
 * g(x) = sum_{|kx|,|ky| <= K} C(k) exp(+2 pi i k.x), complex C.
 *
 * The method (Barnett, Magland and af Klinteberg 2019, FINUFFT): an
 * M x M grid, M >= 2 (2K + 1) (oversampling 2), the "exponential of
 * semicircle" kernel phi(t) = exp(beta (sqrt(1 - (t/alpha)^2) - 1)) on
 * |t| <= alpha = w/2 with beta = 2.30 w; type 1 spreads the points onto the
 * grid with phi, transforms (FFTW, exp(-)) and divides by the kernel's
 * Fourier transform phihat(kx/M) phihat(ky/M) (Gauss-Legendre quadrature);
 * type 2 divides C by the same, transforms back (exp(+)) and interpolates
 * with phi. By Poisson summation the error is the aliased copies weighted
 * by phihat(m - k/M), |m - k/M| >= 3/4: about 10^-(w-1) of the largest
 * term (w = 10: 2e-10 for type 1 and 1.6e-9 for type 2, relative to the
 * largest value, measured by test_nufft).
 *
 * Determinism: type 1 spreads in fixed point. Each contribution
 * phi(.) phi(.) in [0, 1] is rounded to an integer number of units 2^-s
 * (s = 40, less for sets so large that a grid value could pass 2^62), and
 * the grid holds int64 sums: addition of integers does not depend on its
 * order, so the grid, and after the (one-thread) FFT the coefficients, are
 * the same bits for any number of threads, and for any cut of the points
 * into parts whose integer grids are added (the ranks of an MPI run: sum
 * cfpo_nufft_spread's grids, then cfpo_nufft_type1_finish). The rounding,
 * 2^-41 per contribution, is far below the kernel's error. Type 2 at a
 * point is a pure function of the point and the grid.
 *
 * Spreading runs in parallel without atomics: grid rows are cut into an
 * even number of strips of at least w rows; a point writes only into the
 * strip holding its first row and the next; even strips run concurrently,
 * then odd ones.
 *
 * FFTW's planner is not thread-safe: plans are made and destroyed under one
 * process-wide lock, so several threads of a program may use NUFFTs.
 *
 * Owns: the kernel, the grid, the plans, both directions. Does not own what
 * the coefficients are used for (the periodogram: analysis/nufft.c; the
 * hyperuniform variant's transport: transport.c). */
#ifndef CFPO_NUFFT_H
#define CFPO_NUFFT_H

#include <stddef.h>
#include <stdint.h>

#define CFPO_NUFFT_TYPE1 1
#define CFPO_NUFFT_TYPE2 2

/* kernel_row's polynomials: degree and lanes (the widest kernel) */
#define CFPO_NUFFT_DEG 15
#define CFPO_NUFFT_MAXW 16

typedef struct {
    double pc[(CFPO_NUFFT_DEG + 1) * CFPO_NUFFT_MAXW]; /* the kernel's polynomials (nufft.c) */
    int K, w, M;      /* frequencies |kx|, |ky| <= K; kernel width; grid side */
    int deg;          /* the polynomials' degree: w + 3, at most CFPO_NUFFT_DEG */
    double alpha, beta;
    double *phihat;   /* phihat(k / M) for k = 0..K */
    size_t stride;    /* type 1 grid: doubles per row (in-place real-to-complex) */
    void *g1;         /* type 1 grid: int64 sums, then after the transform complex B(k) */
    double *g2;       /* type 2 grid: M x M complex */
    void *p1, *p2;    /* the FFTW plans */
    int threads;      /* for spreading and interpolating over many points */
} cfpo_nufft;

/* A NUFFT for |kx|, |ky| <= K (1 <= K <= 8192), kernel width w (4..CFPO_NUFFT_MAXW),
 * the directions `types` (CFPO_NUFFT_TYPE1 | CFPO_NUFFT_TYPE2), spreading
 * on `threads` threads (0: OpenMP's default). 0; -1 with a message (bad
 * request, out of memory, FFTW could not plan). */
int cfpo_nufft_init(cfpo_nufft *U, int K, int w, int types, int threads, char *err, size_t errlen);

/* The smallest even m' >= m whose only prime factors are 2, 3, 5, 7 (the
 * FFT sizes the grid takes; also the analysis' differential-domain
 * spectrum's). */
int cfpo_nufft_fft_size(int m);
void cfpo_nufft_free(cfpo_nufft *U);

/* The fixed-point scale exponent s for sets of `total` points. */
int cfpo_nufft_scale(int64_t total);

/* Type 1, first half: the np points (x[j*step], y[j*step]) in [0, 1)
 * spread onto U's grid as int64 units of 2^-cfpo_nufft_scale(total)
 * (total: the points of the whole set, on every part). The grid's
 * cfpo_nufft_grid_count int64 values are at cfpo_nufft_grid; the caller may
 * add other parts' grids to them. 0, or -1 out of memory. */
int cfpo_nufft_spread(cfpo_nufft *U, const double *x, const double *y, size_t step, size_t np, int64_t total);
int64_t *cfpo_nufft_grid(cfpo_nufft *U);
size_t cfpo_nufft_grid_count(const cfpo_nufft *U);
/* Type 1, second half: the grid to coefficients (read with cfpo_nufft_coef). */
void cfpo_nufft_type1_finish(cfpo_nufft *U, int64_t total);
/* Both halves for one part holding the whole set. 0, or -1 out of memory. */
int cfpo_nufft_type1(cfpo_nufft *U, const double *x, const double *y, size_t step, size_t n);
/* f(kx, ky) of the last type 1, |kx|, |ky| <= K. */
void cfpo_nufft_coef(const cfpo_nufft *U, int kx, int ky, double *re, double *im);

/* Type 2, first half: C(k) at C[2 ((ky + K)(2K + 1) + kx + K)] (real,
 * imaginary) to U's type 2 grid. */
void cfpo_nufft_type2_prepare(cfpo_nufft *U, const double *C);
/* Type 2, second half: g at (x, y) in [0, 1), real and imaginary. */
void cfpo_nufft_type2_at(const cfpo_nufft *U, double x, double y, double *re, double *im);

#endif
