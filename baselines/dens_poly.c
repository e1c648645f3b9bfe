/* dens_poly.c - see dens_poly.h. */
#include "dens_poly.h"

#include "density_walk.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

int dens_poly_init(dens_poly *t, const cfpo_density *d)
{
    const int64_t w = d->w, h = d->h;
    t->d = d;
    t->pre = malloc((size_t)(3 * (w + 1) * h) * sizeof *t->pre);
    if (!t->pre) return -1;
    const double sw = (double)w;
    for (int64_t j = 0; j < h; j++)
        for (int l = 0; l < 3; l++) {
            double *p = t->pre + (3 * j + l) * (w + 1), s = 0;
            p[0] = 0;
            for (int64_t i = 0; i < w; i++) {
                /* int over pixel i of s^l = ((i + 1)^(l+1) - i^(l+1)) / ((l + 1) w^(l+1)) */
                const double a = (double)i, b = (double)(i + 1);
                const double mono = l == 0 ? (b - a) / sw
                                  : l == 1 ? (b * b - a * a) / (2 * sw * sw)
                                           : (b * b * b - a * a * a) / (3 * sw * sw * sw);
                p[i + 1] = (s += d->rho[j * w + i] * mono);
            }
        }
    return 0;
}

void dens_poly_free(dens_poly *t)
{
    free(t->pre);
    t->pre = NULL;
}

typedef struct {
    const dens_poly *t;
    double x0, y0, dx, dy, px, py;
    double acc[4];
} poly_ctx;

/* H_l(x) = int_0^x rho(s, row jj) s^l ds, l = 0..2, for x in global pixel
 * column i (rho there c); the density continued periodically in x. */
static void prefix(const dens_poly *t, int64_t jj, int64_t i, double c, double x, double H[3])
{
    const int64_t w = t->d->w;
    const int64_t q = cfpo_floor_div(i, w), ii = i - q * w;
    const double qd = (double)q, xl = x - qd, e = (double)ii / (double)w;
    double loc[3];
    for (int l = 0; l < 3; l++) {
        const double *p = t->pre + (3 * jj + l) * (w + 1);
        const double m = l == 0 ? xl - e : l == 1 ? 0.5 * (xl * xl - e * e) : (xl * xl * xl - e * e * e) / 3;
        loc[l] = p[ii] + c * m;
    }
    if (q == 0) {
        H[0] = loc[0];
        H[1] = loc[1];
        H[2] = loc[2];
        return;
    }
    /* int_q^{q + x'} rho s^l ds = sum_b C(l, b) q^(l-b) H_b(x') */
    H[0] = loc[0];
    H[1] = loc[1] + qd * loc[0];
    H[2] = loc[2] + 2 * qd * loc[1] + qd * qd * loc[0];
    /* int_0^q rho s^l ds over the whole periods in between */
    const double *T0 = t->pre + (3 * jj) * (w + 1), *T1 = T0 + (w + 1), *T2 = T1 + (w + 1);
    const double t0 = T0[w], t1 = T1[w], t2 = T2[w];
    const int64_t lo = q > 0 ? 0 : q, hi = q > 0 ? q : 0;
    const double sgn = q > 0 ? 1 : -1;
    for (int64_t m = lo; m < hi; m++) {
        const double md = (double)m;
        H[0] += sgn * t0;
        H[1] += sgn * (t1 + md * t0);
        H[2] += sgn * (t2 + 2 * md * t1 + md * md * t0);
    }
}

static void poly_piece(void *vc, double t0, double t1, int64_t i, int64_t j)
{
    poly_ctx *c = vc;
    const cfpo_density *d = c->t->d;
    const int64_t jj = j - cfpo_floor_div(j, d->h) * d->h, ii = i - cfpo_floor_div(i, d->w) * d->w;
    const double rho = d->rho[jj * d->w + ii];
    static const double g = 0.28867513459481288225; /* 1 / (2 sqrt 3) */
    const double h = t1 - t0, wgt = 0.5 * h * c->dy;
    for (int k = 0; k < 2; k++) {
        const double t = t0 + h * (k ? 0.5 + g : 0.5 - g);
        const double x = c->x0 + t * c->dx, v = c->y0 + t * c->dy - c->py, px = c->px;
        double H[3];
        prefix(c->t, jj, i, rho, x, H);
        c->acc[0] += wgt * H[0];
        c->acc[1] += wgt * (H[1] - px * H[0]);
        c->acc[2] += wgt * (v * H[0]);
        c->acc[3] += wgt * (H[2] - 2 * px * H[1] + px * px * H[0] + v * v * H[0]);
    }
}

void dens_poly_moments(const dens_poly *t, double px, double py, const double *v, size_t k, double out[4])
{
    poly_ctx c = {.t = t, .px = px, .py = py};
    for (size_t a = 0; a < k; a++) {
        const size_t b = a + 1 == k ? 0 : a + 1;
        c.x0 = px + v[2 * a];
        c.y0 = py + v[2 * a + 1];
        c.dx = px + v[2 * b] - c.x0;
        c.dy = py + v[2 * b + 1] - c.y0;
        if (c.dy == 0) continue; /* G dy vanishes */
        cfpo_density_walk(t->d, c.x0, c.y0, c.dx, c.dy, poly_piece, &c);
    }
    for (int q = 0; q < 4; q++) out[q] = c.acc[q];
}

typedef struct {
    const cfpo_density *d;
    double sum;
} seg_ctx;

static void seg_piece(void *vc, double t0, double t1, int64_t i, int64_t j)
{
    seg_ctx *c = vc;
    const int64_t jj = j - cfpo_floor_div(j, c->d->h) * c->d->h, ii = i - cfpo_floor_div(i, c->d->w) * c->d->w;
    c->sum += c->d->rho[jj * c->d->w + ii] * (t1 - t0);
}

double dens_poly_segment(const dens_poly *t, double x0, double y0, double x1, double y1)
{
    const double dx = x1 - x0, dy = y1 - y0;
    if (dx == 0 && dy == 0) return 0;
    seg_ctx c = {t->d, 0};
    cfpo_density_walk(t->d, x0, y0, dx, dy, seg_piece, &c);
    return c.sum * sqrt(dx * dx + dy * dy);
}
