/* test_nufft.c - the core library's non-uniform FFT (src/solver/nufft.h) and the
 * hyperuniform variant's transport field built on it (src/engine/transport.h),
 * against direct sums:
 *  - type 1 on random points (several n, K, widths): the largest error
 *    over |kx|, |ky| <= K relative to the largest |f(k)| within the bound
 *    of the width (about 10^-(w-1)); width 4 must miss the bound of width
 *    10, and the conjugate reference (the wrong sign) must miss it too;
 *  - type 2 with random coefficients at random points, likewise, and
 *    against the wrong sign;
 *  - type 1 is the same bits for 1 and 3 threads, and for the set cut into
 *    two parts whose integer grids are added (what the ranks of a run do);
 *  - the transport field against its definition's direct sum, u(x) =
 *    sum_k -i k rho_hat(k) / (2 pi n |k|^2) exp(2 pi i k.x) over the band
 *    0 < 25 |k|^2 <= n, and the field's direction: it points down the
 *    density's gradient for a set with one density mode. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "nufft.h"
#include "testutil.h"
#include "transport.h"

static int passed_, failed_;

static double uni(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * 0x1p-53;
}

/* exp(sign 2 pi i k t) with the phase reduced first (a few ulps). */
static void cis(double k, double t, int sign, double *c, double *s)
{
    double p = k * t;
    p -= nearbyint(p);
    *c = cos(2 * M_PI * p);
    *s = sign * sin(2 * M_PI * p);
}

/* f(k) = sum_j exp(sign 2 pi i k.x_j) directly. */
static void direct1(const double *x, const double *y, int n, int kx, int ky, int sign, double *re, double *im)
{
    double sr = 0, si = 0;
    for (int j = 0; j < n; j++) {
        double c1, s1, c2, s2;
        cis(kx, x[j], sign, &c1, &s1);
        cis(ky, y[j], sign, &c2, &s2);
        sr += c1 * c2 - s1 * s2;
        si += c1 * s2 + s1 * c2;
    }
    *re = sr;
    *im = si;
}

/* The largest |f_nufft - f_direct| over the square, relative to the
 * largest |f_direct|; sign -1 is the definition, +1 the wrong sign. */
static double type1_error(int n, int K, int w, int sign, uint64_t seed)
{
    double *x = malloc(sizeof(double) * (size_t)n), *y = malloc(sizeof(double) * (size_t)n);
    for (int j = 0; j < n; j++) x[j] = uni(&seed), y[j] = uni(&seed);
    cfpo_nufft U;
    char err[128];
    if (cfpo_nufft_init(&U, K, w, CFPO_NUFFT_TYPE1, 2, err, sizeof err) != 0 || cfpo_nufft_type1(&U, x, y, 1, (size_t)n) != 0) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
    double worst = 0, big = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            double re, im, dr, di;
            cfpo_nufft_coef(&U, kx, ky, &re, &im);
            direct1(x, y, n, kx, ky, sign, &dr, &di);
            worst = fmax(worst, hypot(re - dr, im - di));
            big = fmax(big, hypot(dr, di));
        }
    cfpo_nufft_free(&U);
    free(x);
    free(y);
    return worst / big;
}

/* Type 2: random C, g at random points; the largest error relative to the
 * largest |g|. */
static double type2_error(int npts, int K, int w, int sign, uint64_t seed)
{
    const int W = 2 * K + 1;
    double *C = malloc(sizeof(double) * 2 * (size_t)W * (size_t)W);
    for (int i = 0; i < 2 * W * W; i++) C[i] = 2 * uni(&seed) - 1;
    cfpo_nufft U;
    char err[128];
    if (cfpo_nufft_init(&U, K, w, CFPO_NUFFT_TYPE2, 1, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
    cfpo_nufft_type2_prepare(&U, C);
    double worst = 0, big = 0;
    for (int j = 0; j < npts; j++) {
        const double x = uni(&seed), y = uni(&seed);
        double re, im, sr = 0, si = 0;
        cfpo_nufft_type2_at(&U, x, y, &re, &im);
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                double c1, s1, c2, s2;
                cis(kx, x, sign, &c1, &s1);
                cis(ky, y, sign, &c2, &s2);
                const double er = c1 * c2 - s1 * s2, ei = c1 * s2 + s1 * c2;
                const double *c = C + 2 * ((ky + K) * W + kx + K);
                sr += c[0] * er - c[1] * ei;
                si += c[0] * ei + c[1] * er;
            }
        worst = fmax(worst, hypot(re - sr, im - si));
        big = fmax(big, hypot(sr, si));
    }
    cfpo_nufft_free(&U);
    free(C);
    return worst / big;
}

/* The bound for width w: 10^-(w-2), ten times the kernel's nominal error
 * (measured: 1.6e-9 for type 2 at width 10), but not below 1e-9 (at width
 * 12 the sums' own rounding, about 1e-10, is reached). */
static double bound(int w) { return fmax(pow(10.0, -(w - 2)), 1e-9); }

static void accuracy(void)
{
    static const int ns[] = {1, 50, 700}, Ks[] = {1, 6, 23, 40}, ws[] = {6, 8, 10, 12};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 4; b++)
            for (int c = 0; c < 4; c++) {
                const double e = type1_error(ns[a], Ks[b], ws[c], -1, 11 + (uint64_t)(a * 16 + b * 4 + c));
                CHECK(e <= bound(ws[c]), "type 1 n=%d K=%d w=%d: error %.2e > %.0e", ns[a], Ks[b], ws[c], e, bound(ws[c]));
            }
    for (int b = 0; b < 4; b++)
        for (int c = 0; c < 4; c++) {
            const double e = type2_error(200, Ks[b], ws[c], +1, 7 + (uint64_t)(b * 4 + c));
            CHECK(e <= bound(ws[c]), "type 2 K=%d w=%d: error %.2e > %.0e", Ks[b], ws[c], e, bound(ws[c]));
        }
    const double e10 = type1_error(2000, 23, 10, -1, 5), e2 = type2_error(200, 23, 10, +1, 5);
    printf("width 10, K 23: type 1 error %.2e, type 2 error %.2e\n", e10, e2);
    /* the comparisons can fail: a narrow kernel, the wrong sign */
    const double narrow = type1_error(2000, 23, 4, -1, 5), narrow2 = type2_error(200, 23, 4, +1, 5);
    CHECK(narrow > bound(10) && narrow2 > bound(10), "width 4 passes width 10's bound: %.2e, %.2e", narrow, narrow2);
    const double wrong1 = type1_error(2000, 23, 10, +1, 5), wrong2 = type2_error(200, 23, 10, -1, 5);
    CHECK(wrong1 > 0.1 && wrong2 > 0.1, "the wrong sign passes: %.2e, %.2e", wrong1, wrong2);
}

/* Type 1's bits: threads 1 and 3, and two parts' grids added. */
static void bits(void)
{
    const int n = 5000, K = 30;
    uint64_t seed = 99;
    double *x = malloc(sizeof(double) * n), *y = malloc(sizeof(double) * n);
    for (int j = 0; j < n; j++) x[j] = uni(&seed), y[j] = uni(&seed);
    cfpo_nufft A, B, P;
    char err[128];
    int ok = cfpo_nufft_init(&A, K, 10, CFPO_NUFFT_TYPE1, 1, err, sizeof err) == 0 &&
             cfpo_nufft_init(&B, K, 10, CFPO_NUFFT_TYPE1, 3, err, sizeof err) == 0 &&
             cfpo_nufft_init(&P, K, 10, CFPO_NUFFT_TYPE1, 2, err, sizeof err) == 0;
    CHECK(ok, "init: %s", err);
    if (!ok) exit(1);
    cfpo_nufft_type1(&A, x, y, 1, n);
    cfpo_nufft_type1(&B, x, y, 1, n);
    /* parts: the odd-numbered points, then the even ones, into P's grid */
    int64_t *g = malloc(sizeof(int64_t) * cfpo_nufft_grid_count(&P));
    cfpo_nufft_spread(&P, x + 1, y + 1, 2, n / 2, n);
    memcpy(g, cfpo_nufft_grid(&P), sizeof(int64_t) * cfpo_nufft_grid_count(&P));
    cfpo_nufft_spread(&P, x, y, 2, (n + 1) / 2, n);
    for (size_t i = 0; i < cfpo_nufft_grid_count(&P); i++) cfpo_nufft_grid(&P)[i] += g[i];
    cfpo_nufft_type1_finish(&P, n);
    int same3 = 1, sameparts = 1;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            double a[2], b[2], p[2];
            cfpo_nufft_coef(&A, kx, ky, &a[0], &a[1]);
            cfpo_nufft_coef(&B, kx, ky, &b[0], &b[1]);
            cfpo_nufft_coef(&P, kx, ky, &p[0], &p[1]);
            same3 &= memcmp(a, b, sizeof a) == 0;
            sameparts &= memcmp(a, p, sizeof a) == 0;
        }
    CHECK(same3, "type 1 differs between 1 and 3 threads");
    CHECK(sameparts, "type 1 differs when the set is cut into two parts");
    CHECK(cfpo_nufft_scale(n) == 40 && cfpo_nufft_scale((int64_t)1 << 40) == 21,
          "fixed-point scale: %d, %d", cfpo_nufft_scale(n), cfpo_nufft_scale((int64_t)1 << 40));
    cfpo_nufft_free(&A);
    cfpo_nufft_free(&B);
    cfpo_nufft_free(&P);
    free(g);
    free(x);
    free(y);
}

/* The weight of mode k (transport.h): 1 on the band 0 < |k| <= kb = 0.2
 * sqrt(n), cos^2 of (pi / 2) (|k| / kb - 1) / CFPO_TRANSPORT_TAPER past it
 * up to (1 + CFPO_TRANSPORT_TAPER) kb, 0 beyond. */
static double weight_direct(int kx, int ky, int n)
{
    if (cfpo_in_lowk_band(kx, ky, n)) return 1;
    const double t = (hypot(kx, ky) / (0.2 * sqrt(n)) - 1) / CFPO_TRANSPORT_TAPER;
    return t > 0 && t < 1 ? cos(0.5 * M_PI * t) * cos(0.5 * M_PI * t) : 0;
}

/* u at (px, py) from the definition, directly. */
static void field_direct(const double *x, const double *y, int n, double px, double py, double *ux, double *uy)
{
    const int K = (int)ceil(0.2 * sqrt(n) * (1 + CFPO_TRANSPORT_TAPER));
    double sx = 0, sy = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            const double w = weight_direct(kx, ky, n);
            if (w == 0) continue;
            double rr, ri, c1, s1, c2, s2;
            direct1(x, y, n, kx, ky, -1, &rr, &ri);
            cis(kx, px, 1, &c1, &s1);
            cis(ky, py, 1, &c2, &s2);
            const double er = c1 * c2 - s1 * s2, ei = c1 * s2 + s1 * c2, q = 2 * M_PI * n * (kx * kx + ky * ky);
            /* Re(-i rho e) = Im(rho e) */
            const double t = w * (rr * ei + ri * er) / q;
            sx += kx * t;
            sy += ky * t;
        }
    *ux = sx;
    *uy = sy;
}

static void transport(void)
{
    const int n = 1500;
    uint64_t seed = 3;
    double *x = malloc(sizeof(double) * n), *y = malloc(sizeof(double) * n);
    for (int j = 0; j < n; j++) x[j] = uni(&seed), y[j] = uni(&seed);
    cfpo_transport F;
    CHECK(cfpo_transport_init(&F, n, 2) == 0, "transport init");
    cfpo_transport_spread(&F, x, y, n, n);
    cfpo_transport_finish(&F, n);
    double worst = 0, big = 0;
    for (int i = 0; i < 100; i++) {
        const double px = uni(&seed), py = uni(&seed);
        double ux, uy, dx, dy;
        cfpo_transport_field(&F, px, py, &ux, &uy);
        field_direct(x, y, n, px, py, &dx, &dy);
        worst = fmax(worst, hypot(ux - dx, uy - dy));
        big = fmax(big, hypot(dx, dy));
    }
    printf("transport field: error %.2e relative to the largest |u| %.3e\n", worst / big, big);
    CHECK(big > 0 && worst <= bound(CFPO_TRANSPORT_WIDTH) * big, "transport field: error %.2e of %.2e (width %d)", worst, big,
          CFPO_TRANSPORT_WIDTH);
    cfpo_transport_free(&F);
    /* one mode: density 1 + 0.5 cos(2 pi x) (points at the quantiles of
     * that density in x); u must point away from x = 0, the density's peak,
     * with |u| about 0.5 / (2 pi) sin(2 pi x) */
    const int m = 100, nn = m * m;
    double *X = malloc(sizeof(double) * nn), *Y = malloc(sizeof(double) * nn);
    for (int i = 0; i < m; i++) {
        double q = (i + 0.5) / m, t = q; /* solve t + 0.5 sin(2 pi t) / (2 pi) = q by Newton */
        for (int it = 0; it < 50; it++) t -= (t + 0.25 / M_PI * sin(2 * M_PI * t) - q) / (1 + 0.5 * cos(2 * M_PI * t));
        for (int j = 0; j < m; j++) X[i * m + j] = cfpo_wrap01(t), Y[i * m + j] = (j + 0.5) / m;
    }
    CHECK(cfpo_transport_init(&F, nn, 1) == 0, "transport init");
    cfpo_transport_spread(&F, X, Y, nn, nn);
    cfpo_transport_finish(&F, nn);
    double u1, v1, u2, v2;
    cfpo_transport_field(&F, 0.25, 0.3, &u1, &v1);
    cfpo_transport_field(&F, 0.75, 0.3, &u2, &v2);
    printf("one mode: u(0.25) = (%.4f, %.1e), u(0.75) = (%.4f, %.1e), expected +-%.4f\n", u1, v1, u2, v2, 0.25 / M_PI);
    CHECK(fabs(u1 - 0.25 / M_PI) < 0.01 && fabs(u2 + 0.25 / M_PI) < 0.01 && fabs(v1) < 1e-3 && fabs(v2) < 1e-3,
          "one mode: u(0.25) = (%g, %g), u(0.75) = (%g, %g)", u1, v1, u2, v2);
    cfpo_transport_free(&F);
    free(X);
    free(Y);
    free(x);
    free(y);
}

int main(void)
{
    accuracy();
    bits();
    transport();
    return test_report(passed_, failed_);
}
