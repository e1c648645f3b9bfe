/* test_closed_forms.c - the periodogram against closed forms, both paths
 * (NUFFT and exact): one point gives P = 1 everywhere; two points give
 * P(k) = 1 + cos(2 pi k.(x1 - x2)); an m x m square lattice gives P = n on
 * its reciprocal lattice (k = 0 mod m) and 0 elsewhere; uniform random sets
 * average to about 1 on every ring (E P(k) = 1 for k != 0). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "power.h"
#include "rings.h"
#include "testsets.h"
#include "testutil.h"

static int passed_, failed_;

static int spectrum(int exact, const double *xy, size_t n, int K, double *P)
{
    char err[256];
    int r = exact ? an_power_exact(xy, n, K, P, NULL, NULL, err, sizeof err)
                  : an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err);
    if (r) fprintf(stderr, "%s\n", err);
    return r;
}

static void one_point(int exact)
{
    const int K = 17;
    double xy[2] = {0.3141592653589793, 0.7182818284590452}, P[35 * 35];
    double worst = 0;
    CHECK(spectrum(exact, xy, 1, K, P) == 0, "one point: spectrum failed");
    for (int t = 0; t < 35 * 35; t++) worst = fmax(worst, fabs(P[t] - 1));
    CHECK(worst < 1e-9, "one point (%s): max |P - 1| = %g", exact ? "exact" : "nufft", worst);
}

static void two_points(int exact)
{
    const int K = 25;
    double xy[4] = {0.1, 0.2, 0.7316, 0.0423}, worst = 0;
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    CHECK(spectrum(exact, xy, 2, K, P) == 0, "two points: spectrum failed");
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            double want = 1 + cos(2 * M_PI * (kx * (xy[0] - xy[2]) + ky * (xy[1] - xy[3])));
            worst = fmax(worst, fabs(P[an_pidx(K, kx, ky)] - want));
        }
    CHECK(worst < 1e-9, "two points (%s): max deviation %g", exact ? "exact" : "nufft", worst);
    free(P);
}

static void lattice(int exact, int m, int K)
{
    const double n = (double)m * m;
    double *xy = ts_lattice(m, 0.37, 0.81);
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    CHECK(spectrum(exact, xy, (size_t)m * m, K, P) == 0, "lattice: spectrum failed");
    double on = 0, off = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            double p = P[an_pidx(K, kx, ky)];
            if (kx % m == 0 && ky % m == 0) on = fmax(on, fabs(p - n) / n);
            else off = fmax(off, p / n);
        }
    CHECK(on < 1e-9 && off < 1e-9, "lattice %dx%d (%s): on reciprocal lattice %g, off %g", m, m,
          exact ? "exact" : "nufft", on, off);
    free(xy);
    free(P);
}

/* Ten uniform sets: every ring's averaged RAPS within 5 standard errors of
 * 1 (each P(k) is about exponential with mean 1), the grand mean within 2%. */
static void uniform_rings(void)
{
    const int K = 48, sets = 10;
    const size_t n = 1000, N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P), *avg = calloc(N, sizeof *avg);
    for (int s = 0; s < sets; s++) {
        double *xy = ts_uniform(n, 1000 + s);
        spectrum(0, xy, n, K, P);
        for (size_t t = 0; t < N; t++) avg[t] += P[t] / sets;
        free(xy);
    }
    an_rings r;
    CHECK(an_rings_compute(avg, K, &r) == 0, "rings failed");
    double sum = 0, cnt = 0;
    int bad = 0;
    for (int i = 1; i <= K; i++) {
        double se = 1 / sqrt((double)r.count[i] / 2 * sets); /* P(k) = P(-k): half independent */
        if (fabs(r.mean[i] - 1) > 5 * se) {
            bad++;
            fprintf(stderr, "ring %d: RAPS %g (count %lld)\n", i, r.mean[i], (long long)r.count[i]);
        }
        sum += r.sum[i];
        cnt += (double)r.count[i];
    }
    CHECK(bad == 0, "uniform sets: %d rings off 1 by more than 5 standard errors", bad);
    CHECK(fabs(sum / cnt - 1) < 0.02, "uniform sets: grand mean %g", sum / cnt);
    an_rings_free(&r);
    free(P);
    free(avg);
}

int main(void)
{
    for (int exact = 0; exact < 2; exact++) {
        one_point(exact);
        two_points(exact);
        lattice(exact, 8, 20);
        lattice(exact, 16, 40);
    }
    uniform_rings();
    return test_report(passed_, failed_);
}
