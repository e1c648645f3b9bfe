/* dda.h - the differential-domain spectrum of a point set under a density
 * (Wei and Wang, "Differential domain analysis for non-uniform sampling",
 * ACM TOG 30(4), 2011), with the symmetric normalisation of the density
 * measures (src/density/dens_measure.h): the spectrum adaptive sets get at all.
 *
 * Owns the definition (analysis/README.md, "Differential-domain
 * spectrum"). With local spacing r = Delta(n) / sqrt(rho), each pair's
 * difference d_ij = x_j - x_i (torus, nearest image) is scaled to
 *     d'_ij = Delta(n) d_ij / sqrt(r_i r_j) = d_ij (rho_i rho_j)^(1/4),
 * weighted by a window W(|d'| / (R Delta(n))), W(s) = (1 - s^2)^2 on
 * s < 1, and the spectrum at the integer frequencies k of [-K, K]^2 is
 *     S(k) = (1/m) sum_{i,j} W(|d'_ij| / (R Delta)) exp(-2 pi i k.d'_ij)
 *            - m What(k),
 * the sum over the m points with rho > 0 (i = j included: W(0) = 1),
 * What(k) = 16 pi (R Delta)^2 J3(a) / a^3, a = 2 pi |k| R Delta, the
 * window's own transform: what a Poisson set of the same local density
 * puts there (a point sees about m neighbours per unit of scaled area).
 * S is the set's structure factor smoothed by What (width about
 * 1 / (R Delta) in |k|): 1 at high frequencies, below 1 where the set is
 * blue. R = 0 takes every pair and no window (What = the unit mass at
 * k = 0): with rho = 1 that is the periodogram P(k) of power.h exactly
 * (S(0) = 0 instead of n); it is O(n^2) and kept to AN_DDA_FULL_MAX
 * points.
 *
 * Computed as a type-1 NUFFT of the pairs (nufft_kernel.h, width
 * AN_DDA_WIDTH), the pairs found on a cell list: from point i only the
 * partners with rho_j > rho_i (or equal and j > i), within R r_i, each
 * pair once with weight 2 W (the real part). Pairs are spread by fixed
 * chunks of points into private patches summed in chunk order: the
 * result does not depend on the number of threads. */
#ifndef AN_DDA_H
#define AN_DDA_H

#include <stddef.h>
#include <stdio.h>

#include "density.h"

#define AN_DDA_RADIUS 8.0      /* the window's radius R in local spacings */
#define AN_DDA_WIDTH 8         /* spreading kernel support (error about 1e-7 of the pairs' weight) */
#define AN_DDA_FULL_MAX 65536  /* most points for R = 0 (all pairs) */

typedef struct {
    double radius;   /* R */
    double pairs;    /* unordered pairs inside the window */
    int grid;        /* NUFFT grid side */
    size_t m;        /* points with rho > 0 */
} an_dda_info;

/* Bytes an_dda_compute needs for n points and K, about. */
double an_dda_bytes(size_t n, int K, double radius);

/* 0 when an_dda_bytes(n, K, radius) fits in 0.9 `have` bytes; else -1
 * with one line in err naming the need and what there is. */
int an_dda_check_memory(size_t n, int K, double radius, double have, char *err, size_t errlen);

/* S: (2K+1)^2 doubles in power.h's layout. n >= 2, 1 <= K <= AN_KMAX,
 * radius 0 or in [1, 64]. 0, or -1 with one line in err (bad request, no
 * point on the support, out of memory). info may be NULL. */
int an_dda_compute(const cfpo_density *d, const double *xy, size_t n, int K, double radius, double *S,
                   an_dda_info *info, char *err, size_t errlen);

/* The window's transform What at |k|^2 = k2 (units of the torus). */
double an_dda_window_ft(double k2, double radius, size_t n);

/* The summary of a spectrum S of n points: the highest ring mean (rings
 * of rings.h) and its ring over sqrt(n), the mean of S over the
 * low-frequency band 0 < |k| <= 0.2 sqrt(n) (src/solver/geom.h), and the mean
 * anisotropy (dB) over the rings 0.5 sqrt(n)..2 sqrt(n) within K. */
typedef struct {
    double peak, peak_freq, low, aniso_db;
    int peak_ring;
} an_dda_summary;
int an_dda_summarise(const double *S, int K, size_t n, an_dda_summary *out);

/* dda_raps.txt: ring, ring / sqrt(n), radial mean, anisotropy (dB),
 * frequencies on the ring; '#' lines say what it is. 0, or -1 with err. */
int an_dda_write_raps(const char *path, const double *S, int K, size_t n, int sets, double radius, char *err,
                      size_t errlen);

#endif
