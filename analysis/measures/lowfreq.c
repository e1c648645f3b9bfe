/* lowfreq.c - see lowfreq.h. */
#include "lowfreq.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "geom.h"
#include "power.h"

/* Least squares y = a + b x over m points: 0, or -1 when degenerate. */
static int line_fit(const double *x, const double *y, int m, double *a, double *b)
{
    if (m < 2) return -1;
    double mx = 0, my = 0;
    for (int i = 0; i < m; i++) { mx += x[i]; my += y[i]; }
    mx /= m;
    my /= m;
    double sxx = 0, sxy = 0;
    for (int i = 0; i < m; i++) { sxx += (x[i] - mx) * (x[i] - mx); sxy += (x[i] - mx) * (y[i] - my); }
    if (!(sxx > 0)) return -1;
    *b = sxy / sxx;
    *a = my - *b * mx;
    return 0;
}

/* The first local maximum of mean[1..K] reaching 1 (scipy.signal.find_peaks
 * with height 1: interior samples only, a flat top counted at its middle). */
static int first_peak(const double *mean, int K)
{
    for (int i = 2; i < K; i++) {
        if (!(mean[i] > mean[i - 1])) continue;
        int j = i;
        while (j < K && mean[j + 1] == mean[i]) j++;
        if (j < K && mean[j + 1] < mean[i] && mean[i] >= 1) return (i + j) / 2;
        i = j;
    }
    return 0;
}

int an_lowfreq_compute(const double *P, int K, size_t n, const an_rings *r, an_lowfreq *out)
{
    const double R = 0.2 * sqrt((double)n);
    out->range = R;
    out->p0 = out->h = out->s0 = out->alpha = NAN;
    out->peak = 1;
    out->peak_ring = 0;
    out->p0_count = 0;
    out->rings = 0;

    /* |k| <= 0.2 sqrt(n) exactly: 25 |k|^2 <= n */
    int kr = (int)floor(R) + 1;
    while (kr > 0 && 25 * (int64_t)kr * kr > (int64_t)n) kr--;
    if (kr < 1 || kr > K) return 0; /* nothing in range, or the box cuts it */
    {
        double s = 0;
        long long c = 0;
        for (int ky = -kr; ky <= kr; ky++)
            for (int kx = -kr; kx <= kr; kx++) {
                if (cfpo_in_lowk_band(kx, ky, (int64_t)n)) { s += P[an_pidx(K, kx, ky)]; c++; }
            }
        out->p0 = s / (double)c;
        out->p0_count = c;
    }

    /* rings 1..floor(R), complete inside the box since floor(R) <= K */
    const int m = kr;
    double *x = malloc((size_t)(m + 1) * sizeof *x), *y = malloc((size_t)(m + 1) * sizeof *y);
    double *lx = malloc((size_t)(m + 1) * sizeof *lx), *ly = malloc((size_t)(m + 1) * sizeof *ly);
    long long *cnt = calloc((size_t)(m + 1), sizeof *cnt);
    if (!x || !y || !lx || !ly || !cnt) {
        free(x); free(y); free(lx); free(ly); free(cnt);
        return -1;
    }
    for (int i = 0; i <= m; i++) x[i] = 0;
    for (int ky = -m - 1; ky <= m + 1; ky++)
        for (int kx = -m - 1; kx <= m + 1; kx++) {
            const int64_t q = (int64_t)kx * kx + (int64_t)ky * ky;
            if (q == 0) continue;
            const int i = an_ring_of(q);
            if (i > m) continue;
            x[i] += sqrt((double)q);
            cnt[i]++;
        }
    int nl = 0;
    for (int i = 1; i <= m; i++) {
        x[i - 1] = x[i] / (double)cnt[i];
        y[i - 1] = r->mean[i];
        if (y[i - 1] > 0) { lx[nl] = log(x[i - 1]); ly[nl] = log(y[i - 1]); nl++; }
    }
    double a, b;
    if (m >= 2 && line_fit(x, y, m, &a, &b) == 0) {
        out->rings = m;
        out->s0 = a;
        out->peak_ring = first_peak(r->mean, r->K);
        if (out->peak_ring) out->peak = r->mean[out->peak_ring];
        out->h = a / out->peak;
    }
    if (m >= 2 && line_fit(lx, ly, nl, &a, &b) == 0) out->alpha = b;
    free(x); free(y); free(lx); free(ly); free(cnt);
    return 0;
}
