/* test_d3_measures.c - the 3-D measures against brute force: the NUFFT
 * spectrum against the direct sum (random sets; a simple cubic lattice,
 * whose P is n on the reciprocal lattice and 0 elsewhere), P(0) = n and
 * P(-k) = P(k), the shells and P0 against sums written out here, and g(r)
 * against all pairs on both paths (cells, and one cell for a large r);
 * the per-mode spike check against a search written out here, passed by
 * white noise and a jittered set, failed by a jittered lattice and by
 * white noise imprinted with one cosine (the mode named). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "measures3_pcf.h"
#include "measures3_spec.h"
#include "measures3_w6.h"
#include "q6.h"
#include "nn3.h"
#include "rng.h"
#include "solve3.h"
#include "testutil.h"

static int passed_, failed_;

static size_t at(int K, int x, int y, int z)
{
    const size_t S = 2 * (size_t)K + 1;
    return ((size_t)(z + K) * S + (size_t)(y + K)) * S + (size_t)(x + K);
}

static void random_set(double *p, size_t n, uint64_t seed)
{
    for (size_t i = 0; i < 3 * n; i++) p[i] = cfpo_rand01(seed, 0x5350, i);
}

static void check_spectrum(const char *name, const double *p, size_t n, int K)
{
    const size_t S = 2 * (size_t)K + 1, S3 = S * S * S;
    double *A = malloc(S3 * sizeof *A), *B = malloc(S3 * sizeof *B);
    char err[200];
    CHECK(cfpo3_power_exact(p, n, K, A) == 0 && cfpo3_power_nufft(p, n, K, B, err, sizeof err) == 0, "%s: runs", name);
    double worst = 0;
    for (size_t k = 0; k < S3; k++) worst = fmax(worst, fabs(A[k] - B[k]) / fmax(A[k], 1.0));
    CHECK(worst < 1e-6, "%s: NUFFT against the direct sum: %.3g", name, worst);
    CHECK(fabs(A[at(K, 0, 0, 0)] - (double)n) < 1e-9 * (double)n, "%s: P(0) = n", name);
    double asym = 0;
    for (int z = -K; z <= K; z++)
        for (int y = -K; y <= K; y++)
            for (int x = -K; x <= K; x++) asym = fmax(asym, fabs(A[at(K, x, y, z)] - A[at(K, -x, -y, -z)]));
    CHECK(asym < 1e-9 * (double)n, "%s: P(-k) = P(k)", name);
    /* the shells and P0 written out */
    double *sh = malloc(((size_t)K + 1) * sizeof *sh);
    long *cnt = malloc(((size_t)K + 1) * sizeof *cnt);
    cfpo3_power_shells(A, K, sh, cnt);
    int bad = 0;
    for (int s = 1; s <= K; s++) {
        double sum = 0;
        long c = 0;
        for (int z = -K; z <= K; z++)
            for (int y = -K; y <= K; y++)
                for (int x = -K; x <= K; x++) {
                    const double r = sqrt((double)(x * x + y * y + z * z));
                    if (r >= s - 0.5 && r < s + 0.5) sum += A[at(K, x, y, z)], c++;
                }
        bad += c != cnt[s] || fabs(sum / (double)c - sh[s]) > 1e-9 * fmax(1, sh[s]);
    }
    CHECK(bad == 0, "%s: %d shells differ from their sums", name, bad);
    long c0;
    const double p0 = cfpo3_power_p0(A, K, n, &c0);
    const double R = 0.2 * cbrt((double)n);
    double sum = 0;
    long c = 0;
    for (int z = -K; z <= K; z++)
        for (int y = -K; y <= K; y++)
            for (int x = -K; x <= K; x++) {
                const double q = x * x + y * y + z * z;
                if (q > 0 && q <= R * R) sum += A[at(K, x, y, z)], c++;
            }
    CHECK(c == c0 && (c == 0 ? isnan(p0) : fabs(p0 - sum / (double)c) < 1e-9 * fmax(1, p0)), "%s: P0", name);
    free(A), free(B), free(sh), free(cnt);
}

static void check_pcf(const char *name, const double *p, size_t n, double rmax)
{
    const double dr = 0.05;
    const int bins = (int)lround(rmax / dr);
    double *g = malloc((size_t)bins * sizeof *g), *h = calloc((size_t)bins, sizeof *h);
    CHECK(cfpo3_pcf(p, n, rmax, dr, g, bins) == 0, "%s: pcf runs", name);
    const double D = cfpo3_delta_bound((double)n);
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            const double dx = cfpo3_pdiff(p[3 * i], p[3 * j]), dy = cfpo3_pdiff(p[3 * i + 1], p[3 * j + 1]),
                         dz = cfpo3_pdiff(p[3 * i + 2], p[3 * j + 2]);
            const double r = sqrt(dx * dx + dy * dy + dz * dz) / D;
            const long b = (long)(r / dr);
            if (r < rmax && b < bins) h[b] += 1;
        }
    int bad = 0;
    for (int b = 0; b < bins; b++) {
        const double lo = b * dr * D, hi = (b + 1) * dr * D;
        const double want = h[b] / ((double)n * (double)(n - 1) / 2 * 4.0 / 3.0 * M_PI * (hi * hi * hi - lo * lo * lo));
        bad += fabs(want - g[b]) > 1e-12 * fmax(1, want);
    }
    CHECK(bad == 0, "%s: %d bins of g(r) differ from all pairs", name, bad);
    free(g), free(h);
}

/* a lattice of side^3 conventional cells: kind 0 FCC, 1 BCC, 2 SC */
/* The spike check of p (the NUFFT, K) against a plain search over the
 * half space; returns the check's answer. */
static cfpo3_spike spike_of(const char *name, const double *p, size_t n, int K)
{
    const size_t S = 2 * (size_t)K + 1;
    double *P = malloc(S * S * S * sizeof *P), *sh = malloc(((size_t)K + 1) * sizeof *sh);
    long *cnt = malloc(((size_t)K + 1) * sizeof *cnt);
    char err[200];
    cfpo3_spike r;
    CHECK(cfpo3_power_nufft(p, n, K, P, err, sizeof err) == 0, "%s: spectrum", name);
    cfpo3_power_shells(P, K, sh, cnt);
    cfpo3_power_spike(P, K, sh, cnt, &r);
    double best = -1;
    int bk[3] = {0, 0, 0};
    for (int z = -K; z <= K; z++)
        for (int y = -K; y <= K; y++)
            for (int x = -K; x <= K; x++) {
                const int half = z > 0 || (z == 0 && (y > 0 || (y == 0 && x > 0)));
                const double q2 = (double)(x * x + y * y + z * z);
                const long sh_i = lround(sqrt(q2));
                if (!half || sh_i < 1 || sh_i > K || cnt[sh_i] < CFPO3_SPIKE_MIN_COUNT) continue;
                const double q = P[at(K, x, y, z)] / sh[sh_i];
                if (q > best) best = q, bk[0] = x, bk[1] = y, bk[2] = z;
            }
    CHECK(fabs(r.ratio - best) < 1e-12 * best && r.kx == bk[0] && r.ky == bk[1] && r.kz == bk[2],
          "%s: spike %.6g at (%d %d %d), the search %.6g at (%d %d %d)", name, r.ratio, r.kx, r.ky, r.kz, best, bk[0],
          bk[1], bk[2]);
    CHECK(fabs(r.noise - (log(pow(2.0 * K + 1, 3) / 2) + 4)) < 1e-12 && r.pass == (r.ratio <= r.noise),
          "%s: the noise level", name);
    free(P), free(sh), free(cnt);
    return r;
}

static void check_spikes(void)
{
    const size_t n = 4096;
    const int K = 24, h = 16;
    double *p = malloc(3 * n * sizeof *p);
    random_set(p, n, 11);
    cfpo3_spike r = spike_of("white", p, n, K);
    CHECK(r.pass && r.ratio > 5, "white noise: spike %.3g against the level %.3g", r.ratio, r.noise);
    /* jittered: one uniform point in each cell of the 16^3 grid */
    for (size_t i = 0; i < n; i++) {
        const size_t c[3] = {i % h, i / h % h, i / (h * h)};
        for (int a = 0; a < 3; a++) p[3 * i + a] = ((double)c[a] + cfpo_rand01(12, 0x4a49, 3 * i + a)) / h;
    }
    r = spike_of("jittered", p, n, K);
    CHECK(r.pass, "jittered: spike %.3g against the level %.3g", r.ratio, r.noise);
    /* the same grid's centres moved by at most 0.2 of a cell: the lattice */
    for (size_t i = 0; i < n; i++) {
        const size_t c[3] = {i % h, i / h % h, i / (h * h)};
        for (int a = 0; a < 3; a++)
            p[3 * i + a] = ((double)c[a] + 0.5 + 0.2 * (cfpo_rand01(13, 0x4a49, 3 * i + a) - 0.5)) / h;
    }
    r = spike_of("lattice", p, n, K);
    CHECK(!r.pass && r.shell == h && abs(r.kx) + abs(r.ky) + abs(r.kz) == h,
          "lattice: spike %.3g at (%d %d %d), level %.3g", r.ratio, r.kx, r.ky, r.kz, r.noise);
    /* white noise of density 1 + 0.3 cos(2 pi k0.x), k0 = (3, -5, 7), by
     * rejection */
    const int k0[3] = {3, -5, 7};
    uint64_t draw = 0;
    for (size_t i = 0; i < n;) {
        double x[3];
        for (int a = 0; a < 3; a++) x[a] = cfpo_rand01(14, 0x494d, draw++);
        const double dens = 1 + 0.3 * cos(2 * M_PI * (k0[0] * x[0] + k0[1] * x[1] + k0[2] * x[2]));
        if (1.3 * cfpo_rand01(14, 0x494e, draw++) > dens) continue;
        for (int a = 0; a < 3; a++) p[3 * i + a] = x[a];
        i++;
    }
    r = spike_of("imprinted", p, n, K);
    CHECK(!r.pass && r.kx == k0[0] && r.ky == k0[1] && r.kz == k0[2],
          "imprinted: spike %.3g at (%d %d %d), level %.3g", r.ratio, r.kx, r.ky, r.kz, r.noise);
    free(p);
}

static size_t lattice(double *p, int kind, int side)
{
    static const double fcc[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    static const double bcc[2][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}};
    const int nb = kind == 0 ? 4 : kind == 1 ? 2 : 1;
    size_t n = 0;
    for (int z = 0; z < side; z++)
        for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++)
                for (int b = 0; b < nb; b++) {
                    const double *o = kind == 0 ? fcc[b] : kind == 1 ? bcc[b] : fcc[0];
                    p[3 * n] = (x + o[0]) / side, p[3 * n + 1] = (y + o[1]) / side, p[3 * n + 2] = (z + o[2]) / side;
                    n++;
                }
    return n;
}

static void check_w6(const char *name, double *p, int kind, int side, int k, double q6, double w6)
{
    const size_t n = lattice(p, kind, side);
    cfpo3_w6_result r;
    cfpo3_q6_result q;
    CHECK(cfpo3_w6(p, n, k, &r) == 0 && cfpo3_q6(p, n, k, 0.7, 8, &q) == 0, "%s: runs", name);
    CHECK(fabs(r.q6 - q6) < 5e-4 && fabs(r.q6 - q.q6_global) < 1e-9, "%s: Q6 %.6f (q6.h %.6f), want %.4f", name, r.q6,
          q.q6_global, q6);
    CHECK(fabs(r.w6 - w6) < 2e-5 && fabs(r.w6_local - w6) < 2e-5, "%s: W6 %.6f, local %.6f, want %.6f", name, r.w6,
          r.w6_local, w6);
}

int main(void)
{
    double *p = malloc(3 * 5000 * sizeof *p);
    random_set(p, 200, 1);
    check_spectrum("white 200, K 9", p, 200, 9);
    random_set(p, 1000, 2);
    check_spectrum("white 1000, K 12", p, 1000, 12);
    /* simple cubic 5^3: P = n where 5 divides every component, else 0 */
    size_t n = 0;
    for (int z = 0; z < 5; z++)
        for (int y = 0; y < 5; y++)
            for (int x = 0; x < 5; x++) p[3 * n] = x / 5.0, p[3 * n + 1] = y / 5.0, p[3 * n + 2] = z / 5.0, n++;
    check_spectrum("simple cubic 125", p, n, 10);
    {
        const int K = 10;
        const size_t S = 21;
        double *P = malloc(S * S * S * sizeof *P);
        char err[200];
        CHECK(cfpo3_power_nufft(p, n, K, P, err, sizeof err) == 0, "lattice nufft");
        double worst = 0;
        for (int z = -K; z <= K; z++)
            for (int y = -K; y <= K; y++)
                for (int x = -K; x <= K; x++) {
                    const double want = (x % 5 == 0 && y % 5 == 0 && z % 5 == 0) ? 125.0 : 0.0;
                    worst = fmax(worst, fabs(P[at(K, x, y, z)] - want));
                }
        CHECK(worst < 1e-5, "simple cubic: the reciprocal lattice only (off by %.3g)", worst);
        free(P);
    }
    random_set(p, 300, 3);
    check_pcf("white 300, r < 2.5 (one cell)", p, 300, 2.5);
    random_set(p, 5000, 4);
    check_pcf("white 5000, r < 3 (cells)", p, 5000, 3.0);
    /* g of white noise is about 1: bins of 0.05 Delta3 beyond 0.5 hold
     * hundreds of pairs */
    {
        double g[60];
        cfpo3_pcf(p, 5000, 3.0, 0.05, g, 60);
        double m = 0;
        for (int b = 20; b < 60; b++) m += g[b] / 40;
        CHECK(fabs(m - 1) < 0.03, "white 5000: mean g over [1, 3) is %.4f, not about 1", m);
    }
    CHECK(cfpo3_pcf(p, 10, 3.0, 0.05, (double[60]){0}, 60) == -1, "g(r) refuses r past half the box");
    /* W6 of the cubic lattices (Steinhardt, Nelson and Ronchetti 1983) and
     * the 3j symbols' orthogonality: sum over m1, m2 of (6 6 6; m1 m2 m3)^2
     * = 1/13 for each m3 */
    check_w6("FCC", p, 0, 5, 12, 0.5745, -0.013161);
    check_w6("BCC", p, 1, 6, 14, 0.5107, 0.013161);
    check_w6("SC", p, 2, 8, 6, 0.3536, 0.013161);
    double orth = 0;
    for (int m3 = -6; m3 <= 6; m3++) {
        double s = 0;
        for (int m1 = -6; m1 <= 6; m1++) {
            const double w = cfpo3_wigner666(m1, -m1 - m3, m3);
            s += w * w;
        }
        orth = fmax(orth, fabs(s - 1.0 / 13));
    }
    CHECK(orth < 1e-12, "3j orthogonality off by %.3g", orth);
    check_spikes();
    free(p);
    return test_report(passed_, failed_);
}
