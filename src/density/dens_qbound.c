/* dens_qbound.c - layer 2: the pyramids of maxima and minima of q (dens_qbound.h). */
#include "dens_qbound.h"

#include <math.h>
#include <stdlib.h>

/* A float at least v (v >= 0, finite). */
static float up(double v)
{
    float f = (float)v;
    return (double)f < v ? nextafterf(f, INFINITY) : f;
}

/* A float at most v (v >= 0, or +inf). */
static float down(double v)
{
    float f = (float)v;
    return (double)f > v ? nextafterf(f, 0) : f;
}

/* Level l's texel (i, j): the max (min over the non-zero ones, +inf if
 * none) of q over the pixels it covers. */
static double texel(const cfpo_dens_qbound *b, int l, int64_t i, int64_t j)
{
    if (l > 0) return (double)b->q[l][j * b->w[l] + i];
    const double r = b->d->rho[j * b->w[0] + i];
    return b->lowest && !(r > 0) ? INFINITY : sqrt(r);
}

/* a better than m in the pyramid's sense */
static int beats(const cfpo_dens_qbound *b, double a, double m) { return b->lowest ? a < m : a > m; }

static int build(cfpo_dens_qbound *b, const cfpo_density *d, int lowest)
{
    b->d = d;
    b->lowest = lowest;
    b->levels = 1;
    const double qlo = sqrt(d->rho_min), qhi = sqrt(d->rho_max);
    b->flat = qlo > 0 && qhi <= qlo * CFPO_QBOUND_FLAT ? (lowest ? qlo : qhi) : 0;
    b->w[0] = d->w;
    b->h[0] = d->h;
    b->q[0] = NULL;
    int64_t w = d->w, h = d->h;
    for (int l = 1; l < CFPO_QBOUND_LEVELS && (w > 1 || h > 1); l++) {
        const int64_t pw = w, ph = h;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
        b->w[l] = w;
        b->h[l] = h;
        b->q[l] = malloc((size_t)(w * h) * sizeof(float));
        if (!b->q[l]) {
            cfpo_dens_qbound_free(b);
            return -1;
        }
        b->levels = l + 1;
        for (int64_t j = 0; j < h; j++)
            for (int64_t i = 0; i < w; i++) {
                double m = lowest ? INFINITY : 0;
                for (int64_t dj = 0; dj < 2; dj++)
                    for (int64_t di = 0; di < 2; di++) {
                        const int64_t ii = 2 * i + di, jj = 2 * j + dj;
                        if (ii < pw && jj < ph) {
                            const double v = texel(b, l - 1, ii, jj);
                            if (beats(b, v, m)) m = v;
                        }
                    }
                b->q[l][j * w + i] = lowest ? down(m) : up(m);
            }
    }
    return 0;
}

int cfpo_dens_qbound_build(cfpo_dens_qbound *b, const cfpo_density *d) { return build(b, d, 0); }

int cfpo_dens_qbound_build_min(cfpo_dens_qbound *b, const cfpo_density *d) { return build(b, d, 1); }

/* The pixel range [a, z] of one axis (n pixels) that [lo, hi] touches,
 * widened by one pixel each side, as at most two ranges inside [0, n). */
static int ranges(double lo, double hi, int64_t n, int64_t r[2][2])
{
    const double fa = floor(lo * (double)n) - 1, fz = floor(hi * (double)n) + 1;
    if (!(fz - fa + 1 < (double)n)) {
        r[0][0] = 0;
        r[0][1] = n - 1;
        return 1;
    }
    /* fa is a whole number well inside int64_t's range: the remainder in
     * integers is fmod's, exactly */
    int64_t a = (int64_t)fa % n, z;
    if (a < 0) a += n;
    z = a + (int64_t)(fz - fa);
    if (z < n) {
        r[0][0] = a;
        r[0][1] = z;
        return 1;
    }
    r[0][0] = a;
    r[0][1] = n - 1;
    r[1][0] = 0;
    r[1][1] = z - n;
    return 2;
}

/* The max (min) over pixels [xa, xz] x [ya, yz] of level 0: the lowest
 * level where each axis's range spans at most two texels, `finer` levels
 * below it (at most 2^(finer + 1) + 1 texels an axis). */
static double rect(const cfpo_dens_qbound *b, int64_t xa, int64_t xz, int64_t ya, int64_t yz, int finer)
{
    /* (z >> l) - (a >> l) <= 1 needs z - a < 2^(l + 1), so no level
     * below floor(log2(z - a)) does: the search starts there (the same
     * level) */
    const int64_t span = xz - xa > yz - ya ? xz - xa : yz - ya;
    int l = span > 0 ? 63 - __builtin_clzll((unsigned long long)span) : 0;
    if (l > b->levels - 1) l = b->levels - 1;
    while (l + 1 < b->levels && ((xz >> l) - (xa >> l) > 1 || (yz >> l) - (ya >> l) > 1)) l++;
    l = l > finer ? l - finer : 0;
    double m = b->lowest ? INFINITY : 0;
    for (int64_t j = ya >> l; j <= yz >> l; j++)
        for (int64_t i = xa >> l; i <= xz >> l; i++) {
            const double v = texel(b, l, i, j);
            if (beats(b, v, m)) m = v;
        }
    return m;
}

double cfpo_dens_qbound_box(const cfpo_dens_qbound *b, double x0, double y0, double x1, double y1)
{
    return cfpo_dens_qbound_box_finer(b, x0, y0, x1, y1, 0);
}

double cfpo_dens_qbound_box_finer(const cfpo_dens_qbound *b, double x0, double y0, double x1, double y1, int finer)
{
    if (b->flat > 0) return b->flat;
    int64_t rx[2][2], ry[2][2];
    const int nx = ranges(x0, x1, b->w[0], rx), ny = ranges(y0, y1, b->h[0], ry);
    double m = b->lowest ? INFINITY : 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const double v = rect(b, rx[i][0], rx[i][1], ry[j][0], ry[j][1], finer);
            if (beats(b, v, m)) m = v;
        }
    return m;
}

void cfpo_dens_qbound_free(cfpo_dens_qbound *b)
{
    for (int l = 1; l < b->levels; l++) free(b->q[l]);
    b->levels = 0;
}
