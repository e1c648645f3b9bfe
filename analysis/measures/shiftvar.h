/* shiftvar.h - the exact variance of the integration error of a point set
 * under a random toroidal shift, from the set's own periodogram.
 *
 * Owns: the integrands and the formula. For f = sum_k fhat(k) e^{2 pi i k.x}
 * on the unit torus and a shift s uniform on it, the estimate
 * I(s) = (1/n) sum_j f(x_j + s) has mean fhat(0) (the integral) and
 *     Var_s I = (1/n) sum_{k != 0} |fhat(k)|^2 P(k)
 * exactly, P the periodogram of power.h. The sum runs over the computed box
 * [-K, K]^2; beyond it P is taken as 1 (its mean over any large region for
 * distinct points) and the rest of sum |fhat|^2 comes from Parseval, so the
 * tail adds (1/n) (sum_{k != 0} |fhat(k)|^2 - sum over the box).
 * Integrands (fixed on the torus, so the variance against n shows the rate):
 *   gauss_S  the periodised Gaussian sum_m exp(-|x - c + m|^2 / (2 S^2)),
 *            fhat(k) = 2 pi S^2 exp(-2 pi^2 S^2 |k|^2); the box sum and the
 *            tail are products of one-dimensional theta sums;
 *   disk_R   the indicator of a disk of radius R (< 1/2) on the torus,
 *            fhat(0) = pi R^2, fhat(k) = R J1(2 pi R |k|) / |k|,
 *            sum_{k != 0} |fhat|^2 = pi R^2 - pi^2 R^4.
 * n^2 Var for a disk is the number variance of hyperuniformity studies. */
#ifndef AN_SHIFTVAR_H
#define AN_SHIFTVAR_H

#include <stddef.h>

#define AN_SHIFTVAR_COUNT 6

typedef struct {
    const char *name; /* "gauss_0.02", "disk_0.25", ... */
    int disk;         /* 0: Gaussian, 1: disk */
    double size;      /* sigma or radius */
} an_integrand;

extern const an_integrand an_integrands[AN_SHIFTVAR_COUNT];

typedef struct {
    double var[AN_SHIFTVAR_COUNT];  /* Var_s I */
    double tail[AN_SHIFTVAR_COUNT]; /* the part from beyond the box (P = 1) */
} an_shiftvar;

/* |fhat(k)|^2 of integrand t at |k|^2 = k2 (k2 > 0). */
double an_integrand_fhat2(int t, double k2);
/* The integrand itself at a torus offset (dx, dy) from its centre, each in
 * [-1/2, 1/2). For tests. */
double an_integrand_value(int t, double dx, double dy);

/* P over [-K, K]^2 (power.h), n points per set. Cost O(K^2). */
void an_shiftvar_compute(const double *P, int K, size_t n, an_shiftvar *out);

#endif
