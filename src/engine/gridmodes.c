/* gridmodes.c - see gridmodes.h: the set's modes at the grid's lattice
 * vectors, summed in fixed point, and the transport field that cancels
 * them. */
#define _GNU_SOURCE /* sincos */
#include "gridmodes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int cfpo_gridmodes_init(cfpo_gridmodes *M, int g, int64_t n)
{
    memset(M, 0, sizeof *M);
    if (g < 3) return 0;
    const int reach = g % 3 == 0 ? 4 : 1;
    M->reach = reach;
    M->q = g % 3 == 0 ? g / 3 : g;
    for (int my = 0; my <= reach; my++)
        for (int mx = -reach; mx <= reach; mx++) {
            if (my == 0 && mx <= 0) continue;
            M->mx[M->count] = mx;
            M->my[M->count] = my;
            M->count++;
        }
    /* n terms of at most 2^bits each stay below 2^62 */
    int len = 0;
    for (uint64_t v = (uint64_t)(n > 0 ? n : 1); v; v >>= 1) len++;
    M->scale_bits = 61 - len;
    if (M->scale_bits > 40) M->scale_bits = 40;
    M->tab = calloc(2 * (size_t)CFPO_GRIDMODES_TABLE * CFPO_GRIDMODES_TABLE, sizeof *M->tab);
    if (!M->tab) {
        M->count = 0;
        return -1;
    }
    return 0;
}

void cfpo_gridmodes_free(cfpo_gridmodes *M)
{
    free(M->tab);
    M->tab = NULL;
}

/* z^m for m = 0..r of the unit complex z = (c, s). */
static void powers(double c, double s, int r, double *re, double *im)
{
    re[0] = 1;
    im[0] = 0;
    for (int m = 1; m <= r; m++) {
        re[m] = re[m - 1] * c - im[m - 1] * s;
        im[m] = re[m - 1] * s + im[m - 1] * c;
    }
}

/* exp(sign 2 pi i k.x) for every vector of M at (x, y), in M's order: row
 * my = 0 (mx = 1..r), then rows my = 1..r (mx = -r..r), r = M->reach. */
static void terms(const cfpo_gridmodes *M, double x, double y, double sign, double *tr, double *ti)
{
    const int r = M->reach, w = 2 * r + 1;
    double pr[5], pi[5], xr[9], xi[9], yr[5], yi[5], cx, sx, cy, sy;
    sincos(sign * 2 * M_PI * M->q * x, &sx, &cx);
    sincos(sign * 2 * M_PI * M->q * y, &sy, &cy);
    powers(cx, sx, r, pr, pi);
    powers(cy, sy, r, yr, yi);
    for (int m = 0; m <= r; m++) {
        xr[r + m] = xr[r - m] = pr[m];
        xi[r + m] = pi[m];
        xi[r - m] = -pi[m];
    }
    for (int m = 1; m <= r; m++) {
        tr[m - 1] = xr[r + m];
        ti[m - 1] = xi[r + m];
    }
    for (int my = 1; my <= r; my++) {
        double *a = tr + r + (my - 1) * w, *b = ti + r + (my - 1) * w;
        for (int j = 0; j < w; j++) {
            a[j] = xr[j] * yr[my] - xi[j] * yi[my];
            b[j] = xr[j] * yi[my] + xi[j] * yr[my];
        }
    }
}

void cfpo_gridmodes_sum(cfpo_gridmodes *M, const double *x, const double *y, int64_t np, int threads)
{
    const int nv = M->count;
    int64_t ar[CFPO_GRIDMODES_MAX] = {0}, ai[CFPO_GRIDMODES_MAX] = {0};
    const double scale = ldexp(1.0, M->scale_bits);
    if (nv > 0) {
#pragma omp parallel for schedule(static) reduction(+ : ar[:nv], ai[:nv]) num_threads(threads)
        for (int64_t j = 0; j < np; j++) {
            double tr[CFPO_GRIDMODES_MAX], ti[CFPO_GRIDMODES_MAX];
            terms(M, x[j], y[j], -1, tr, ti);
            /* truncated: a pure function of the term, so exact sums */
            for (int i = 0; i < nv; i++) {
                ar[i] += (int64_t)(tr[i] * scale);
                ai[i] += (int64_t)(ti[i] * scale);
            }
        }
    }
    for (int i = 0; i < CFPO_GRIDMODES_MAX; i++) {
        M->acc[2 * i] = ar[i];
        M->acc[2 * i + 1] = ai[i];
    }
}

/* The field at (x, y) from the modes: the sum over the vectors. */
static void field_exact(const cfpo_gridmodes *M, double x, double y, double *ux, double *uy)
{
    double tr[CFPO_GRIDMODES_MAX], ti[CFPO_GRIDMODES_MAX];
    double vx = 0, vy = 0;
    terms(M, x, y, 1, tr, ti);
    for (int i = 0; i < M->count; i++) {
        /* 2 Re(-i c e) = 2 Im(c e), e = exp(2 pi i k.x) */
        const double f = 2 * (M->c[2 * i] * ti[i] + M->c[2 * i + 1] * tr[i]);
        vx += f * M->mx[i] * M->q;
        vy += f * M->my[i] * M->q;
    }
    *ux = vx;
    *uy = vy;
}

void cfpo_gridmodes_finish(cfpo_gridmodes *M, int64_t n)
{
    for (int i = 0; i < M->count; i++) {
        const double kx = (double)M->mx[i] * M->q, ky = (double)M->my[i] * M->q;
        const double s = ldexp(1.0, M->scale_bits) * 2 * M_PI * (double)n * (kx * kx + ky * ky);
        M->c[2 * i] = (double)M->acc[2 * i] / s;
        M->c[2 * i + 1] = (double)M->acc[2 * i + 1] / s;
    }
    /* the field repeats with period 1 / q on both axes: its table over one
     * period */
    const int T = CFPO_GRIDMODES_TABLE;
    for (int b = 0; b < T; b++)
        for (int a = 0; a < T; a++) {
            double *t = M->tab + 2 * ((size_t)b * T + (size_t)a);
            field_exact(M, (double)a / T / M->q, (double)b / T / M->q, &t[0], &t[1]);
        }
}

double cfpo_gridmodes_power(const cfpo_gridmodes *M, int i, int64_t n)
{
    const double re = ldexp((double)M->acc[2 * i], -M->scale_bits), im = ldexp((double)M->acc[2 * i + 1], -M->scale_bits);
    return (re * re + im * im) / (double)n;
}

void cfpo_gridmodes_field(const cfpo_gridmodes *M, double x, double y, double *ux, double *uy)
{
    const int T = CFPO_GRIDMODES_TABLE;
    const double u = M->q * x * T, v = M->q * y * T;
    const double fu = floor(u), fv = floor(v), du = u - fu, dv = v - fv;
    const int a0 = (int)((int64_t)fu % T), b0 = (int)((int64_t)fv % T);
    const int a1 = (a0 + 1) % T, b1 = (b0 + 1) % T;
    const double *t00 = M->tab + 2 * (b0 * T + a0), *t10 = M->tab + 2 * (b0 * T + a1);
    const double *t01 = M->tab + 2 * (b1 * T + a0), *t11 = M->tab + 2 * (b1 * T + a1);
    const double w00 = (1 - du) * (1 - dv), w10 = du * (1 - dv), w01 = (1 - du) * dv, w11 = du * dv;
    *ux = w00 * t00[0] + w10 * t10[0] + w01 * t01[0] + w11 * t11[0];
    *uy = w00 * t00[1] + w10 * t10[1] + w01 * t01[1] + w11 * t11[1];
}
