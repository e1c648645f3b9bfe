/* dens_draw.c - see dens_draw.h. */
#include "dens_draw.h"

#include <stdlib.h>

#include "rng.h"

int dens_draw_init(dens_draw *s, const cfpo_density *d)
{
    const int64_t np = d->w * d->h;
    s->d = d;
    s->cum = malloc(((size_t)np + 1) * sizeof *s->cum);
    if (!s->cum) return -1;
    s->cum[0] = 0;
    for (int64_t p = 0; p < np; p++) s->cum[p + 1] = s->cum[p] + d->rho[p];
    return 0;
}

void dens_draw_free(dens_draw *s)
{
    free(s->cum);
    s->cum = NULL;
}

void dens_draw_point(const dens_draw *s, const double u[6], double *x, double *y)
{
    const cfpo_density *d = s->d;
    if (u[2] * d->rho_max < cfpo_density_at(d, u[0], u[1])) {
        *x = u[0];
        *y = u[1];
        return;
    }
    /* the first pixel whose cumulative mass exceeds u3 times the total:
     * a pixel of zero mass has an empty interval and is never chosen */
    const int64_t np = d->w * d->h;
    const double t = u[3] * s->cum[np];
    int64_t lo = 0, hi = np - 1;
    while (lo < hi) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (s->cum[mid + 1] > t) hi = mid;
        else lo = mid + 1;
    }
    while (lo > 0 && !(d->rho[lo] > 0)) lo--; /* t rounded up to the total: the last pixel with mass */
    const int64_t i = lo % d->w, j = lo / d->w;
    double px = ((double)i + u[4]) / (double)d->w, py = ((double)j + u[5]) / (double)d->h;
    /* rounding may carry (i + u) / w into the next pixel: take the centre */
    if (cfpo_density_pixel(d, px, py) != lo) {
        px = ((double)i + 0.5) / (double)d->w;
        py = ((double)j + 0.5) / (double)d->h;
    }
    *x = px;
    *y = py;
}

void dens_draw_at(const dens_draw *s, uint64_t seed, uint64_t stream, uint64_t k, double *x, double *y)
{
    double u[6] = {*x, *y};
    for (int j = 0; j < 4; j++) u[2 + j] = cfpo_rand01(seed, stream, 4 * k + (uint64_t)j);
    dens_draw_point(s, u, x, y);
}
