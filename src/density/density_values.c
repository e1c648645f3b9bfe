/* density_values.c - layer 2: values turned into a density (density.h):
 * validation (finite, non-negative, not all zero, the contrast limit),
 * normalisation to mean 1, the hash; n against the density. Below
 * density.c and density_analytic.c, which both hand it their values. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "density.h"
#include "geom.h"
#include "greyimg.h"

static uint64_t fnv1a(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

int cfpo_density_from_values(const double *v, int64_t w, int64_t h, const char *what, cfpo_density *d, char *err,
                             size_t errlen)
{
    memset(d, 0, sizeof *d);
    const size_t cnt = (size_t)(w * h);
    if (w <= 0 || h <= 0 || w * h > GREY_MAX_PIXELS) {
        snprintf(err, errlen, "%s: %lld x %lld values (1 to %lld wanted)", what, (long long)w, (long long)h,
                 (long long)GREY_MAX_PIXELS);
        return -1;
    }
    double sum = 0, mn = INFINITY, mx = 0;
    size_t nz = 0;
    for (size_t k = 0; k < cnt; k++) {
        const double x = v[k];
        if (!isfinite(x) || x < 0) {
            snprintf(err, errlen, "%s: value %g at row %zu, column %zu: a density is finite and non-negative", what, x,
                     k / (size_t)w, k % (size_t)w);
            return -1;
        }
        if (x > 0) {
            nz++;
            sum += x;
            if (x < mn) mn = x;
            if (x > mx) mx = x;
        }
    }
    if (nz == 0) { snprintf(err, errlen, "%s: the density is zero everywhere", what); return -1; }
    if (mx / mn > DENSITY_CONTRAST_MAX) {
        snprintf(err, errlen, "%s: contrast 1:%.4g (largest over smallest non-zero value) is beyond the limit 1:%g",
                 what, mx / mn, DENSITY_CONTRAST_MAX);
        return -1;
    }
    d->rho = malloc(cnt * sizeof *d->rho);
    if (!d->rho) { snprintf(err, errlen, "%s: out of memory", what); return -1; }
    const double scale = (double)cnt / sum;
    d->rho_min = INFINITY;
    for (size_t k = 0; k < cnt; k++) {
        d->rho[k] = v[k] * scale;
        if (d->rho[k] > 0 && d->rho[k] < d->rho_min) d->rho_min = d->rho[k];
        if (d->rho[k] > d->rho_max) d->rho_max = d->rho[k];
    }
    d->w = w;
    d->h = h;
    d->support = (double)nz / (double)cnt;
    uint64_t hh = 14695981039346656037ull, dims[2] = {(uint64_t)w, (uint64_t)h};
    hh = fnv1a(hh, dims, sizeof dims);
    d->hash = fnv1a(hh, d->rho, cnt * sizeof *d->rho);
    return 0;
}

void cfpo_density_free(cfpo_density *d)
{
    free(d->rho);
    d->rho = NULL;
}

int cfpo_density_check_n(const cfpo_density *d, int64_t n, char *err, size_t errlen)
{
    const double r = cfpo_delta_bound((double)n) / sqrt(d->rho_min);
    if (n < 2 || r > 0.25) {
        /* r <= 1/4  <=>  n >= 2 / (sqrt(3) (1/4)^2 rho_min) */
        const double need = ceil(2.0 / (sqrt(3.0) * 0.0625 * d->rho_min));
        snprintf(err, errlen, "n=%lld is too small for this density: its sparsest pixels want a spacing of %.3g "
                 "(over 1/4 of the torus); n must be at least %.0f", (long long)n, r, need < 2 ? 2 : need);
        return -1;
    }
    return 0;
}
