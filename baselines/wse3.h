/* wse3.h - weighted sample elimination (Cem Yuksel, "Sample Elimination for
 * Generating Poisson Disk Sample Sets", Computer Graphics Forum 34(2),
 * Eurographics 2015) on the periodic unit cube.
 *
 * Owns the algorithm as the paper gives it for three dimensions:
 *  - candidates: ratio * N uniform points (the paper's default ratio 5);
 *  - r_max = (V / (4 sqrt(2) N))^(1/3) for N output points in volume V = 1
 *    (the paper's 3-D bound; 2 r_max = Delta3(N), the FCC spacing),
 *    d_max = 2 r_max;
 *  - pair weight w_ij = (1 - d^_ij / d_max)^alpha for d_ij < d_max
 *    (alpha = 8), a sample's weight the sum over its neighbours (wse.h's
 *    fixed-point wse_pair_weight, so the order of additions does not
 *    matter and the brute-force test gives the same order bit for bit);
 *  - weight limiting (the paper's default, beta = 0.65, gamma = 1.5):
 *    d^_ij = max(d_ij, d_min), d_min = d_max (1 - (N/M)^gamma) beta;
 *  - elimination: the heaviest sample is removed (ties: the larger index),
 *    its neighbours' weights lowered by their pair weight, until N remain
 *    (a max-heap);
 *  - periodic tiling: distances between all periodic images; one image is
 *    within d_max of another when d_max <= 1/3 (a grid of cells at least
 *    d_max wide), all images in [-2, 2]^3 are summed otherwise.
 * The survivors keep the candidates' (random) order. */
#ifndef CFPO_BASELINES_WSE3_H
#define CFPO_BASELINES_WSE3_H
#include <stddef.h>
#include <stdint.h>

/* d_max = Delta3(N) for N output points on the unit cube. */
double wse3_dmax(size_t N);
/* d_min of weight limiting for N kept of M (0 when limit is 0). */
double wse3_dmin(size_t N, size_t M, int limit);
/* The elimination of the M points xyz down to n (1 <= n <= M): keep[0..n)
 * the kept points' indices, increasing. 0, or -1 when out of memory. */
int wse3_order(const double *xyz, size_t M, size_t n, double alpha, int limit, size_t *keep);
/* n points: ceil(ratio * n) white-noise candidates from seed, eliminated
 * (out: 3n doubles). 0, or -1 with a message. */
int wse3_points(int64_t n, uint64_t seed, double ratio, double alpha, int limit, double *out, char *err,
                size_t errlen);
#endif
