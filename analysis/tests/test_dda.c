/* test_dda.c - the differential-domain spectrum (dda.h) against what it
 * must equal:
 *  - every pair, rho = 1: the periodogram of power.h (exact sum), all k,
 *    to 1e-5 of max(P, 1) (the spreading errs by about 1e-7 of the pairs'
 *    total weight, n - 1 here);
 *  - every pair, a random piecewise-constant rho: the direct double sum of
 *    the definition over all ordered pairs, all k;
 *  - the window (R = 2 and 3): the direct double sum with the window's
 *    weights over all pairs (no cell list), all k;
 *  - the window's transform What against a polar quadrature of W;
 *  - rho = 1, window R = AN_DDA_RADIUS, a dart-throwing set of about 2,500
 *    points: the radial means agree with the periodogram's RAPS over
 *    bands of 0.125 sqrt(n) to within 0.15 max(band mean, 1), and the
 *    low-frequency means to within 15% (the window smooths a sharp peak by
 *    about 7% and the periodogram's rings are noisy: see analysis/README.md);
 *  - the same bytes with 1 and 2 threads;
 *  - refusals: R = 0 beyond AN_DDA_FULL_MAX, no point on the support, bad
 *    R, and the memory check's one line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dda.h"
#include "density.h"
#include "geom.h"
#include "omp_compat.h"
#include "power.h"
#include "rings.h"
#include "testsets.h"
#include "testdensity.h"
#include "testutil.h"

static int passed_, failed_;

/* The definition summed directly: every ordered pair (i != j) of points on
 * the support, weight W (b = R Delta; b = 0: W = 1), minus m What. */
static void brute(const cfpo_density *d, const double *xy, size_t n, int K, double radius, double *S)
{
    const double b = radius * cfpo_delta_bound((double)n);
    size_t m = 0;
    for (size_t i = 0; i < n; i++) m += cfpo_density_at(d, xy[2 * i], xy[2 * i + 1]) > 0;
    const size_t side = an_side(K);
    double *acc = calloc(side * side, sizeof *acc);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            const double ri = cfpo_density_at(d, xy[2 * i], xy[2 * i + 1]), rj = cfpo_density_at(d, xy[2 * j], xy[2 * j + 1]);
            if (i == j || ri == 0 || rj == 0) continue;
            const double f = pow(ri * rj, 0.25);
            double dx = xy[2 * j] - xy[2 * i], dy = xy[2 * j + 1] - xy[2 * i + 1];
            dx = (dx - floor(dx + 0.5)) * f;
            dy = (dy - floor(dy + 0.5)) * f;
            double w = 1;
            if (b > 0) {
                const double s2 = (dx * dx + dy * dy) / (b * b);
                if (s2 >= 1) continue;
                w = (1 - s2) * (1 - s2);
            }
            for (int ky = -K; ky <= K; ky++)
                for (int kx = -K; kx <= K; kx++) acc[an_pidx(K, kx, ky)] += w * cos(2 * M_PI * (kx * dx + ky * dy));
        }
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            const size_t t = an_pidx(K, kx, ky);
            S[t] = 1 + acc[t] / (double)m - (double)m * an_dda_window_ft((double)(kx * kx + ky * ky), radius, n);
        }
    free(acc);
}

static double maxdiff(const double *a, const double *b, int K)
{
    double mx = 0;
    for (size_t t = 0; t < an_side(K) * an_side(K); t++) {
        const double e = fabs(a[t] - b[t]) / fmax(1, fabs(b[t]));
        if (e > mx) mx = e;
    }
    return mx;
}

static void test_periodogram(void)
{
    cfpo_density d;
    test_density_random(&d, 1, 1, 1);
    const size_t n = 300;
    const int K = 20;
    double *xy = ts_uniform(n, 5), *S = malloc(an_side(K) * an_side(K) * sizeof *S),
           *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    char err[256];
    CHECK(an_dda_compute(&d, xy, n, K, 0, S, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(an_power_exact(xy, n, K, P, NULL, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(fabs(S[an_pidx(K, 0, 0)]) < 1e-6, "S(0) = %g, not 0", S[an_pidx(K, 0, 0)]);
    S[an_pidx(K, 0, 0)] = (double)n;
    const double e = an_power_maxdiff(S, P, K);
    CHECK(e < 1e-5, "every pair, rho = 1: differs from the periodogram by %g", e);
    free(xy), free(S), free(P);
    cfpo_density_free(&d);
}

static void test_brute(double radius, size_t n, int K, uint64_t seed)
{
    cfpo_density d;
    test_density_random(&d, 5, 7, seed);
    double *xy = ts_uniform(n, seed + 1), *S = malloc(an_side(K) * an_side(K) * sizeof *S),
           *B = malloc(an_side(K) * an_side(K) * sizeof *B);
    char err[256];
    an_dda_info info;
    CHECK(an_dda_compute(&d, xy, n, K, radius, S, &info, err, sizeof err) == 0, "%s", err);
    brute(&d, xy, n, K, radius, B);
    const double e = maxdiff(S, B, K);
    CHECK(e < 1e-5, "R = %g, n = %zu: differs from the direct sum by %g", radius, n, e);
    CHECK(info.m == n && info.pairs > 0, "info: m %zu pairs %g", info.m, info.pairs);
    free(xy), free(S), free(B);
    cfpo_density_free(&d);
}

/* What against the polar midpoint rule for W(r / b) cos(2 pi |k| r cos t). */
static void test_window_ft(void)
{
    const size_t n = 1000;
    const double R = 8, b = R * cfpo_delta_bound((double)n);
    const double ks[] = {0, 1, 3, 7.5, 12, 20, 33};
    for (size_t q = 0; q < sizeof ks / sizeof *ks; q++) {
        const int NR = 2000, NT = 512;
        double s = 0;
        for (int a = 0; a < NR; a++) {
            const double r = (a + 0.5) / NR * b, u = r / b, w = (1 - u * u) * (1 - u * u);
            double c = 0;
            for (int t = 0; t < NT; t++) c += cos(2 * M_PI * ks[q] * r * cos(2 * M_PI * (t + 0.5) / NT));
            s += w * r * c * (2 * M_PI / NT) * (b / NR);
        }
        const double f = an_dda_window_ft(ks[q] * ks[q], R, n), scale = an_dda_window_ft(0, R, n);
        CHECK(fabs(f - s) < 1e-6 * scale, "What(|k| = %g) = %.10g, quadrature %.10g", ks[q], f, s);
    }
    CHECK(an_dda_window_ft(0, 0, n) == 1 && an_dda_window_ft(4, 0, n) == 0, "R = 0: the unit mass at k = 0");
}

/* Band means of ring means over [lo, lo + 0.125) sqrt(n). */
static void bands(const double *P, int K, size_t n, double *out, int nb)
{
    an_rings r;
    an_rings_compute(P, K, &r);
    for (int b = 0; b < nb; b++) {
        double s = 0;
        int c = 0;
        for (int i = 1; i <= K; i++) {
            const double f = i / sqrt((double)n);
            if (f >= 0.125 * b && f < 0.125 * (b + 1)) s += r.mean[i], c++;
        }
        out[b] = c ? s / c : NAN;
    }
    an_rings_free(&r);
}

static void test_raps(void)
{
    cfpo_density d;
    test_density_random(&d, 1, 1, 1);
    size_t n;
    double *xy = ts_dart(0.75 * cfpo_delta_bound(2500), 60000, 11, &n);
    const int K = (int)ceil(3 * sqrt((double)n));
    double *S = malloc(an_side(K) * an_side(K) * sizeof *S), *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    char err[256];
    CHECK(an_dda_compute(&d, xy, n, K, AN_DDA_RADIUS, S, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) == 0, "%s", err);
    enum { NB = 23 };
    double a[NB], b[NB];
    bands(S, K, n, a, NB);
    bands(P, K, n, b, NB);
    for (int q = 1; q < NB; q++)
        CHECK(fabs(a[q] - b[q]) <= 0.15 * fmax(b[q], 1), "n = %zu, band %.3f: DDA %.4f, RAPS %.4f", n, 0.125 * q,
              a[q], b[q]);
    an_dda_summary s;
    an_dda_summarise(S, K, n, &s);
    double p0 = 0;
    int c = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++)
            if (cfpo_in_lowk_band(kx, ky, (int64_t)n)) p0 += P[an_pidx(K, kx, ky)], c++;
    p0 /= c;
    CHECK(fabs(s.low - p0) <= 0.15 * p0, "low-frequency mean %.5f, periodogram %.5f", s.low, p0);
    CHECK(s.peak_freq > 0.8 && s.peak_freq < 1.3 && s.peak > 1, "peak %.4f at %.4f", s.peak, s.peak_freq);
    free(xy), free(S), free(P);
    cfpo_density_free(&d);
}

static void test_threads(void)
{
    cfpo_density d;
    test_density_random(&d, 16, 16, 3);
    const size_t n = 3000;
    const int K = 60;
    double *xy = ts_uniform(n, 9), *S1 = malloc(an_side(K) * an_side(K) * sizeof *S1),
           *S2 = malloc(an_side(K) * an_side(K) * sizeof *S2);
    char err[256];
    omp_set_num_threads(1);
    CHECK(an_dda_compute(&d, xy, n, K, AN_DDA_RADIUS, S1, NULL, err, sizeof err) == 0, "%s", err);
    omp_set_num_threads(2);
    CHECK(an_dda_compute(&d, xy, n, K, AN_DDA_RADIUS, S2, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(memcmp(S1, S2, an_side(K) * an_side(K) * sizeof *S1) == 0, "1 and 2 threads differ");
    free(xy), free(S1), free(S2);
    cfpo_density_free(&d);
}

static void test_refusals(void)
{
    cfpo_density d;
    char err[256];
    double S[9];
    const double v[4] = {1, 0, 0, 0}; /* only the pixel [0, 1/2)^2 */
    CHECK(cfpo_density_from_values(v, 2, 2, "test", &d, err, sizeof err) == 0, "%s", err);
    const double xy[6] = {0.7, 0.7, 0.8, 0.9, 0.6, 0.95};
    CHECK(an_dda_compute(&d, xy, 3, 1, 8, S, NULL, err, sizeof err) != 0 && strstr(err, "no point"),
          "no point on the support: '%s'", err);
    CHECK(an_dda_compute(&d, xy, 3, 1, 0.5, S, NULL, err, sizeof err) != 0 && strstr(err, "bad request"),
          "R = 0.5: '%s'", err);
    double *big = ts_uniform(AN_DDA_FULL_MAX + 1, 1);
    CHECK(an_dda_compute(&d, big, AN_DDA_FULL_MAX + 1, 1, 0, S, NULL, err, sizeof err) != 0 && strstr(err, "O(n^2)"),
          "R = 0 beyond the limit: '%s'", err);
    free(big);
    CHECK(an_dda_check_memory(1 << 20, 2048, 8, 1e12, err, sizeof err) == 0, "1e12 bytes refused");
    CHECK(an_dda_check_memory(1 << 20, 2048, 8, 1e8, err, sizeof err) != 0 && strstr(err, "needs") &&
              !strchr(err, '\n'), "1e8 bytes: '%s'", err);
    CHECK(an_dda_bytes(1 << 20, 2048, 8) > 8.0 * 8194 * 8194, "bytes %g", an_dda_bytes(1 << 20, 2048, 8));
    cfpo_density_free(&d);
}

int main(void)
{
    test_periodogram();
    test_brute(0, 200, 12, 21);
    test_brute(2, 400, 30, 22);
    test_brute(3, 500, 24, 23);
    test_window_ft();
    test_raps();
    test_threads();
    test_refusals();
    return test_report(passed_, failed_);
}
