/* shiftvar.c - see shiftvar.h.
 *
 * The box sum visits the octant 0 <= ky <= kx <= K once per |fhat|^2 (the
 * disks' Bessel function is the cost) and adds P at the up to eight
 * frequencies of the same |k| related by the square's symmetries. */
#include "shiftvar.h"

#include <math.h>
#include <stdint.h>

#include "power.h"

const an_integrand an_integrands[AN_SHIFTVAR_COUNT] = {
    {"gauss_0.02", 0, 0.02}, {"gauss_0.05", 0, 0.05}, {"gauss_0.15", 0, 0.15},
    {"disk_0.1", 1, 0.1},    {"disk_0.25", 1, 0.25},  {"disk_0.4", 1, 0.4}};

double an_integrand_fhat2(int t, double k2)
{
    const double s = an_integrands[t].size;
    if (!an_integrands[t].disk) {
        const double c = 2 * M_PI * s * s;
        return c * c * exp(-4 * M_PI * M_PI * s * s * k2);
    }
    const double k = sqrt(k2), f = s * j1(2 * M_PI * s * k) / k;
    return f * f;
}

double an_integrand_value(int t, double dx, double dy)
{
    const double s = an_integrands[t].size;
    if (an_integrands[t].disk) return dx * dx + dy * dy < s * s ? 1 : 0;
    double v = 0;
    const int m = (int)ceil(8 * s) + 1; /* images to 8 sigma and beyond */
    for (int my = -m; my <= m; my++)
        for (int mx = -m; mx <= m; mx++) {
            const double ex = dx + mx, ey = dy + my;
            v += exp(-(ex * ex + ey * ey) / (2 * s * s));
        }
    return v;
}

/* sum over the up to 8 symmetric images of (kx, ky), 0 <= ky <= kx, of P */
static double orbit(const double *P, int K, int kx, int ky)
{
    double s = 0;
    const int xs[2] = {kx, -kx}, ys[2] = {ky, -ky};
    for (int a = 0; a < (kx ? 2 : 1); a++)
        for (int b = 0; b < (ky ? 2 : 1); b++) {
            s += P[an_pidx(K, xs[a], ys[b])];
            if (kx != ky) s += P[an_pidx(K, ys[b], xs[a])];
        }
    return s;
}

static int orbit_size(int kx, int ky)
{
    int c = (kx ? 2 : 1) * (ky ? 2 : 1);
    return kx != ky ? 2 * c : c;
}

void an_shiftvar_compute(const double *P, int K, size_t n, an_shiftvar *out)
{
    long double box[AN_SHIFTVAR_COUNT] = {0}, fsum[AN_SHIFTVAR_COUNT] = {0};
    for (int kx = 1; kx <= K; kx++)
        for (int ky = 0; ky <= kx; ky++) {
            const double k2 = (double)kx * kx + (double)ky * ky;
            const double po = orbit(P, K, kx, ky);
            const int os = orbit_size(kx, ky);
            for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
                const double f2 = an_integrand_fhat2(t, k2);
                box[t] += (long double)f2 * po;
                fsum[t] += (long double)f2 * os;
            }
        }
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
        const double s = an_integrands[t].size;
        double tail;
        if (an_integrands[t].disk) {
            tail = (double)((long double)M_PI * s * s - (long double)M_PI * M_PI * s * s * s * s - fsum[t]);
        } else {
            /* theta sums: T_K = sum_{|m| <= K} q^{m^2}, T = T_K + 2 sum_{m > K}
             * q^{m^2}; box (with k = 0) c^2 T_K^2, all c^2 T^2 */
            const double a = 4 * M_PI * M_PI * s * s, c = 2 * M_PI * s * s;
            long double tk = 1, rest = 0;
            for (int m = 1; m <= K; m++) tk += 2 * expl(-(long double)a * m * m);
            for (int64_t m = K + 1;; m++) {
                const long double e = expl(-(long double)a * (long double)m * (long double)m);
                rest += 2 * e;
                /* e == 0: past the underflow (a subnormal rest times 1e-30 is 0 too,
                 * so the relative test alone never ended: m = 344 of a 1,024-point set) */
                if (e == 0 || e < 1e-30L * (rest > 0 ? rest : 1)) break;
            }
            tail = (double)((long double)c * c * rest * (2 * tk + rest));
        }
        if (tail < 0) tail = 0; /* rounding, when the box holds all of it */
        out->tail[t] = tail / (double)n;
        out->var[t] = (double)(box[t] + tail) / (double)n;
    }
}
