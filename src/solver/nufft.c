/* nufft.c - see nufft.h: the non-uniform FFT on the unit torus (kernel,
 * fixed-point spreading, FFTW transforms, deconvolution, interpolation). */
#include "nufft.h"

#include <fftw3.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"
#include "quadrature.h"

#define MAXW CFPO_NUFFT_MAXW
#define DEG CFPO_NUFFT_DEG
#define PW CFPO_NUFFT_MAXW

static pthread_mutex_t planner = PTHREAD_MUTEX_INITIALIZER;

int cfpo_nufft_fft_size(int m)
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

static double kernel_at(const cfpo_nufft *U, double t)
{
    double s = 1.0 - (t / U->alpha) * (t / U->alpha);
    return s > 0 ? exp(U->beta * (sqrt(s) - 1.0)) : 0.0;
}

/* phihat(k / M) for k = 0..K: the integral of phi(t) cos(2 pi nu t). */
static void kernel_ft(cfpo_nufft *U)
{
    enum { Q = 96 };
    double z[Q], wt[Q], f[Q];
    cfpo_gauss_legendre(Q, z, wt);
    for (int i = 0; i < Q; i++) f[i] = wt[i] * kernel_at(U, U->alpha * z[i]);
    for (int kk = 0; kk <= U->K; kk++) {
        double nu = (double)kk / U->M, s = 0;
        for (int i = 0; i < Q; i++) s += f[i] * cos(2 * M_PI * nu * U->alpha * z[i]);
        U->phihat[kk] = U->alpha * s;
    }
}

/* The w kernel values of a point at grid coordinates ux and uy (vx, vy);
 * their first grid indices (may be negative; callers wrap). With
 * l0 = ceil(u - alpha), z = u - l0 lies in (alpha - 1, alpha] and value a
 * is phi(z - a): on that unit interval, a polynomial of degree U->deg in
 * s = 2 (z - alpha) + 1 in [-1, 1], its coefficients pc[d * PW + a] fitted
 * at init (poly_fit), as FINUFFT does: no exp or sqrt per value, all w
 * values of both axes by one Horner loop (two independent chains). */
static inline void kernel_rows(const cfpo_nufft *U, double ux, double uy, double *vx, double *vy, int *lx, int *ly)
{
    *lx = (int)ceil(ux - U->alpha);
    *ly = (int)ceil(uy - U->alpha);
    const double sx = 2 * (ux - (double)*lx - U->alpha) + 1, sy = 2 * (uy - (double)*ly - U->alpha) + 1;
    const double *c = U->pc + U->deg * PW;
    double tx[PW], ty[PW];
    for (int a = 0; a < PW; a++) tx[a] = ty[a] = c[a];
    for (int d = U->deg - 1; d >= 0; d--) {
        c -= PW;
        for (int a = 0; a < PW; a++) {
            tx[a] = tx[a] * sx + c[a];
            ty[a] = ty[a] * sy + c[a];
        }
    }
    for (int a = 0; a < U->w; a++) vx[a] = tx[a], vy[a] = ty[a];
}

/* The polynomials of kernel_rows: interpolation at the deg + 1 Chebyshev
 * points of [-1, 1] (a Vandermonde system, solved by elimination with
 * partial pivoting; its error is measured against kernel_at by test_nufft
 * through the transforms). */
static void poly_fit(cfpo_nufft *U)
{
    const int Q = U->deg + 1;
    double s[DEG + 1];
    for (int i = 0; i < Q; i++) s[i] = cos(M_PI * (i + 0.5) / Q);
    memset(U->pc, 0, sizeof U->pc);
    for (int a = 0; a < U->w; a++) {
        double A[DEG + 1][DEG + 2];
        for (int i = 0; i < Q; i++) {
            double p = 1;
            for (int d = 0; d < Q; d++) A[i][d] = p, p *= s[i];
            /* z = alpha + (s - 1) / 2, the value phi(z - a) */
            A[i][Q] = kernel_at(U, U->alpha + 0.5 * (s[i] - 1) - a);
        }
        for (int col = 0; col < Q; col++) {
            int piv = col;
            for (int r = col + 1; r < Q; r++)
                if (fabs(A[r][col]) > fabs(A[piv][col])) piv = r;
            for (int d = 0; d <= Q; d++) {
                const double tmp = A[col][d];
                A[col][d] = A[piv][d];
                A[piv][d] = tmp;
            }
            for (int r = 0; r < Q; r++) {
                if (r == col) continue;
                const double f = A[r][col] / A[col][col];
                for (int d = col; d <= Q; d++) A[r][d] -= f * A[col][d];
            }
        }
        for (int d = 0; d < Q; d++) U->pc[d * PW + a] = A[d][Q] / A[d][d];
    }
}

static inline int wrap(int i, int M) { return i < 0 ? i + M : (i >= M ? i - M : i); }

int cfpo_nufft_scale(int64_t total)
{
    int bits = 0; /* bits of total + 1 */
    for (uint64_t t = (uint64_t)(total > 0 ? total : 0) + 1; t; t >>= 1) bits++;
    const int s = 62 - bits;
    return s < 40 ? s : 40;
}

void cfpo_nufft_free(cfpo_nufft *U)
{
    pthread_mutex_lock(&planner);
    if (U->p1) fftw_destroy_plan((fftw_plan)U->p1);
    if (U->p2) fftw_destroy_plan((fftw_plan)U->p2);
    pthread_mutex_unlock(&planner);
    fftw_free(U->g1);
    fftw_free(U->g2);
    free(U->phihat);
    memset(U, 0, sizeof *U);
}

int cfpo_nufft_init(cfpo_nufft *U, int K, int w, int types, int threads, char *err, size_t errlen)
{
    memset(U, 0, sizeof *U);
    if (K < 1 || K > 8192 || w < 4 || w > MAXW || !(types & (CFPO_NUFFT_TYPE1 | CFPO_NUFFT_TYPE2))) {
        snprintf(err, errlen, "nufft: bad request (K=%d, width=%d)", K, w);
        return -1;
    }
    int M = 2 * (2 * K + 1);
    if (M < 2 * w) M = 2 * w;
    U->M = M = cfpo_nufft_fft_size(M);
    U->K = K;
    U->w = w;
    U->alpha = 0.5 * w;
    U->beta = 2.30 * w;
    U->deg = w + 3 < DEG ? w + 3 : DEG;
    U->threads = threads > 0 ? threads : omp_get_max_threads();
    U->stride = 2 * ((size_t)M / 2 + 1);
    U->phihat = malloc(((size_t)K + 1) * sizeof *U->phihat);
    if (types & CFPO_NUFFT_TYPE1) U->g1 = fftw_malloc(sizeof(double) * (size_t)M * U->stride);
    if (types & CFPO_NUFFT_TYPE2) U->g2 = fftw_malloc(sizeof(double) * 2 * (size_t)M * (size_t)M);
    if (!U->phihat || ((types & CFPO_NUFFT_TYPE1) && !U->g1) || ((types & CFPO_NUFFT_TYPE2) && !U->g2)) {
        cfpo_nufft_free(U);
        snprintf(err, errlen, "nufft: out of memory for a %d x %d grid", M, M);
        return -1;
    }
    pthread_mutex_lock(&planner);
    if (U->g1) U->p1 = fftw_plan_dft_r2c_2d(M, M, (double *)U->g1, (fftw_complex *)U->g1, FFTW_ESTIMATE);
    if (U->g2)
        U->p2 = fftw_plan_dft_2d(M, M, (fftw_complex *)U->g2, (fftw_complex *)U->g2, FFTW_BACKWARD, FFTW_ESTIMATE);
    pthread_mutex_unlock(&planner);
    if ((U->g1 && !U->p1) || (U->g2 && !U->p2)) {
        cfpo_nufft_free(U);
        snprintf(err, errlen, "nufft: FFTW could not plan a %d x %d transform", M, M);
        return -1;
    }
    kernel_ft(U);
    poly_fit(U);
    return 0;
}

int64_t *cfpo_nufft_grid(cfpo_nufft *U) { return (int64_t *)U->g1; }
size_t cfpo_nufft_grid_count(const cfpo_nufft *U) { return (size_t)U->M * U->stride; }

/* ---- type 1 ---- */

static inline int first_row(const cfpo_nufft *U, double y)
{
    return wrap((int)ceil(y * U->M - U->alpha), U->M);
}

static inline int strip_begin(int s, int S, int M) { return (int)((int64_t)s * M / S); }

static int strip_of(int row, int S, int M)
{
    int s = (int)((int64_t)row * S / M);
    while (s + 1 < S && strip_begin(s + 1, S, M) <= row) s++;
    while (s > 0 && strip_begin(s, S, M) > row) s--;
    return s;
}

/* One point's w x w contributions; W is w as a constant where it is one of
 * the common widths (spread_point), so the loops unroll and vectorise. */
static inline __attribute__((always_inline)) void spread_w(const cfpo_nufft *U, double x, double y, double unit,
                                                          int64_t *grid, const int w)
{
    double vx[MAXW], vy[MAXW];
    const int M = U->M;
    int lx, ly;
    kernel_rows(U, x * M, y * M, vx, vy, &lx, &ly);
    const int inside = lx >= 0 && lx + w <= M;
    for (int b = 0; b < w; b++) {
        int64_t *r = grid + (size_t)wrap(ly + b, M) * U->stride;
        const double c = vy[b] * unit;
        /* every product is >= 0: + 0.5 and truncation round it */
        if (inside) {
            int64_t *rr = r + lx;
            for (int a = 0; a < w; a++) rr[a] += (int64_t)(c * vx[a] + 0.5);
        } else {
            for (int a = 0; a < w; a++) r[wrap(lx + a, M)] += (int64_t)(c * vx[a] + 0.5);
        }
    }
}

static void spread_point(const cfpo_nufft *U, double x, double y, double unit, int64_t *grid)
{
    switch (U->w) {
    case 6: spread_w(U, x, y, unit, grid, 6); break;
    case 8: spread_w(U, x, y, unit, grid, 8); break;
    case 10: spread_w(U, x, y, unit, grid, 10); break;
    case 12: spread_w(U, x, y, unit, grid, 12); break;
    default: spread_w(U, x, y, unit, grid, U->w);
    }
}

int cfpo_nufft_spread(cfpo_nufft *U, const double *x, const double *y, size_t step, size_t np, int64_t total)
{
    const int M = U->M;
    int64_t *grid = (int64_t *)U->g1;
    const size_t rows = U->stride;
    const double unit = ldexp(1.0, cfpo_nufft_scale(total));
    int S = M / U->w;
    if (S > 128) S = 128;
    S &= ~1;
    if (S < 2) S = 2; /* M >= 2w guarantees strips of at least w rows */
    size_t *start = calloc((size_t)S + 1, sizeof *start);
    size_t *order = malloc((np ? np : 1) * sizeof *order);
    if (!start || !order) {
        free(start);
        free(order);
        return -1;
    }
#pragma omp parallel for schedule(static) num_threads(U->threads)
    for (int r = 0; r < M; r++) memset(grid + (size_t)r * rows, 0, rows * sizeof *grid);
    for (size_t j = 0; j < np; j++) start[strip_of(first_row(U, y[j * step]), S, M) + 1]++;
    for (int s = 0; s < S; s++) start[s + 1] += start[s];
    for (size_t j = 0; j < np; j++) order[start[strip_of(first_row(U, y[j * step]), S, M)]++] = j;
    for (int s = S; s > 0; s--) start[s] = start[s - 1];
    start[0] = 0;
    for (int parity = 0; parity < 2; parity++) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(U->threads)
        for (int s = parity; s < S; s += 2)
            for (size_t q = start[s]; q < start[s + 1]; q++) {
                const size_t j = order[q];
                spread_point(U, x[j * step], y[j * step], unit, grid);
            }
    }
    free(start);
    free(order);
    return 0;
}

void cfpo_nufft_type1_finish(cfpo_nufft *U, int64_t total)
{
    const double q = ldexp(1.0, -cfpo_nufft_scale(total));
    const size_t N = cfpo_nufft_grid_count(U);
    unsigned char *g = U->g1;
    /* the int64 sums to doubles in place (memcpy: no aliasing of types) */
#pragma omp parallel for schedule(static) num_threads(U->threads)
    for (size_t i = 0; i < N; i++) {
        int64_t v;
        memcpy(&v, g + 8 * i, 8);
        const double d = (double)v * q;
        memcpy(g + 8 * i, &d, 8);
    }
    fftw_execute((fftw_plan)U->p1);
}

int cfpo_nufft_type1(cfpo_nufft *U, const double *x, const double *y, size_t step, size_t n)
{
    if (cfpo_nufft_spread(U, x, y, step, n, (int64_t)n) != 0) return -1;
    cfpo_nufft_type1_finish(U, (int64_t)n);
    return 0;
}

void cfpo_nufft_coef(const cfpo_nufft *U, int kx, int ky, double *re, double *im)
{
    /* the real-to-complex transform keeps kx >= 0; f(-k) = conj f(k) */
    const int flip = kx < 0;
    if (flip) kx = -kx, ky = -ky;
    const double *row = (const double *)U->g1 + (size_t)(ky < 0 ? ky + U->M : ky) * U->stride;
    const double d = U->phihat[ky < 0 ? -ky : ky] * U->phihat[kx];
    *re = row[2 * kx] / d;
    *im = row[2 * kx + 1] / d;
    if (flip) *im = -*im;
}

/* ---- type 2 ---- */

void cfpo_nufft_type2_prepare(cfpo_nufft *U, const double *C)
{
    const int K = U->K, M = U->M, W = 2 * K + 1;
    memset(U->g2, 0, sizeof(double) * 2 * (size_t)M * (size_t)M);
    for (int ky = -K; ky <= K; ky++) {
        double *row = U->g2 + 2 * (size_t)wrap(ky, M) * (size_t)M;
        const double *c = C + 2 * (size_t)(ky + K) * (size_t)W;
        for (int kx = -K; kx <= K; kx++) {
            const double d = U->phihat[ky < 0 ? -ky : ky] * U->phihat[kx < 0 ? -kx : kx];
            row[2 * wrap(kx, M)] = c[2 * (kx + K)] / d;
            row[2 * wrap(kx, M) + 1] = c[2 * (kx + K) + 1] / d;
        }
    }
    fftw_execute((fftw_plan)U->p2);
}

/* g at one point; W as in spread_w. */
static inline __attribute__((always_inline)) void interp_w(const cfpo_nufft *U, double x, double y, double *re,
                                                          double *im, const int w)
{
    double vx[MAXW], vy[MAXW];
    const int M = U->M;
    int lx, ly;
    kernel_rows(U, x * M, y * M, vx, vy, &lx, &ly);
    double sr = 0, si = 0;
    if (lx >= 0 && lx + w <= M) {
        for (int b = 0; b < w; b++) {
            const double *r = U->g2 + 2 * ((size_t)wrap(ly + b, M) * (size_t)M + (size_t)lx);
            double tr = 0, ti = 0;
            for (int a = 0; a < w; a++) {
                tr += vx[a] * r[2 * a];
                ti += vx[a] * r[2 * a + 1];
            }
            sr += vy[b] * tr;
            si += vy[b] * ti;
        }
    } else {
        int col[MAXW];
        for (int a = 0; a < w; a++) col[a] = wrap(lx + a, M);
        for (int b = 0; b < w; b++) {
            const double *r = U->g2 + 2 * (size_t)wrap(ly + b, M) * (size_t)M;
            double tr = 0, ti = 0;
            for (int a = 0; a < w; a++) {
                tr += vx[a] * r[2 * col[a]];
                ti += vx[a] * r[2 * col[a] + 1];
            }
            sr += vy[b] * tr;
            si += vy[b] * ti;
        }
    }
    *re = sr;
    *im = si;
}

void cfpo_nufft_type2_at(const cfpo_nufft *U, double x, double y, double *re, double *im)
{
    switch (U->w) {
    case 6: interp_w(U, x, y, re, im, 6); break;
    case 8: interp_w(U, x, y, re, im, 8); break;
    case 10: interp_w(U, x, y, re, im, 10); break;
    case 12: interp_w(U, x, y, re, im, 12); break;
    default: interp_w(U, x, y, re, im, U->w);
    }
}
