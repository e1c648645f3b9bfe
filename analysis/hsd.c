/* hsd.c - see hsd.h. C(r) is a step function of |k|^2, so it is evaluated
 * exactly at every integer |k|^2 <= K^2 that is a sum of two squares (the
 * disk of radius K lies inside [-K, K]^2). */
#include "hsd.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "power.h"

static double eff_nyquist(const double *P, int K, size_t n, an_hsd *h, int *oom)
{
    const int64_t R2 = (int64_t)K * K;
    double *sum = calloc((size_t)R2 + 1, sizeof *sum);
    uint32_t *cnt = calloc((size_t)R2 + 1, sizeof *cnt);
    if (!sum || !cnt) { free(sum); free(cnt); *oom = 1; return NAN; }
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            int64_t r2 = (int64_t)kx * kx + (int64_t)ky * ky;
            if (r2 == 0 || r2 > R2) continue;
            sum[r2] += P[an_pidx(K, kx, ky)];
            cnt[r2]++;
        }
    const double start2 = (double)n / 4; /* (sqrt(n)/2)^2 */
    double acc = 0, num = 0;
    int64_t last01 = -1, half = -1;
    for (int64_t r2 = 1; r2 <= R2; r2++) {
        if (!cnt[r2]) continue;
        acc += sum[r2];
        num += cnt[r2];
        double C = acc / num;
        if (C < 0.1) last01 = r2;
        if ((double)r2 >= start2 && C > 0.5) { half = r2; break; }
    }
    free(sum);
    free(cnt);
    h->r_half = half < 0 ? NAN : sqrt((double)half);
    h->r_01 = last01 < 0 ? 0 : sqrt((double)last01);
    if (half < 0) return NAN;
    return h->r_01 / sqrt((double)n);
}

static void oscillation(const an_rings *r, int K, size_t n, an_hsd *h)
{
    int from = 0;
    for (int i = 1; i <= K && !from; i++)
        if (r->mean[i] >= 0.98) from = i;
    h->osc_from = from;
    h->osc_to = 0;
    h->osc_clipped = 0;
    if (!from) { h->oscillation = NAN; return; }
    double limit = from + 5 * sqrt((double)n);
    int to = limit >= K ? K : (int)floor(limit);
    h->osc_clipped = limit > K;
    h->osc_to = to;
    double acc = 0, w = 0;
    for (int i = from; i <= to; i++) {
        double d = r->mean[i] - 1;
        acc += (double)r->count[i] * d * d;
        w += (double)r->count[i];
    }
    h->oscillation = 10 * sqrt(acc / w);
}

int an_hsd_compute(const double *P, int K, size_t n, const an_rings *r, an_hsd *h)
{
    int oom = 0;
    h->eff_nyquist = eff_nyquist(P, K, n, h, &oom);
    if (oom) return -1;
    oscillation(r, K, n, h);
    return 0;
}
