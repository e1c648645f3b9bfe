/* test_lowfreq.c - P0, H and alpha (lowfreq.h) on synthetic spectra whose
 * answers are known (a constant, a line plus peaks, powers of |k|) and on
 * real sets: white noise (P0 and the intercept near 1, alpha near 0),
 * jittered (alpha near 2, P0 small) and CFPO (P0 far below white noise). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "lowfreq.h"
#include "power.h"
#include "rings.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

static an_lowfreq of(const double *P, int K, size_t n)
{
    an_rings r;
    an_lowfreq lf;
    CHECK(an_rings_compute(P, K, &r) == 0, "rings");
    CHECK(an_lowfreq_compute(P, K, n, &r, &lf) == 0, "lowfreq");
    an_rings_free(&r);
    return lf;
}

static an_lowfreq of_sets(const char *what, int kind, size_t n, int sets)
{
    const int K = (int)ceil(6 * sqrt((double)n));
    const size_t N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P), *avg = calloc(N, sizeof *avg), *xy = malloc(2 * n * sizeof *xy);
    char err[256];
    for (int s = 0; s < sets; s++) {
        if (kind == 0) set_white(xy, n, 300 + s);
        else if (kind == 1) set_jittered(xy, (size_t)llround(sqrt((double)n)), 400 + s);
        else {
            cfpo_options o;
            cfpo_options_init(&o);
            o.seed = 500 + s;
            o.threads = 1;
            cfpo_result res;
            CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
        }
        CHECK(an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) == 0, "%s: %s", what, err);
        for (size_t t = 0; t < N; t++) avg[t] += P[t] / sets;
    }
    an_lowfreq lf = of(avg, K, n);
    printf("%-12s n=%zu sets=%d: P0 %.4g  H %.4g (S0 %.4g, peak %.4g at ring %d)  alpha %.3f over %d rings\n", what,
           n, sets, lf.p0, lf.h, lf.s0, lf.peak, lf.peak_ring, lf.alpha, lf.rings);
    free(P); free(avg); free(xy);
    return lf;
}

int main(void)
{
    const size_t n = 4096; /* R = 12.8: rings 1..12 */
    const int K = 40;
    const size_t N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P);

    /* constant: P0 is it, over every k with 25 |k|^2 <= n */
    for (size_t t = 0; t < N; t++) P[t] = 0.3;
    long long count = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) count += kx * kx + ky * ky > 0 && 25 * (kx * kx + ky * ky) <= (int)n;
    an_lowfreq lf = of(P, K, n);
    CHECK(fabs(lf.p0 - 0.3) < 1e-15 && lf.p0_count == count, "constant: P0 %.17g over %lld (want %lld)", lf.p0,
          lf.p0_count, count);
    CHECK(lf.rings == 12 && fabs(lf.range - 12.8) < 1e-12, "rings %d, range %g", lf.rings, lf.range);
    CHECK(fabs(lf.alpha) < 1e-12 && fabs(lf.s0 - 0.3) < 1e-12, "constant: alpha %g, intercept %g", lf.alpha, lf.s0);
    CHECK(lf.peak_ring == 0 && lf.peak == 1, "constant: no peak (found ring %d)", lf.peak_ring);

    /* a line a + b|k| below the peaks: the intercept is a; the first local
     * maximum reaching 1 is ring 30 (ring 25's bump stays below 1) */
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            const double k = sqrt((double)(kx * kx + ky * ky));
            const int ring = an_ring_of((int64_t)kx * kx + (int64_t)ky * ky);
            double v = ring <= 20 ? 0.01 + 0.02 * k : 0.9;
            if (ring == 25) v = 0.95;
            if (ring == 30) v = 1.7;
            if (ring == 35) v = 2.5;
            P[an_pidx(K, kx, ky)] = v;
        }
    lf = of(P, K, n);
    CHECK(fabs(lf.s0 - 0.01) < 1e-12 && lf.peak_ring == 30 && fabs(lf.peak - 1.7) < 1e-12 &&
              fabs(lf.h - 0.01 / 1.7) < 1e-12,
          "line: intercept %.15g, peak %g at ring %d, H %.15g", lf.s0, lf.peak, lf.peak_ring, lf.h);

    /* powers of |k|: alpha recovers them (ring means of |k|^b against the
     * ring mean of |k|: within 2%) */
    for (int b = 1; b <= 4; b++) {
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) P[an_pidx(K, kx, ky)] = 1e-3 * pow(kx * kx + ky * ky, b / 2.0);
        lf = of(P, K, n);
        CHECK(fabs(lf.alpha - b) < 0.02 * b, "|k|^%d: alpha %.6g", b, lf.alpha);
    }
    /* the box cuts the range (K = 10 < 12.8): nothing */
    {
        an_rings r;
        an_lowfreq cut;
        const int k10 = 10;
        double *Q = malloc(an_side(k10) * an_side(k10) * sizeof *Q);
        for (size_t t = 0; t < an_side(k10) * an_side(k10); t++) Q[t] = 0.5;
        CHECK(an_rings_compute(Q, k10, &r) == 0 && an_lowfreq_compute(Q, k10, n, &r, &cut) == 0, "K = 10");
        CHECK(isnan(cut.p0) && isnan(cut.h) && isnan(cut.alpha), "K = 10: P0 %g, H %g, alpha %g", cut.p0, cut.h,
              cut.alpha);
        an_rings_free(&r);
        free(Q);
    }
    /* too small a set: no frequency in range */
    lf = of(P, K, 20);
    CHECK(isnan(lf.p0) && isnan(lf.h) && isnan(lf.alpha), "n = 20: P0 %g, H %g, alpha %g", lf.p0, lf.h, lf.alpha);
    free(P);

    /* real sets, averaged as the paper averages */
    lf = of_sets("white noise", 0, 4096, 10);
    CHECK(fabs(lf.p0 - 1) < 0.1 && fabs(lf.alpha) < 0.3, "white noise: P0 %g, alpha %g", lf.p0, lf.alpha);
    const double white_h = lf.h;
    CHECK(white_h > 0.5, "white noise: H %g", white_h);
    lf = of_sets("jittered", 1, 4096, 10);
    CHECK(lf.p0 < 0.2 && fabs(lf.alpha - 2) < 0.3, "jittered: P0 %g, alpha %g", lf.p0, lf.alpha);
    lf = of_sets("cfpo", 2, 4096, 4);
    CHECK(lf.p0 < 0.05 && lf.h < 0.05, "cfpo: P0 %g, H %g", lf.p0, lf.h);
    return test_report(passed_, failed_);
}
