/* dens_levels.c - layer 3: cells sized to the local spacing (dens_levels.h). */
#include "dens_levels.h"

#include <math.h>
#include <stdlib.h>

#include "dens_dist.h"

int cfpo_dens_levels_init(cfpo_dens_levels *V, const cfpo_density *d, int64_t g0, double D, double spacings)
{
    *V = (cfpo_dens_levels){.n = 1, .g0 = g0, .qmin = sqrt(d->rho_min), .sx = NAN, .sy = NAN};
    /* the densest spacing's cells a side */
    const double gd = floor(1.0 / (spacings * D / sqrt(d->rho_max)));
    while (V->n < CFPO_DENS_LEVELS_MAX && (double)(g0 << V->n) <= gd && (g0 << V->n) <= 3 * 8192) V->n++;
    if (V->n == 1) return 0;
    const int64_t gf = g0 << (V->n - 1);
    V->work = malloc((size_t)(gf * gf) * sizeof *V->work);
    int ok = V->work != NULL;
    for (int l = 0; l < V->n; l++) {
        const int64_t g = g0 << l;
        for (int k = 0; k < CFPO_DENS_TIERS; k++) {
            V->tq[l][k] = malloc((size_t)(g * g) * sizeof *V->tq[l][k]);
            ok &= V->tq[l][k] != NULL;
        }
    }
    if (!ok) {
        cfpo_dens_levels_free(V);
        return -1;
    }
    return 0;
}

/* out[i] = the least of e[i .. i + w - 1], i in [0, n - w]: runs of
 * doubling length folded in place into t (n floats of room), then two
 * overlapping runs a window (the same least as a scan of the window). */
static void window_min(const float *e, int64_t n, int64_t w, float *t, float *out)
{
    for (int64_t i = 0; i < n; i++) t[i] = e[i];
    int64_t q = 1;
    for (; 2 * q <= w; q *= 2)
        for (int64_t i = 0; i + 2 * q <= n; i++) t[i] = t[i + q] < t[i] ? t[i + q] : t[i];
    for (int64_t i = 0; i + w <= n; i++) out[i] = t[i + w - q] < t[i] ? t[i + w - q] : t[i];
}

/* out: the least of a over the cells within h of each (wrapping, g x g),
 * along the rows, then along the columns; line: 5 g floats of room
 * (a line with its wrapped ends, the folded runs, a line's minima). */
static void box_min(const float *a, float *out, int64_t g, int64_t h, float *line)
{
    if (2 * h + 1 > g) h = g / 2; /* the whole line */
    float *t = line + g + 2 * h, *o = t + g + 2 * h;
    for (int pass = 0; pass < 2; pass++) {
        const float *src = pass ? out : a;
        for (int64_t r = 0; r < g; r++) {
            for (int64_t i = -h; i < g + h; i++) {
                const int64_t k = i < 0 ? i + g : i >= g ? i - g : i;
                line[i + h] = pass ? src[k * g + r] : src[r * g + k];
            }
            window_min(line, g + 2 * h, 2 * h + 1, t, o);
            for (int64_t i = 0; i < g; i++) {
                if (pass) out[i * g + r] = o[i];
                else out[r * g + i] = o[i];
            }
        }
    }
}

/* float at most v (v >= 0 or +inf) */
static float below(double v)
{
    const float f = (float)v;
    return (double)f > v ? nextafterf(f, 0) : f;
}

int cfpo_dens_levels_place(cfpo_dens_levels *V, const cfpo_dens_qbound *qlow, double sx, double sy)
{
    if (V->n == 1 || (sx == V->sx && sy == V->sy)) return 0;
    const int f = V->n - 1;
    const int64_t gf = V->g0 << f;
    float *line = malloc((size_t)(5 * gf + 8) * sizeof *line), *own = malloc((size_t)(gf * gf) * sizeof *own);
    if (!line || !own) {
        free(line);
        free(own);
        return -1;
    }
    /* each finest cell's own least q, from the pyramid (over the pixels
     * it touches, widened by one) */
    const double Lf = 1.0 / (double)gf;
    for (int64_t j = 0; j < gf; j++)
        for (int64_t i = 0; i < gf; i++) {
            const double x0 = sx + (double)i * Lf, y0 = sy + (double)j * Lf;
            V->work[j * gf + i] = below(cfpo_dens_qbound_box(qlow, x0, y0, x0 + Lf, y0 + Lf));
        }
    /* up the levels (a cell of level l is 2 x 2 of level l + 1: the same
     * offset, cell_of's floors nest), each level's tiers from its own */
    for (int l = f; l >= 0; l--) {
        const int64_t g = V->g0 << l;
        if (l < f) {
            const int64_t h = 2 * g;
            const float *c = V->work;
            for (int64_t j = 0; j < g; j++)
                for (int64_t i = 0; i < g; i++) {
                    float m = c[(2 * j) * h + 2 * i];
                    if (c[(2 * j) * h + 2 * i + 1] < m) m = c[(2 * j) * h + 2 * i + 1];
                    if (c[(2 * j + 1) * h + 2 * i] < m) m = c[(2 * j + 1) * h + 2 * i];
                    if (c[(2 * j + 1) * h + 2 * i + 1] < m) m = c[(2 * j + 1) * h + 2 * i + 1];
                    own[j * g + i] = m;
                }
            for (int64_t t = 0; t < g * g; t++) V->work[t] = own[t];
        }
        for (int k = 1; k <= CFPO_DENS_TIERS; k++) box_min(V->work, V->tq[l][k - 1], g, ((int64_t)1 << (k - 1)) + 1, line);
    }
    free(line);
    free(own);
    V->sx = sx;
    V->sy = sy;
    return 0;
}

int cfpo_dens_levels_tiers(const cfpo_dens_levels *V, int l, int64_t cx, int64_t cy, double *t)
{
    const int64_t g = V->g0 << l;
    for (int k = 0; k < CFPO_DENS_TIERS; k++) t[k] = (double)V->tq[l][k][cy * g + cx];
    return CFPO_DENS_TIERS;
}

uint32_t cfpo_dens_levels_fine(const cfpo_dens_levels *V, double x, double y)
{
    int64_t ix, iy; /* the cell's column and row, without dividing its index */
    cfpo_dens_cell_xy(V->g0 << (V->n - 1), V->sx, V->sy, x, y, &ix, &iy);
    return (uint32_t)(iy << 16 | ix);
}

int cfpo_dens_levels_of(const cfpo_dens_levels *V, double x, double y, double q, double D, double spacings,
                        double worth)
{
    if (V->n == 1 || !(q > 0)) return 0;
    return cfpo_dens_levels_of_fine(V, cfpo_dens_levels_fine(V, x, y), q, D, spacings, worth);
}

int cfpo_dens_levels_of_fine(const cfpo_dens_levels *V, uint32_t fine, double q, double D, double spacings,
                             double worth)
{
    if (V->n == 1 || !(q > 0)) return 0;
    int l = V->n - 1;
    const double s = spacings * D / q;
    while (l > 0 && 1.0 / (double)(V->g0 << l) < s) l--;
    double t[CFPO_DENS_TIERS];
    const int64_t fx = fine & 0xffff, fy = fine >> 16;
    for (; l > 0; l--) {
        const int64_t g = V->g0 << l, sh = V->n - 1 - l;
        const int nt = cfpo_dens_levels_tiers(V, l, fx >> sh, fy >> sh, t);
        const double L = 1.0 / (double)g;
        if (cfpo_dens_levels_clear(t, nt, V->qmin, L, L, q, (worth * D) * (worth * D))) break;
    }
    return l;
}

void cfpo_dens_levels_mark_fine(const cfpo_dens_levels *V, uint32_t *const *touch, uint32_t phase, uint32_t a, uint32_t b)
{
    const int f = V->n - 1;
    const int64_t ax = a & 0xffff, ay = a >> 16, bx = b & 0xffff, by = b >> 16;
    for (int l = 0; l <= f; l++) { /* a level's cell of a spot: the finest's shifted (the floors nest) */
        const int sh = f - l;
        const int64_t g = V->g0 << l;
        __atomic_store_n(&touch[l][(ay >> sh) * g + (ax >> sh)], phase, __ATOMIC_RELAXED);
        __atomic_store_n(&touch[l][(by >> sh) * g + (bx >> sh)], phase, __ATOMIC_RELAXED);
    }
}

void cfpo_dens_levels_free(cfpo_dens_levels *V)
{
    for (int l = 0; l < CFPO_DENS_LEVELS_MAX; l++)
        for (int k = 0; k < CFPO_DENS_TIERS; k++) {
            free(V->tq[l][k]);
            V->tq[l][k] = NULL;
        }
    free(V->work);
    V->work = NULL;
    V->n = 1;
}
