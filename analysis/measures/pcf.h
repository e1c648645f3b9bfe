/* pcf.h - the pair correlation function g(r) of a point set on the unit
 * torus, exact for its kernel, in O(n) time.
 *
 * Owns: the definition and its computation. With Delta(n) = sqrt(2 /
 * (sqrt(3) n)) (the spacing of the hexagonal lattice of n points) and
 * sigma = s Delta,
 *     g(r) = [n (n - 1) 2 pi r]^-1 sum_{i != j} k(r - |x_i - x_j|),
 *     k(t) = exp(-t^2 / (2 sigma^2)) / (sigma sqrt(2 pi)) for |t| <= 6 sigma,
 *            0 beyond (the truncated mass is 2e-9 of the kernel's),
 * |x_i - x_j| the distance on the torus (minimum image). No window
 * correction: the torus has no edge, so the factor is 1 (UTK's toroidal
 * PCF keeps the unit square's 1/(1 - 4r/pi + r^2/pi)). White noise has
 * g = 1 for r >= 6 sigma (below, the kernel reaches r < 0, where no pair
 * is). g is tabulated at r_b = b h, b = 1..B, h = sigma / 5, up to rmax
 * (B = floor(rmax / h + 1e-9)), and no further than 1/2 - 6 sigma (beyond,
 * the circle of radius r would meet itself on the torus): B is cut there
 * for small n.
 * How: only pairs closer than r_B + 6 sigma count; a grid of cells of at
 * least that side finds them (each unordered pair once, half stencil), a
 * plain double loop when the grid would have fewer than 3 cells a side.
 * Along b the kernel is a product recurrence (two exp a pair). Each row of
 * cells sums into its own table and the tables add in row order, so the
 * result is the same for any number of OpenMP threads. */
#ifndef AN_PCF_H
#define AN_PCF_H

#include <stddef.h>

#define AN_PCF_SIGMA 0.05 /* default sigma / Delta */
#define AN_PCF_RMAX 3.0   /* default rmax / Delta */
#define AN_PCF_CUT 6.0    /* the kernel's support, in sigma */

/* Bins B for n points (0: none fits, n < 2 or the torus is too small). */
int an_pcf_bins(size_t n, double sigma, double rmax);

/* g(r_b) for b = 1..bins into g[0..bins-1] (bins from an_pcf_bins).
 * Coordinates in [0, 1). 0, or -1 out of memory. */
int an_pcf_compute(const double *xy, size_t n, double sigma, double rmax, int bins, double *g);

/* The same by the O(n^2) double loop and a direct exp per term: for tests. */
void an_pcf_brute(const double *xy, size_t n, double sigma, int bins, double *g);

#endif
