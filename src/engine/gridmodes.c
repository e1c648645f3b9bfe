/* gridmodes.c - see gridmodes.h: the set's modes at the grid's lattice
 * vectors, summed in fixed point, and the transport field that cancels
 * them. */
#define _GNU_SOURCE /* sincos */
#include "gridmodes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void cfpo_gridmodes_init(cfpo_gridmodes *M, int g, int64_t n)
{
    memset(M, 0, sizeof *M);
    if (g < 3) return;
    const int reach = g % 3 == 0 ? 4 : 1;
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
}

/* z^m for m = 0..4 of the unit complex z = (c, s). */
static void powers(double c, double s, double *re, double *im)
{
    re[0] = 1;
    im[0] = 0;
    for (int m = 1; m <= 4; m++) {
        re[m] = re[m - 1] * c - im[m - 1] * s;
        im[m] = re[m - 1] * s + im[m - 1] * c;
    }
}

/* exp(sign 2 pi i k.x) for every vector of M at (x, y). */
static void terms(const cfpo_gridmodes *M, double x, double y, double sign, double *tr, double *ti)
{
    double xr[5], xi[5], yr[5], yi[5];
    const double ax = sign * 2 * M_PI * M->q * x, ay = sign * 2 * M_PI * M->q * y;
    double cx, sx, cy, sy;
    sincos(ax, &sx, &cx);
    sincos(ay, &sy, &cy);
    powers(cx, sx, xr, xi);
    powers(cy, sy, yr, yi);
    for (int i = 0; i < M->count; i++) {
        const int a = abs(M->mx[i]);
        const double pr = xr[a], pi = M->mx[i] < 0 ? -xi[a] : xi[a];
        const double qr = yr[M->my[i]], qi = yi[M->my[i]];
        tr[i] = pr * qr - pi * qi;
        ti[i] = pr * qi + pi * qr;
    }
}

void cfpo_gridmodes_sum(cfpo_gridmodes *M, const double *x, const double *y, int64_t np, int threads)
{
    const int nv = 2 * M->count;
    int64_t acc[2 * CFPO_GRIDMODES_MAX] = {0};
    const double scale = ldexp(1.0, M->scale_bits);
    if (nv > 0) {
#pragma omp parallel for schedule(static) reduction(+ : acc[:nv]) num_threads(threads)
        for (int64_t j = 0; j < np; j++) {
            double tr[CFPO_GRIDMODES_MAX], ti[CFPO_GRIDMODES_MAX];
            terms(M, x[j], y[j], -1, tr, ti);
            for (int i = 0; i < M->count; i++) {
                acc[2 * i] += llrint(tr[i] * scale);
                acc[2 * i + 1] += llrint(ti[i] * scale);
            }
        }
    }
    memcpy(M->acc, acc, sizeof acc);
}

void cfpo_gridmodes_finish(cfpo_gridmodes *M, int64_t n)
{
    for (int i = 0; i < M->count; i++) {
        const double kx = (double)M->mx[i] * M->q, ky = (double)M->my[i] * M->q;
        const double s = ldexp(1.0, M->scale_bits) * 2 * M_PI * (double)n * (kx * kx + ky * ky);
        M->c[2 * i] = (double)M->acc[2 * i] / s;
        M->c[2 * i + 1] = (double)M->acc[2 * i + 1] / s;
    }
}

double cfpo_gridmodes_power(const cfpo_gridmodes *M, int i, int64_t n)
{
    const double re = ldexp((double)M->acc[2 * i], -M->scale_bits), im = ldexp((double)M->acc[2 * i + 1], -M->scale_bits);
    return (re * re + im * im) / (double)n;
}

void cfpo_gridmodes_field(const cfpo_gridmodes *M, double x, double y, double *ux, double *uy)
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
