/* test_shiftvar.c - the exact shift variance (1/n) sum |fhat|^2 P against
 * a direct Monte Carlo estimate over 4,000 random toroidal shifts, for
 * white noise, a jittered set and a CFPO set, every integrand: within five
 * Monte Carlo standard errors of the variance estimate (fixed seeds). The
 * white-noise formula (P = 1 everywhere) must miss the CFPO set's disks by
 * more than that (the test can tell the sets apart). Also: the Fourier
 * coefficients against a direct quadrature of the integrands. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "power.h"
#include "sets.h"
#include "shiftvar.h"
#include "testutil.h"

static int passed_, failed_;

static double wrap(double d) { return d - floor(d + 0.5); } /* to [-1/2, 1/2) */

/* Separable periodised Gaussian and the disk, fast enough for 4,000 shifts. */
static double value(int t, double dx, double dy)
{
    const double s = an_integrands[t].size;
    if (an_integrands[t].disk) return dx * dx + dy * dy < s * s ? 1 : 0;
    const int m = (int)ceil(8 * s) + 1;
    double gx = 0, gy = 0;
    for (int i = -m; i <= m; i++) {
        gx += exp(-(dx + i) * (dx + i) / (2 * s * s));
        gy += exp(-(dy + i) * (dy + i) / (2 * s * s));
    }
    return gx * gy;
}

static void compare(const char *what, const double *xy, size_t n, int white_must_miss)
{
    const int K = (int)ceil(6 * sqrt((double)n));
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    char err[256];
    CHECK(an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) == 0, "%s: %s", what, err);
    an_shiftvar sv;
    an_shiftvar_compute(P, K, n, &sv);
    const int M = 4000;
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
        const double s = an_integrands[t].size;
        const double mu = an_integrands[t].disk ? M_PI * s * s : 2 * M_PI * s * s;
        double m1 = 0, m2 = 0;
        for (int r = 0; r < M; r++) {
            const double sx = cfpo_rand01(77, 5, 2 * (uint64_t)r), sy = cfpo_rand01(77, 5, 2 * (uint64_t)r + 1);
            double I = 0;
            for (size_t j = 0; j < n; j++) I += value(t, wrap(xy[2 * j] + sx), wrap(xy[2 * j + 1] + sy));
            const double e = (I / (double)n - mu) * (I / (double)n - mu);
            m1 += e;
            m2 += e * e;
        }
        m1 /= M;
        const double se = sqrt((m2 / M - m1 * m1) / M);
        CHECK(fabs(m1 - sv.var[t]) <= 5 * se, "%s, %s: exact %.6g, Monte Carlo %.6g +- %.2g (tail %.2g)", what,
              an_integrands[t].name, sv.var[t], m1, se, sv.tail[t]);
        printf("%-12s %-11s exact %.6e  Monte Carlo %.6e +- %.1e  (%.1f se)\n", what, an_integrands[t].name,
               sv.var[t], m1, se, (m1 - sv.var[t]) / se);
        if (white_must_miss && an_integrands[t].disk) {
            const double white = (M_PI * s * s - M_PI * M_PI * s * s * s * s) / (double)n;
            CHECK(fabs(m1 - white) > 5 * se, "%s, %s: the white-noise variance %.6g is within 5 se", what,
                  an_integrands[t].name, white);
        }
    }
    free(P);
}

int main(void)
{
    /* the coefficients: fhat(k) = integral of f e^{-2 pi i k.x}, midpoint rule on 400^2 */
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
        const int G = 400, kx = 3, ky = 1;
        double re = 0;
        for (int i = 0; i < G; i++)
            for (int j = 0; j < G; j++) {
                const double x = (i + 0.5) / G - 0.5, y = (j + 0.5) / G - 0.5;
                re += an_integrand_value(t, x, y) * cos(2 * M_PI * (kx * x + ky * y));
            }
        re /= (double)G * G;
        const double want = sqrt(an_integrand_fhat2(t, kx * kx + ky * ky));
        /* the disk's edge limits the midpoint rule to about 1e-4 */
        CHECK(fabs(fabs(re) - want) <= (an_integrands[t].disk ? 2e-4 : 1e-9), "%s: fhat(3,1) %.9g, quadrature %.9g",
              an_integrands[t].name, want, re);
    }

    const size_t n = 576;
    double *xy = malloc(2 * n * sizeof *xy);
    set_white(xy, n, 21);
    compare("white noise", xy, n, 0);
    set_jittered(xy, 24, 22);
    compare("jittered", xy, n, 1);
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 23;
    o.threads = 1;
    cfpo_result res;
    char err[256];
    CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
    compare("cfpo", xy, n, 1);
    free(xy);
    return test_report(passed_, failed_);
}
