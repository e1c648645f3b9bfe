/* ring_power.h - the grid imprint measured directly: P(k) = |sum_j
 * exp(-2 pi i k.x_j)|^2 / n at one integer wave vector by the direct sum,
 * and the mean of P over k's ring, the yardstick a peak at k is read
 * against (docs/results/2026-11-28-imprint.md). Shared by
 * scripts/imprint.c and tests/test_imprint.c; header only, so that the
 * script still builds with one cc line. cfpo-analyze's spectrum and its
 * imprint line are power.h's and rings.h's (every k at once).
 * Includes nothing of the project. */
#ifndef AN_RING_POWER_H
#define AN_RING_POWER_H

#include <math.h>
#include <stddef.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define RP_RING 96 /* the directions a ring's mean samples */

/* P(kx, ky) of the n points xy (x, y pairs). */
static inline double rp_power(const double *xy, size_t n, int kx, int ky)
{
    double re = 0, im = 0;
#pragma omp parallel for reduction(+ : re, im) schedule(static)
    for (size_t i = 0; i < n; i++) {
        const double a = -2 * M_PI * ((double)kx * xy[2 * i] + (double)ky * xy[2 * i + 1]);
        re += cos(a);
        im += sin(a);
    }
    return (re * re + im * im) / (double)n;
}

/* The mean of P over the integer vectors k with round(|k|) = r: RP_RING
 * directions spread evenly over the upper half plane (P(-k) = P(k)), the
 * axis vectors left out (the grid's own), each vector once. NAN when none
 * is left. */
static inline double rp_ring_mean(const double *xy, size_t n, int r)
{
    int kx[RP_RING], ky[RP_RING], m = 0;
    for (int j = 0; j < RP_RING; j++) {
        const double a = M_PI * (j + 0.5) / RP_RING;
        const int x = (int)lround(r * cos(a)), y = (int)lround(r * sin(a));
        if (x == 0 || y == 0 || lround(sqrt((double)x * x + (double)y * y)) != r) continue;
        int dup = 0;
        for (int q = 0; q < m && !dup; q++) dup = kx[q] == x && ky[q] == y;
        if (!dup) kx[m] = x, ky[m] = y, m++;
    }
    double s = 0;
    for (int q = 0; q < m; q++) s += rp_power(xy, n, kx[q], ky[q]);
    return m ? s / m : NAN;
}

#endif
