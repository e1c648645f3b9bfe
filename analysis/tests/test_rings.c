/* test_rings.c - ring statistics and the HSD measures on spectra whose
 * answers are known: ring membership against its floating definition;
 * RAPS and anisotropy of P(k) = |k|^2 and of a constant; a planted spike is
 * found with its k and ratio, and one at a grid's frequency by the lattice
 * ratio; a step spectrum (0 inside radius a, 1
 * outside) gives a <= 2 nu_eff <= a / sqrt(0.9) (where the disk mean
 * crosses 0.1) and oscillation 0, and a RAPS of 1 + 0.1 sin gives
 * oscillation about 10 * 0.1 / sqrt(2); the RAPS of averaged spectra is
 * the mean of their RAPS. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hsd.h"
#include "power.h"
#include "rings.h"
#include "testsets.h"
#include "testutil.h"

static int passed_, failed_;

static void ring_membership(void)
{
    int bad = 0;
    for (int64_t r2 = 0; r2 <= 2000000; r2++) {
        int i = an_ring_of(r2);
        double r = sqrt((double)r2);
        if (!(i - 0.5 <= r && r < i + 0.5)) bad++;
    }
    CHECK(bad == 0, "%d values of |k|^2 in the wrong ring", bad);
}

static double *make(int K, double (*f)(int, int))
{
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) P[an_pidx(K, kx, ky)] = f(kx, ky);
    return P;
}

static double radius2(int kx, int ky) { return (double)kx * kx + (double)ky * ky; }
static double constant(int kx, int ky) { (void)kx; (void)ky; return 2.5; }

static void raps_and_anisotropy(void)
{
    const int K = 30;
    double *P = make(K, radius2);
    an_rings r;
    an_rings_compute(P, K, &r);
    int bad = 0;
    for (int i = 1; i <= K; i++) {
        double s = 0, s2 = 0;
        long c = 0;
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                double rr = sqrt(radius2(kx, ky));
                if (!(i - 0.5 <= rr && rr < i + 0.5)) continue;
                s += radius2(kx, ky);
                c++;
            }
        double m = s / c;
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                double rr = sqrt(radius2(kx, ky));
                if (i - 0.5 <= rr && rr < i + 0.5) s2 += (radius2(kx, ky) - m) * (radius2(kx, ky) - m);
            }
        double db = 10 * log10(s2 / (c - 1) / (m * m));
        if (r.count[i] != c || fabs(r.mean[i] - m) > 1e-9 * m || fabs(r.aniso_db[i] - db) > 1e-9) bad++;
    }
    CHECK(bad == 0, "%d rings with a wrong count, mean or anisotropy", bad);
    CHECK(r.peak_ring == K, "peak ring %d", r.peak_ring);
    an_rings_free(&r);
    free(P);
    P = make(K, constant);
    an_rings_compute(P, K, &r);
    CHECK(r.mean[7] == 2.5 && isinf(r.aniso_db[7]) && r.aniso_db[7] < 0,
          "constant spectrum: mean %g anisotropy %g", r.mean[7], r.aniso_db[7]);
    an_rings_free(&r);
    free(P);
}

static double flat(int kx, int ky) { (void)kx; (void)ky; return 1.0; }

static void spike(void)
{
    const int K = 64, g = 27;
    double *P = make(K, flat);
    P[an_pidx(K, g, 0)] = P[an_pidx(K, -g, 0)] = 300;
    an_rings r;
    an_rings_compute(P, K, &r);
    double mean = (r.count[g] - 2 + 600.0) / r.count[g];
    CHECK(r.spike_kx == g && r.spike_ky == 0 && r.spike_ring == g, "spike at (%d,%d)", r.spike_kx, r.spike_ky);
    CHECK(fabs(r.spike_ratio - 300 / mean) < 1e-9, "spike ratio %g, want %g", r.spike_ratio, 300 / mean);
    CHECK(r.spike_ratio > 50 && r.aniso_db[g] > r.aniso_db[g - 1], "spike %g", r.spike_ratio);
    an_rings_free(&r);
    free(P);
}

/* The lattice ratio looks at the axis frequencies j g / p only: a spike
 * there (a colour frequency, 2g/3, on the ky axis) is found with its
 * ratio; a larger spike off those frequencies is not; the frequencies
 * counted are those within K; g 0 gives none. */
static void lattice(void)
{
    const int K = 64, g = 30;
    double *P = make(K, flat);
    P[an_pidx(K, 0, 20)] = P[an_pidx(K, 0, -20)] = 9;  /* (0, 2g/3) */
    P[an_pidx(K, 17, 5)] = P[an_pidx(K, -17, -5)] = 50; /* no lattice frequency */
    an_rings r;
    an_rings_compute(P, K, &r);
    an_lattice L;
    const int cnt = an_lattice_compute(P, &r, g, 3, &L);
    const double mean = (r.count[20] - 2 + 18.0) / r.count[20];
    /* j g / 3 = 10, 20, 30, 40, 50, 60 on both axes, all within K = 64 */
    CHECK(cnt == 12 && L.count == 12, "lattice: %d frequencies, want 12", cnt);
    CHECK(L.kx == 0 && L.ky == 20 && fabs(L.ratio - 9 / mean) < 1e-9, "lattice: %g at (%d,%d), want %g at (0,20)",
          L.ratio, L.kx, L.ky, 9 / mean);
    CHECK(r.spike_kx == 17 && r.spike_ky == 5, "spike at (%d,%d), want (17,5)", r.spike_kx, r.spike_ky);
    CHECK(an_lattice_compute(P, &r, 44, 2, &L) == 4 && fabs(L.ratio - 1) < 1e-12,
          "g 44, period 2: %d frequencies (22 and 44 on both axes; 66 > K), ratio %g", L.count, L.ratio);
    CHECK(an_lattice_compute(P, &r, 0, 3, &L) == 0 && isnan(L.ratio), "g 0: %d frequencies", L.count);
    an_rings_free(&r);
    free(P);
}

static double step_a;
static double step(int kx, int ky) { return radius2(kx, ky) < step_a * step_a ? 0 : 1; }
static double wavy(int kx, int ky)
{
    double r = sqrt(radius2(kx, ky));
    return r < 10 ? 0 : 1 + 0.1 * sin(r);
}

static void hsd_measures(void)
{
    const int K = 200;
    const size_t n = 4096; /* sqrt(n)/2 = 32 */
    step_a = 50;
    double *P = make(K, step);
    an_rings r;
    an_hsd h;
    an_rings_compute(P, K, &r);
    an_hsd_compute(P, K, n, &r, &h);
    CHECK(h.r_01 >= step_a - 1 && h.r_01 <= step_a / sqrt(0.9), "step: r_01 = %g", h.r_01);
    CHECK(fabs(h.eff_nyquist - h.r_01 / 64) < 1e-12, "step: nu_eff %g", h.eff_nyquist);
    CHECK(h.oscillation < 1e-9 && h.osc_from == 51, "step: oscillation %g from ring %d", h.oscillation, h.osc_from);
    an_rings_free(&r);
    free(P);
    P = make(K, wavy);
    an_rings_compute(P, K, &r);
    an_hsd_compute(P, K, 64, &r, &h); /* 5 sqrt(n) = 40 rings */
    CHECK(fabs(h.oscillation - 10 * 0.1 / sqrt(2)) < 0.08, "wavy: oscillation %g", h.oscillation);
    CHECK(h.osc_to - h.osc_from == 40 && !h.osc_clipped, "wavy: rings %d..%d", h.osc_from, h.osc_to);
    an_rings_free(&r);
    free(P);
}

static void averaging_is_linear(void)
{
    char err[256];
    const int K = 24, sets = 3;
    const size_t n = 300, N = an_side(K) * an_side(K);
    double *avg = calloc(N, sizeof *avg), *P = malloc(N * sizeof *P), mean_of_raps[25] = {0};
    for (int s = 0; s < sets; s++) {
        double *xy = ts_uniform(n, 40 + s);
        an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err);
        an_rings r;
        an_rings_compute(P, K, &r);
        for (int i = 1; i <= K; i++) mean_of_raps[i] += r.mean[i] / sets;
        for (size_t t = 0; t < N; t++) avg[t] += P[t] / sets;
        an_rings_free(&r);
        free(xy);
    }
    an_rings r;
    an_rings_compute(avg, K, &r);
    double worst = 0;
    for (int i = 1; i <= K; i++) worst = fmax(worst, fabs(r.mean[i] - mean_of_raps[i]));
    CHECK(worst < 1e-12, "RAPS of the average differs from the average RAPS by %g", worst);
    an_rings_free(&r);
    free(avg);
    free(P);
}

int main(void)
{
    ring_membership();
    raps_and_anisotropy();
    spike();
    lattice();
    hsd_measures();
    averaging_is_linear();
    return test_report(passed_, failed_);
}
