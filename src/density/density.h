/* density.h - layer 2 (may include cli.h and the layers below): a density
 * on the unit torus, as `--density SPEC` names it.
 *
 * SPEC is one of
 *   FILE.png, FILE.pgm          a greyscale image; dark = dense (rho = 1 -
 *                               grey / white), FILE.png:invert for
 *                               light = dense (rho = grey / white);
 *   FILE.npy                    a 2-D array (H, W) of non-negative float64
 *                               or float32, row j = y;
 *   cos:a=A,kx=K,ky=K           1 + A cos(2 pi (kx x + ky y)), A in [0, 1],
 *                               kx, ky whole numbers (default a=0.9, kx=1, ky=0);
 *   ramp:contrast=C             a periodic linear ramp in x from 1 (x = 0)
 *                               up to C (x = 1/2) and back (default C = 16),
 *                               sampled at the pixels' left edges so that
 *                               its contrast is C exactly (R even);
 *   balzer                      the teaser field of Balzer, Schloemer and
 *                               Deussen (2009) as the design notes give it
 *                               (constants not yet checked against the paper)
 *                               exp(-20 (u^2 + v^2)) + 0.2 sin^2(pi u) sin^2(pi v)
 *                               on (u, v) = (2x - 1, 2y - 1), periodic to
 *                               within 1e-8, values below 1/256 of its
 *                               maximum raised to that.
 *   The named densities take res=R (16..4096, default 1024): they are
 *   sampled at the centres of an R x R raster (the ramp: see above).
 * Every density is piecewise constant on its W x H pixels. Pixel (i, j)
 * covers [i/W, (i+1)/W) x [j/H, (j+1)/H), j counted from y = 0 up: an
 * image's top row (row 0 of the file) is j = H - 1, near y = 1, so a plot
 * with y up shows the image upright; an array's row j is j. The values are
 * normalised to mean 1; zero-density pixels get no points; the contrast
 * (max over the smallest non-zero value) may be at most DENSITY_CONTRAST_MAX.
 *
 * Owns: the SPEC grammar (density.c); normalisation, validation, the
 * hash (density_values.c); lookups. Does not own: the image grammars (pgm.c, png_read.c), the .npy header
 * (npy.c), the named fields' formulas (density_analytic.c). */
#ifndef CFPO_DENSITY_H
#define CFPO_DENSITY_H

#include <stddef.h>
#include <stdint.h>

#define DENSITY_CONTRAST_MAX 256.0

typedef struct {
    int64_t w, h;      /* pixels in x and y */
    double *rho;       /* w h values, row j (y) after row j - 1, mean 1 */
    double rho_min;    /* smallest non-zero value */
    double rho_max;
    double support;    /* fraction of the torus where rho > 0 */
    uint64_t hash;     /* FNV-1a 64 over w, h and the normalised values */
} cfpo_density;

/* The density SPEC names. 0, or -1 with one line in err (bad spec,
 * unreadable or bad file, negative / NaN / infinite / all-zero values, a
 * contrast beyond the limit, too large). */
int cfpo_density_load(const char *spec, cfpo_density *d, char *err, size_t errlen);

/* From w h values, row j = y (what = the name for messages). */
int cfpo_density_from_values(const double *v, int64_t w, int64_t h, const char *what, cfpo_density *d, char *err,
                             size_t errlen);

void cfpo_density_free(cfpo_density *d);

/* Is n enough points for d? The sparsest non-zero pixel's local spacing
 * Delta(n) / sqrt(rho_min) must be at most 1/4 of the torus. */
int cfpo_density_check_n(const cfpo_density *d, int64_t n, char *err, size_t errlen);

static inline int64_t cfpo_density_pixel(const cfpo_density *d, double x, double y)
{
    int64_t i = (int64_t)(x * (double)d->w), j = (int64_t)(y * (double)d->h);
    if (i < 0) i = 0;
    if (i >= d->w) i = d->w - 1;
    if (j < 0) j = 0;
    if (j >= d->h) j = d->h - 1;
    return j * d->w + i;
}

static inline double cfpo_density_at(const cfpo_density *d, double x, double y)
{
    return d->rho[cfpo_density_pixel(d, x, y)];
}

/* Asks the cache for the pixels of the box [x, x + s) x [y, y + s) on the
 * torus (0 <= x, y < 1, s < 1): the rows it covers, each from its first
 * pixel to its last, a hint only (no value is read). A cell's solves
 * read q only inside the cell, and an analytic density's raster (8 MB at
 * 1024 x 1024) does not stay in the cache from one cell to the next. */
static inline void cfpo_density_prefetch_box(const cfpo_density *d, double x, double y, double s)
{
    const int64_t w = d->w, h = d->h;
    int64_t i0 = (int64_t)(x * (double)w), j0 = (int64_t)(y * (double)h);
    int64_t i1 = (int64_t)((x + s) * (double)w), nj = (int64_t)((y + s) * (double)h) - j0 + 1;
    if (i0 < 0 || i0 >= w) i0 = 0;
    if (j0 < 0 || j0 >= h) j0 = 0;
    if (i1 >= w) i1 = w - 1; /* the part past the seam is left to the loads */
    if (i1 < i0) i1 = i0;
    if (nj > h) nj = h;
    for (int64_t r = 0, j = j0; r < nj; r++, j = j + 1 < h ? j + 1 : 0) {
        const uintptr_t e = (uintptr_t)(d->rho + j * w + i1);
        for (uintptr_t a = (uintptr_t)(d->rho + j * w + i0) & ~(uintptr_t)63; a <= e; a += 64)
            __builtin_prefetch((const void *)a, 0, 3); /* one hint a 64-byte line */
    }
}

/* density_analytic.c: the named density `name` with its parameters
 * (params: the text after ':', or NULL), rasterised. */
int cfpo_density_named(const char *name, const char *params, cfpo_density *d, char *err, size_t errlen);

#endif
