/* discrepancy.h - five L2 discrepancies of a point set in [0, 1)^2, exact,
 * in O(n log n) time.
 *
 * Owns: the definitions (d = 2, sums over all ordered pairs i, j, i = j
 * included; analysis/README.md gives the references):
 *   wrap-around L2^2   = -(4/3)^2 + n^-2 sum_ij prod_k (3/2 - |d_k| + d_k^2),
 *                        d_k = x_ik - x_jk  (Hickernell 1998; torus-invariant)
 *   diaphony^2         = [n^2 ((1 + pi^2/3)^2 - 1)]^-1
 *                        sum_ij [prod_k (1 + 2 pi^2 B2({d_k})) - 1],
 *                        B2(t) = t^2 - t + 1/6 (Zinterhof 1976, normalised
 *                        as UTK's Diaphony.hpp; torus-invariant)
 *   L2-star^2          = 3^-2 - (2^-1/n) sum_i prod_k (1 - x_ik^2)
 *                        + n^-2 sum_ij prod_k (1 - max(x_ik, x_jk))
 *   generalised L2^2   = (4/3)^2 - (2/n) sum_i prod_k (3 - x_ik^2)/2
 *                        + n^-2 sum_ij prod_k (2 - max(x_ik, x_jk))
 *   centred L2^2       = (13/12)^2 - (2/n) sum_i prod_k (1 + |u_ik|/2 - u_ik^2/2)
 *                        + n^-2 sum_ij prod_k (1 + |u_ik|/2 + |u_jk|/2 - |u_ik - u_jk|/2),
 *                        u = x - 1/2
 * and their computation. Every value is reported as the square root of the
 * formula (scipy.stats.qmc.discrepancy returns L2-star rooted but the
 * centred and wrap-around ones squared; UTK roots all of them).
 *
 * How: each pair sum is a sum of products of per-axis terms that are
 * polynomials in min(a_i, a_j), |d| and d^2. Sums over pairs of one axis
 * need one sort; sums of a product over both axes (min(a) min(b), |dx||dy|)
 * need a sort by one axis and a Fenwick tree of moments over the ranks of
 * the other (dominance sums); d^2 terms are moment sums. Everything is
 * accumulated in an_quad (quad.h), so the cancellation of the O(1) terms
 * down to a result near n^-2 costs about 40 of its 113 bits. */
#ifndef AN_DISCREPANCY_H
#define AN_DISCREPANCY_H

#include <stddef.h>

typedef struct {
    double wrap_l2, diaphony, l2_star, generalized_l2, centred_l2; /* square roots */
} an_discrepancy;

/* Bytes an_discrepancy_compute allocates at most for n points. */
double an_discrepancy_bytes(size_t n);

/* Coordinates in [0, 1), n >= 1 (fewer than 2^32). 0, or -1 with a message
 * (out of memory, bad n). Runs the torus-invariant two and the other three
 * on two OpenMP threads when allowed (n >= 4,096); the result does not
 * depend on the number of threads. */
int an_discrepancy_compute(const double *xy, size_t n, an_discrepancy *d, char *err, size_t errlen);

#endif
