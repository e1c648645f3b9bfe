/* rings.c - see rings.h. Two passes over the half plane: sums and counts,
 * then squared deviations from the ring means (numerically stable), then
 * the spike. P(-k) = P(k), so the half plane ky > 0 or (ky = 0, kx > 0)
 * counted twice is the whole ring; the variance is the same either way
 * but psa's unbiased (count - 1) uses the full ring count, as here. */
#include "rings.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "power.h"

int an_ring_of(int64_t r2)
{
    int64_t i = (int64_t)floor(sqrt((double)r2) + 0.5);
    while (i * (i + 1) < r2) i++;
    while (i > 0 && i * (i - 1) >= r2) i--;
    return (int)i;
}

static int in_half(int kx, int ky) { return ky > 0 || (ky == 0 && kx > 0); }

void an_rings_free(an_rings *r)
{
    free(r->count);
    free(r->sum);
    free(r->mean);
    free(r->aniso_db);
    memset(r, 0, sizeof *r);
}

static void sums(const double *P, int K, an_rings *r)
{
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (!in_half(kx, ky)) continue;
            int i = an_ring_of((int64_t)kx * kx + (int64_t)ky * ky);
            if (i > K) continue;
            r->count[i] += 2;
            r->sum[i] += 2 * P[an_pidx(K, kx, ky)];
        }
    for (int i = 1; i <= K; i++) r->mean[i] = r->count[i] ? r->sum[i] / (double)r->count[i] : 0;
}

static void anisotropy(const double *P, int K, an_rings *r, double *dev)
{
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (!in_half(kx, ky)) continue;
            int i = an_ring_of((int64_t)kx * kx + (int64_t)ky * ky);
            if (i > K) continue;
            double d = P[an_pidx(K, kx, ky)] - r->mean[i];
            dev[i] += 2 * d * d;
        }
    for (int i = 1; i <= K; i++) {
        double m = r->mean[i];
        if (r->count[i] < 2 || !(m > 0)) { r->aniso_db[i] = NAN; continue; }
        double var = dev[i] / (double)(r->count[i] - 1);
        r->aniso_db[i] = 10 * log10(var / (m * m));
    }
}

static void spike(const double *P, int K, an_rings *r)
{
    r->spike_ratio = NAN;
    r->spike_P = r->spike_mean = NAN;
    r->spike_ring = 0;
    double best = -1;
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (!in_half(kx, ky)) continue;
            int i = an_ring_of((int64_t)kx * kx + (int64_t)ky * ky);
            if (i > K || r->count[i] < AN_SPIKE_MIN_COUNT || !(r->mean[i] > 0)) continue;
            double q = P[an_pidx(K, kx, ky)] / r->mean[i];
            if (q > best) {
                best = q;
                r->spike_ratio = q;
                r->spike_P = P[an_pidx(K, kx, ky)];
                r->spike_mean = r->mean[i];
                r->spike_kx = kx;
                r->spike_ky = ky;
                r->spike_ring = i;
            }
        }
}

/* The mean of P over the box of half side AN_PATTERN_BOX around k (k
 * itself left out), the frequencies inside [-K, K]^2. */
static double local_mean(const double *P, int K, int kx, int ky)
{
    double s = 0;
    int c = 0;
    for (int dy = -AN_PATTERN_BOX; dy <= AN_PATTERN_BOX; dy++)
        for (int dx = -AN_PATTERN_BOX; dx <= AN_PATTERN_BOX; dx++) {
            const int x = kx + dx, y = ky + dy;
            if ((dx == 0 && dy == 0) || x < -K || x > K || y < -K || y > K) continue;
            s += P[an_pidx(K, x, y)];
            c++;
        }
    return c ? s / c : NAN;
}

double an_pattern_level(double level)
{
    const double m = (2 * AN_PATTERN_BOX + 1) * (2 * AN_PATTERN_BOX + 1) - 1;
    return m * (exp(level / m) - 1);
}

/* The pattern (rings.h): the k of ring ratio above the noise level, in
 * (ky, kx) order, whose P also passes an_pattern_level over its
 * neighbourhood; the largest ring ratio among them. */
static void pattern(const double *P, int K, an_rings *r)
{
    r->pattern_ratio = r->pattern_local = NAN;
    r->pattern_ring = 0;
    if (!(r->spike_ratio > 0)) return;
    const double level = an_spike_noise_level(K), local = an_pattern_level(level);
    if (!(r->spike_ratio > level)) return;
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (!in_half(kx, ky)) continue;
            int i = an_ring_of((int64_t)kx * kx + (int64_t)ky * ky);
            if (i > K || r->count[i] < AN_SPIKE_MIN_COUNT || !(r->mean[i] > 0)) continue;
            const double p = P[an_pidx(K, kx, ky)], q = p / r->mean[i];
            if (!(q > level) || q <= r->pattern_ratio) continue;
            const double l = p / local_mean(P, K, kx, ky);
            if (!(l > local)) continue;
            r->pattern_ratio = q;
            r->pattern_local = l;
            r->pattern_kx = kx;
            r->pattern_ky = ky;
            r->pattern_ring = i;
        }
}

int an_lattice_grid(int64_t asked, size_t n)
{
    if (asked >= 0) return (int)asked;
    cfpo_grid G;
    char err[256];
    return cfpo_grid_init(&G, (int64_t)n, CFPO_VARIANT_ADAPTIVE, 1, err, sizeof err) == 0 ? (int)G.g : 0;
}

double an_spike_noise_level(int K)
{
    const double side = 2.0 * K + 1;
    return log(side * side / 2) + 4;
}

int an_lattice_period(int g) { return g % 3 == 0 ? 3 : (g % 2 == 0 ? 2 : 1); }

int an_lattice_compute(const double *P, const an_rings *r, int g, int period, an_lattice *out)
{
    memset(out, 0, sizeof *out);
    out->g = g;
    out->period = period;
    out->ratio = out->P = out->mean = NAN;
    if (g < 1 || period < 1) return 0;
    for (int j = 1; j <= 2 * period; j++) {
        if ((int64_t)j * g % period) continue;
        const int64_t f = (int64_t)j * g / period;
        const int i = an_ring_of(f * f);
        if (f > r->K || i > r->K || r->count[i] < AN_SPIKE_MIN_COUNT || !(r->mean[i] > 0)) continue;
        for (int axis = 0; axis < 2; axis++) {
            const int kx = axis ? 0 : (int)f, ky = axis ? (int)f : 0; /* in the half plane */
            const double q = P[an_pidx(r->K, kx, ky)] / r->mean[i];
            out->count++;
            if (!(q <= out->ratio)) { /* also the first (NAN) */
                out->ratio = q;
                out->P = P[an_pidx(r->K, kx, ky)];
                out->mean = r->mean[i];
                out->kx = kx;
                out->ky = ky;
            }
        }
    }
    return out->count;
}

int an_rings_compute(const double *P, int K, an_rings *r)
{
    memset(r, 0, sizeof *r);
    r->K = K;
    const size_t m = (size_t)K + 1;
    r->count = calloc(m, sizeof *r->count);
    r->sum = calloc(m, sizeof *r->sum);
    r->mean = calloc(m, sizeof *r->mean);
    r->aniso_db = calloc(m, sizeof *r->aniso_db);
    double *dev = calloc(m, sizeof *dev);
    if (!r->count || !r->sum || !r->mean || !r->aniso_db || !dev) {
        free(dev);
        an_rings_free(r);
        return -1;
    }
    sums(P, K, r);
    anisotropy(P, K, r, dev);
    free(dev);
    spike(P, K, r);
    pattern(P, K, r);
    r->aniso_db[0] = NAN;
    r->peak_ring = 1;
    for (int i = 1; i <= K; i++)
        if (r->mean[i] > r->mean[r->peak_ring]) r->peak_ring = i;
    r->peak_mean = r->mean[r->peak_ring];
    return 0;
}
