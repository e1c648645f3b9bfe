/* wse.h - weighted sample elimination (Cem Yuksel, "Sample Elimination for
 * Generating Poisson Disk Sample Sets", Computer Graphics Forum 34(2),
 * Eurographics 2015) on the periodic unit square, and its progressive order.
 *
 * Owns the algorithm, as the paper gives it:
 *  - candidates: ratio * n uniform points (the paper's default ratio 5);
 *  - r_max = sqrt(A / (2 sqrt(3) N)) for N output points in area A = 1 (the
 *    paper's bound for 2-D; 2 r_max = Delta(N)), d_max = 2 r_max;
 *  - weight of a pair w_ij = (1 - d^_ij / d_max)^alpha for d_ij < d_max
 *    (alpha = 8), each sample's weight the sum over its neighbours;
 *  - weight limiting (the paper's default, beta = 0.65, gamma = 1.5):
 *    d^_ij = max(d_ij, d_min), d_min = d_max (1 - (N/M)^gamma) beta, M the
 *    samples the elimination starts from; off: d^_ij = d_ij;
 *  - elimination: the sample of largest weight is removed, its neighbours'
 *    weights lowered by their pair weight, until N remain (a max-heap);
 *  - periodic domain (the paper's tiling): distances between all periodic
 *    images; at most one image of a sample is within d_max of another when
 *    d_max <= 1/3 (a grid of cells at least d_max wide), all images are
 *    summed when d_max is larger (a handful of points);
 *  - progressive order: after the elimination to n, the survivors are
 *    eliminated again to n/2 (integer halves) with d_max and d_min for that
 *    size, then to n/4, ... down to 1; each eliminated part is placed behind
 *    the survivors, the later-eliminated first, so that every prefix of
 *    size n / 2^k is the set left at that stage.
 * Weights are sums of fixed-point terms (units of 2^-40), so the order of
 * the additions and subtractions does not change a weight, and the brute-force
 * reference of the tests gives the same order bit for bit. Ties of weight:
 * the larger candidate index is eliminated first. Without the progressive
 * order the survivors keep the candidates' (random) order. */
#ifndef CFPO_BASELINES_WSE_H
#define CFPO_BASELINES_WSE_H
#include <stddef.h>
#include <stdint.h>

#define WSE_RATIO 5.0
#define WSE_ALPHA 8.0
#define WSE_BETA 0.65
#define WSE_GAMMA 1.5
#define WSE_UNIT 1099511627776.0 /* 2^40: weights in these units */

typedef struct {
    double alpha;
    int weight_limit;
    int progressive;
} wse_params;

/* d_max for N output points on the unit square. */
double wse_dmax(size_t N);
/* The fixed-point weight of a pair at squared distance q (0 at or beyond d_max). */
int64_t wse_pair_weight(double q, double dmax, double dmin, double alpha);
/* The elimination of the M points xy down to n (1 <= n <= M): order[0..n)
 * the kept points' indices in the output order. 0, or -1 when out of memory. */
int wse_order(const double *xy, size_t M, size_t n, const wse_params *p, size_t *order);
/* n points: ceil(ratio * n) white-noise candidates from seed, eliminated
 * (out: 2n doubles). 0, or -1 with a message. */
int wse_points(int64_t n, uint64_t seed, double ratio, const wse_params *p, double *out, char *err, size_t errlen);
#endif
