/* dens_start.c - layer 2: the start under a density (dens_start.h). */
#include "dens_start.h"

#include <stdlib.h>

#include "rng.h"

/* The order of a Hilbert walk over the raster (cfpo_hilbert's curve on
 * the enclosing s x s grid, s a power of 2), without sorting: the square
 * of side t at cell (x0, y0) whose curve runs along a first, then b (unit
 * steps, one of them on each axis) is four squares of side t / 2 in the
 * order (0, 0), (0, 1), (1, 1), (1, 0) of (a, b), the first with a and b
 * swapped, the last swapped and reversed, starting at the far corner.
 * Squares that miss the raster are skipped whole; the pixels of positive
 * density are appended to w->pix in curve order. */
typedef struct {
    const cfpo_density *d;
    uint32_t *pix;
    int64_t m;
} walk;

static void walk_square(walk *w, int64_t x0, int64_t y0, int ax, int ay, int bx, int by, int64_t t)
{
    const int64_t xa = x0 + (t - 1) * ((int64_t)ax + bx), ya = y0 + (t - 1) * ((int64_t)ay + by);
    const int64_t xlo = x0 < xa ? x0 : xa, ylo = y0 < ya ? y0 : ya;
    if (xlo >= w->d->w || ylo >= w->d->h || xlo + t <= 0 || ylo + t <= 0) return; /* misses the raster */
    if (t == 1) {
        const int64_t p = y0 * w->d->w + x0;
        if (w->d->rho[p] > 0) w->pix[w->m++] = (uint32_t)p;
        return;
    }
    const int64_t h = t / 2;
    walk_square(w, x0, y0, bx, by, ax, ay, h);
    walk_square(w, x0 + h * bx, y0 + h * by, ax, ay, bx, by, h);
    walk_square(w, x0 + h * (ax + bx), y0 + h * (ay + by), ax, ay, bx, by, h);
    walk_square(w, x0 + (t - 1) * ax + (h - 1) * bx, y0 + (t - 1) * ay + (h - 1) * by, -bx, -by, -ax, -ay, h);
}

int64_t cfpo_dens_hilbert_order(const cfpo_density *d, uint32_t *pix)
{
    int64_t s = 1;
    while (s < d->w || s < d->h) s *= 2;
    walk wk = {d, pix, 0};
    walk_square(&wk, 0, 0, 1, 0, 0, 1, s);
    return wk.m;
}

int cfpo_dens_start(const cfpo_density *d, int64_t n, uint64_t seed, double *xy)
{
    /* at most 2^26 pixels (greyimg.h) or 4096^2: an index fits 32 bits */
    uint32_t *k = malloc((size_t)(d->w * d->h) * sizeof *k);
    if (!k) return -1;
    const int64_t m = cfpo_dens_hilbert_order(d, k);
    double total = 0;
    for (int64_t t = 0; t < m; t++) total += d->rho[k[t]];
    /* walk the curve once: point p at mass (p + u_p) total / n */
    double acc = 0;
    int64_t t = 0;
    for (int64_t p = 0; p < n; p++) {
        const double want = ((double)p + cfpo_rand01(seed, 0xD57A27ull, (uint64_t)p)) * total / (double)n;
        while (t < m - 1 && acc + d->rho[k[t]] <= want) acc += d->rho[k[t++]];
        const int64_t pix = (int64_t)k[t], i = pix % d->w, j = pix / d->w;
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
