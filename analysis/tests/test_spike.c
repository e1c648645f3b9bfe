/* test_spike.c - the spike ratio (the largest P(k) over its ring's mean,
 * rings of at least AN_SPIKE_MIN_COUNT frequencies) on sets whose answer is
 * known: white noise stays in the band of the largest of many exponential
 * values; a square lattice with a little jitter gives a ratio far above it,
 * at a vector of its reciprocal lattice; the value and its k equal a brute
 * force computation of P(k), the rings and the maximum from their
 * definitions; a spike planted on a ring too small to count is ignored, the
 * same spike on the first ring that counts is found. The lattice ratio
 * (P at a grid's axis frequencies over the ring's mean) finds the lattice
 * when given its size and stays in the noise's band otherwise. The
 * pattern (the imprint line's test: above the ring's mean and above the
 * neighbourhood's) is none for white noise and is the lattice's vector
 * for the lattice; on a spectrum that steps within a ring (P 120x higher
 * beyond a radius, the edge of a band) the spike ratio passes the noise
 * level but no pattern is found, and a peak planted outside the band is. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "power.h"
#include "rings.h"
#include "testsets.h"
#include "testutil.h"

static int passed_, failed_;

static int spike_of(const double *xy, size_t n, int K, an_rings *r)
{
    char err[256];
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    if (!P || an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) != 0 || an_rings_compute(P, K, r) != 0) {
        fprintf(stderr, "spectrum failed\n");
        exit(1);
    }
    free(P);
    return 0;
}

/* The lattice ratio of the set for a grid of g cells, period p. */
static an_lattice lattice_of(const double *xy, size_t n, int K, int g, int p)
{
    char err[256];
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    an_rings r;
    an_lattice L;
    if (!P || an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) != 0 || an_rings_compute(P, K, &r) != 0) {
        fprintf(stderr, "spectrum failed\n");
        exit(1);
    }
    an_lattice_compute(P, &r, g, p, &L);
    an_rings_free(&r);
    free(P);
    return L;
}

/* White noise, n = 4,096, the default K = 6 sqrt(n) = 384: about 2.3e5
 * independent exponential values over their ring means, whose largest is
 * ln(2.3e5) + 0.58 = 13 give or take 1.3 (Gumbel). */
static void white_noise(void)
{
    const size_t n = 4096;
    const int K = 384;
    double lo = 1e9, hi = 0;
    for (uint64_t seed = 1; seed <= 6; seed++) {
        double *xy = ts_uniform(n, 100 + seed);
        an_rings r;
        spike_of(xy, n, K, &r);
        lo = fmin(lo, r.spike_ratio);
        hi = fmax(hi, r.spike_ratio);
        CHECK(r.spike_ratio >= 5 && r.spike_ratio <= 25, "white noise seed %d: spike ratio %g outside [5, 25]",
              (int)seed, r.spike_ratio);
        CHECK(r.spike_ring >= 3 && r.count[r.spike_ring] >= AN_SPIKE_MIN_COUNT, "white noise: spike on ring %d",
              r.spike_ring);
        CHECK(r.pattern_ring == 0 && isnan(r.pattern_ratio), "white noise seed %d: a pattern %g at (%d, %d)", (int)seed,
              r.pattern_ratio, r.pattern_kx, r.pattern_ky);
        /* 12 exponential values over their ring means: above 12 with
         * probability about 12 e^-12 = 7e-5 */
        const an_lattice L = lattice_of(xy, n, K, 57, 3);
        CHECK(L.count == 12 && L.ratio < 12, "white noise seed %d: lattice ratio %g over %d frequencies", (int)seed,
              L.ratio, L.count);
        an_rings_free(&r);
        free(xy);
    }
    printf("white noise, n = 4096, 6 seeds: spike ratio %.2f .. %.2f\n", lo, hi);
}

/* An m x m lattice, every coordinate moved by up to +-a/2 of the spacing:
 * P at a reciprocal vector (m i, m j) is about n sinc^2(a max(|i|, |j|) ...)
 * while its ring of about 2 pi |k| frequencies averages it with the noise;
 * the ratio is of the order of the ring size over its 4 or 8 lattice
 * vectors, a hundred and more. */
static void jittered_lattice(void)
{
    const int m = 64, K = 384;
    const size_t n = (size_t)m * m;
    for (uint64_t seed = 1; seed <= 3; seed++) {
        double *xy = ts_lattice(m, 0.5, 0.5);
        ts_jitter(xy, n, 0.1 / m, 7 + seed);
        an_rings r;
        spike_of(xy, n, K, &r);
        printf("jittered %d x %d lattice (+-0.05 spacing), K = %d: spike ratio %.1f at (%d, %d)\n", m, m, K,
               r.spike_ratio, r.spike_kx, r.spike_ky);
        CHECK(r.spike_ratio > 150, "lattice: spike ratio %g", r.spike_ratio);
        CHECK(r.pattern_ring > 0 && r.pattern_ratio == r.spike_ratio && r.pattern_kx == r.spike_kx &&
                  r.pattern_ky == r.spike_ky && r.pattern_local > an_pattern_level(an_spike_noise_level(K)),
              "lattice: pattern %g (%g over its neighbours) at (%d, %d), spike at (%d, %d)", r.pattern_ratio,
              r.pattern_local, r.pattern_kx, r.pattern_ky, r.spike_kx, r.spike_ky);
        CHECK(r.spike_kx % m == 0 && r.spike_ky % m == 0 && (r.spike_kx || r.spike_ky),
              "lattice: spike at (%d, %d), not on the reciprocal lattice", r.spike_kx, r.spike_ky);
        /* The lattice ratio for its own grid finds it on an axis; for a
         * grid of another size it sees nothing. */
        const an_lattice L = lattice_of(xy, n, K, m, 1), M = lattice_of(xy, n, K, 57, 3);
        CHECK(L.ratio > 150 && (L.kx == 0 || L.ky == 0) && (L.kx + L.ky) % m == 0,
              "lattice: lattice ratio %g at (%d, %d)", L.ratio, L.kx, L.ky);
        CHECK(M.ratio < 12, "lattice: lattice ratio %g for a grid of 57", M.ratio);
        an_rings_free(&r);
        free(xy);
    }
}

/* P(k) by the direct sum in long double, rings by the floating definition
 * i - 1/2 <= |k| < i + 1/2, and the largest P / ring mean over the half
 * plane ky > 0 or (ky = 0, kx > 0), rings of >= AN_SPIKE_MIN_COUNT. */
static void brute_force(const double *xy, size_t n, int K, double *ratio, int *kx_out, int *ky_out)
{
    const double two_pi = 6.283185307179586476925286766559;
    const size_t side = an_side(K);
    double *P = malloc(side * side * sizeof *P);
    double *sum = calloc((size_t)K + 1, sizeof *sum);
    long *cnt = calloc((size_t)K + 1, sizeof *cnt);
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            long double re = 0, im = 0;
            for (size_t j = 0; j < n; j++) {
                long double ph = (long double)two_pi * ((long double)kx * xy[2 * j] + (long double)ky * xy[2 * j + 1]);
                re += cosl(ph);
                im -= sinl(ph);
            }
            double p = (double)((re * re + im * im) / (long double)n);
            P[(size_t)(ky + K) * side + (size_t)(kx + K)] = p;
            double rad = sqrt((double)kx * kx + (double)ky * ky);
            int i = (int)floor(rad + 0.5);
            if (kx == 0 && ky == 0) continue;
            if (i <= K) { sum[i] += p; cnt[i]++; }
        }
    *ratio = -1;
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (!(ky > 0 || kx > 0)) continue;
            int i = (int)floor(sqrt((double)kx * kx + (double)ky * ky) + 0.5);
            if (i > K || cnt[i] < AN_SPIKE_MIN_COUNT) continue;
            double q = P[(size_t)(ky + K) * side + (size_t)(kx + K)] / (sum[i] / cnt[i]);
            if (q > *ratio) { *ratio = q; *kx_out = kx; *ky_out = ky; }
        }
    free(P);
    free(sum);
    free(cnt);
}

static void against_brute_force(void)
{
    struct { const char *name; size_t n; int K; double *xy; } sets[3];
    sets[0].name = "uniform, n = 300"; sets[0].n = 300; sets[0].K = 30; sets[0].xy = ts_uniform(300, 5);
    sets[1].name = "jittered 16 x 16 lattice"; sets[1].n = 256; sets[1].K = 40;
    sets[1].xy = ts_lattice(16, 0.5, 0.5);
    ts_jitter(sets[1].xy, 256, 0.1 / 16, 3);
    sets[2].name = "uniform, n = 500"; sets[2].n = 500; sets[2].K = 25; sets[2].xy = ts_uniform(500, 9);
    for (int c = 0; c < 3; c++) {
        double want;
        int wkx = 0, wky = 0;
        brute_force(sets[c].xy, sets[c].n, sets[c].K, &want, &wkx, &wky);
        an_rings r;
        spike_of(sets[c].xy, sets[c].n, sets[c].K, &r);
        CHECK(fabs(r.spike_ratio - want) <= 1e-6 * want, "%s: spike ratio %.12g, brute force %.12g", sets[c].name,
              r.spike_ratio, want);
        CHECK(r.spike_kx == wkx && r.spike_ky == wky, "%s: spike at (%d, %d), brute force (%d, %d)", sets[c].name,
              r.spike_kx, r.spike_ky, wkx, wky);
        CHECK(fabs(r.spike_P / r.spike_mean - r.spike_ratio) <= 1e-12 * r.spike_ratio, "%s: P / mean != ratio",
              sets[c].name);
        an_rings_free(&r);
        free(sets[c].xy);
    }
}

/* A flat spectrum with one planted spike: on ring 2 (12 frequencies) it is
 * ignored, on ring 3 (20) it is the answer; with only rings 1 and 2 there
 * is no spike ratio at all. */
static void small_rings(void)
{
    const int K = 20;
    const size_t N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P);
    int where[2][2] = {{2, 1}, {3, 1}}; /* |k|^2 = 5 (ring 2), 10 (ring 3) */
    for (int c = 0; c < 2; c++) {
        for (size_t t = 0; t < N; t++) P[t] = 1;
        int kx = where[c][0], ky = where[c][1];
        P[an_pidx(K, kx, ky)] = P[an_pidx(K, -kx, -ky)] = 50;
        an_rings r;
        an_rings_compute(P, K, &r);
        int ring = an_ring_of((int64_t)kx * kx + ky * ky);
        if (c == 0)
            CHECK(ring == 2 && r.count[2] < AN_SPIKE_MIN_COUNT && r.spike_ring != 2 && fabs(r.spike_ratio - 1) < 1e-12,
                  "spike on ring %d (%lld frequencies) counted: ratio %g on ring %d", ring, (long long)r.count[ring],
                  r.spike_ratio, r.spike_ring);
        else
            CHECK(ring == 3 && r.count[3] >= AN_SPIKE_MIN_COUNT && r.spike_kx == kx && r.spike_ky == ky &&
                      fabs(r.spike_ratio - 50 / ((r.count[3] - 2 + 100.0) / r.count[3])) < 1e-9,
                  "spike on ring 3 missed: ratio %g at (%d, %d)", r.spike_ratio, r.spike_kx, r.spike_ky);
        an_rings_free(&r);
    }
    free(P);
    const int K2 = 2;
    double P2[25];
    for (int t = 0; t < 25; t++) P2[t] = 1;
    P2[an_pidx(K2, 1, 1)] = P2[an_pidx(K2, -1, -1)] = 9;
    an_rings r;
    an_rings_compute(P2, K2, &r);
    CHECK(isnan(r.spike_ratio) && r.spike_ring == 0, "K = 2: spike ratio %g on ring %d, want none", r.spike_ratio,
          r.spike_ring);
    an_rings_free(&r);
}

/* A spectrum that steps within a ring: P = 1e-4 Exp(1) for |k| <= R and
 * 0.012 Exp(1) beyond (the hyperuniform variant's transport band at
 * 262,144 points: R = 102.4, ring 102 a tenth outside; docs/results/
 * 2026-11-29-imprint.md). Its few frequencies beyond R stand 9x above the
 * ring's mean before any noise, so the spike ratio passes the level; none
 * stands above its neighbourhood, half of which is beyond R too. A peak
 * of 60 times the outer level planted at (0, 300) is the pattern. */
static void band_edge(void)
{
    const int K = 384;
    const double R2 = 102.4 * 102.4, level = an_spike_noise_level(K);
    const size_t N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P);
    for (int planted = 0; planted < 2; planted++) {
        uint64_t st = 2026;
        for (int ky = 0; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                if (ky == 0 && kx <= 0) continue;
                const double e = -log(1 - ts_u(&st)), r2 = (double)kx * kx + (double)ky * ky;
                P[an_pidx(K, kx, ky)] = P[an_pidx(K, -kx, -ky)] = (r2 <= R2 ? 1e-4 : 0.012) * e;
            }
        P[an_pidx(K, 0, 0)] = 0;
        if (planted) P[an_pidx(K, 0, 300)] = P[an_pidx(K, 0, -300)] = 60 * 0.012;
        an_rings r;
        if (an_rings_compute(P, K, &r) != 0) exit(1);
        printf("band edge%s: spike ratio %.1f at (%d, %d) (level %.1f), pattern %.1f at (%d, %d)\n",
               planted ? ", a peak at (0, 300)" : "", r.spike_ratio, r.spike_kx, r.spike_ky, level, r.pattern_ratio,
               r.pattern_kx, r.pattern_ky);
        const int edge = an_ring_of((int64_t)r.spike_kx * r.spike_kx + (int64_t)r.spike_ky * r.spike_ky) == 102;
        if (!planted)
            CHECK(r.spike_ratio > level && edge && r.pattern_ring == 0,
                  "band edge: spike %g at (%d, %d), pattern %g at (%d, %d); want a spike above %g on ring 102 and no "
                  "pattern",
                  r.spike_ratio, r.spike_kx, r.spike_ky, r.pattern_ratio, r.pattern_kx, r.pattern_ky, level);
        else
            CHECK(r.pattern_ring > 0 && r.pattern_kx == 0 && r.pattern_ky == 300,
                  "band edge with a peak: pattern %g at (%d, %d), want (0, 300)", r.pattern_ratio, r.pattern_kx,
                  r.pattern_ky);
        an_rings_free(&r);
    }
    free(P);
}

int main(void)
{
    band_edge();
    small_rings();
    against_brute_force();
    white_noise();
    jittered_lattice();
    return test_report(passed_, failed_);
}
