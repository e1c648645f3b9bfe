/* integration.h - UTK's integration test (Gaussian and Heaviside integrands
 * over the unit square, the mean squared error over many random ones) with
 * exact ground truth.
 *
 * Owns: the integrands, drawn as UTK's Integrands/GaussianIntegrands.hpp
 * and HeavisideIntegrands.hpp draw them (with the project's counter-based
 * generator, so not UTK's very integrands, but the same distributions):
 *   gauss      f(x) = exp(-(x - mu)^T Sigma^-1 (x - mu) / 2), not
 *              normalised, mu uniform in [0, 1]^2, Sigma = R diag(s1, s2)
 *              R^T with s1, s2 uniform in [0.01, 1] and R a rotation by an
 *              angle uniform in [0, 2 pi) (UTK: the Q of a Gaussian
 *              matrix's QR; in 2-D the quadratic form is the same for R
 *              and a reflection);
 *   heaviside  f(x) = [nu . (x - p) > 0], nu a uniform unit normal, p
 *              uniform in [0, 1]^2 (a random line through the square).
 * The estimate of integrand m is (1/n) sum_j f(x_j), not periodised (the
 * unit square, as UTK). MSE = (1/M) sum_m (estimate_m - I_m)^2 and its
 * standard error, over M integrands of each kind from a fixed seed.
 * Ground truth I_m, exact: Heaviside, the area of the square on the
 * line's positive side (the square clipped by the half-plane, shoelace);
 * Gaussian, int_0^1 exp(-dx^2 / (2 S_xx)) sqrt(2 pi / c) [Phi(sqrt c (1 -
 * mu_y + b dx / c)) - Phi(sqrt c (-mu_y + b dx / c))] dx (the conditional
 * normal's CDF in y, Sigma^-1 = [[a, b], [b, c]], S_xx = 1 / (a - b^2 / c),
 * dx = x - mu_x), by composite 16-point Gauss-Legendre on 64 panels (the
 * integrand is analytic with features no narrower than 0.1: the rule is
 * exact to rounding, 1e-15). */
#ifndef AN_INTEGRATION_H
#define AN_INTEGRATION_H

#include <stddef.h>
#include <stdint.h>

#define AN_INTEG_M 1024   /* default integrands of each kind */
#define AN_INTEG_SEED 2022

typedef struct {
    int gauss; /* 1: Gaussian, 0: Heaviside */
    double mx, my, a, b, c; /* Gaussian: mu, Sigma^-1 = [[a, b], [b, c]] */
    double nx, ny, r;       /* Heaviside: [nx x + ny y + r > 0] */
} an_integ_fn;

typedef struct {
    int M;
    double gauss_mse, gauss_se, heaviside_mse, heaviside_se;
} an_integration;

/* Integrand m (0-based) of the given kind for the seed. */
void an_integ_draw(int gauss, uint64_t seed, int m, an_integ_fn *f);
double an_integ_value(const an_integ_fn *f, double x, double y);
/* Its integral over [0, 1]^2, exact (see above). */
double an_integ_truth(const an_integ_fn *f);
/* The integral of f^2 (for the white-noise variance (int f^2 - I^2) / n). */
double an_integ_truth_sq(const an_integ_fn *f);

/* MSE over M >= 1 integrands of each kind. Coordinates in [0, 1). 0, or
 * -1 out of memory. The same result for any number of OpenMP threads. */
int an_integration_compute(const double *xy, size_t n, int M, uint64_t seed, an_integration *out);

#endif
