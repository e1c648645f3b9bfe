/* dens_start.c - layer 2: the start under a density (dens_start.h). */
#include "dens_start.h"

#include <stdlib.h>

#include "hilbert.h"
#include "rng.h"

typedef struct { uint64_t key, pix; } keyed;

static int by_key(const void *a, const void *b)
{
    const keyed *p = a, *q = b;
    return p->key < q->key ? -1 : p->key > q->key;
}

int cfpo_dens_start(const cfpo_density *d, int64_t n, uint64_t seed, double *xy)
{
    const int64_t np = d->w * d->h;
    uint64_t s = 1;
    while ((int64_t)s < d->w || (int64_t)s < d->h) s *= 2;
    keyed *k = malloc((size_t)np * sizeof *k);
    if (!k) return -1;
    int64_t m = 0;
    for (int64_t j = 0; j < d->h; j++)
        for (int64_t i = 0; i < d->w; i++)
            if (d->rho[j * d->w + i] > 0) k[m++] = (keyed){cfpo_hilbert(s, (uint64_t)i, (uint64_t)j), (uint64_t)(j * d->w + i)};
    qsort(k, (size_t)m, sizeof *k, by_key);
    double total = 0;
    for (int64_t t = 0; t < m; t++) total += d->rho[k[t].pix];
    /* walk the curve once: point p at mass (p + u_p) total / n */
    double acc = 0;
    int64_t t = 0;
    for (int64_t p = 0; p < n; p++) {
        const double want = ((double)p + cfpo_rand01(seed, 0xD57A27ull, (uint64_t)p)) * total / (double)n;
        while (t < m - 1 && acc + d->rho[k[t].pix] <= want) acc += d->rho[k[t++].pix];
        const int64_t pix = (int64_t)k[t].pix, i = pix % d->w, j = pix / d->w;
        double x = ((double)i + cfpo_rand01(seed, 0xD57A28ull, (uint64_t)p)) / (double)d->w;
        double y = ((double)j + cfpo_rand01(seed, 0xD57A29ull, (uint64_t)p)) / (double)d->h;
        if (x >= 1) x = 0; /* rounding: stay on the torus */
        if (y >= 1) y = 0;
        /* rounding may leave the pixel: keep the point inside it */
        if (cfpo_density_pixel(d, x, y) != pix) { x = ((double)i + 0.5) / (double)d->w; y = ((double)j + 0.5) / (double)d->h; }
        xy[2 * p] = x;
        xy[2 * p + 1] = y;
    }
    free(k);
    return 0;
}
