/* prog_herd.h - layer 4: the order of a small progressive level's points
 * (progressive.h), paced as prog_order.h's and herded: among the points
 * the quadtree's allowances leave free and that keep the prefix's
 * nearest distance at or above a floor (CFPO_PROG_HERD_FLOOR Delta(m),
 * or the farthest free point's distance where that is less), next the
 * one that adds the least to a smooth low-frequency energy of the prefix.
 *
 * The energy of a set X is sum over 0 < |k| <= R of |k|^-3 |S(k)|^2,
 * S(k) = sum over x in X of exp(2 pi i k . x), k integer: the power of
 * the set's lowest frequencies, weighted as the squared Fourier transform
 * of the indicator of any region with a smooth boundary falls (|k|^-3,
 * on average over directions). Adding point x to X adds 2 phi(x) + K(0),
 * phi(x) = sum over y in X of K(x - y) with the periodic kernel K(d) =
 * sum over 0 < |k| <= R of |k|^-3 cos(2 pi k . d); so the point with the
 * least phi fills the largest long-wavelength deficit (kernel herding,
 * Chen, Welling and Smola 2010). R = CFPO_PROG_HERD_FREQ sqrt(m1): the
 * frequencies well below the prefix's blue-noise ring (about 0.93
 * sqrt(m)).
 *
 * O(q m1 R^2) for a level of q = m1 - m0 new points: for the small levels
 * (m1 <= CFPO_PROG_HERD_MAX) only. Serial: the same bytes always.
 * May include: prog_order.h (layer 4, the quadtree's depth). */
#ifndef CFPO_PROG_HERD_H
#define CFPO_PROG_HERD_H

#include <stddef.h>
#include <stdint.h>

#define CFPO_PROG_HERD_MAX 1024  /* the levels herded: those of at most this many points */
#define CFPO_PROG_HERD_FLOOR 0.68 /* a candidate's distance to the points before it: at least this Delta(m) */
#define CFPO_PROG_HERD_FREQ 0.5  /* the energy's frequencies: |k| <= this sqrt(m1) */

/* The kernel's frequency radius R for a level ending at m1 points. */
double cfpo_prog_herd_radius(int64_t m1, double freq);

#define CFPO_PROG_HERD_KMAX 64 /* the kernel's frequencies: at most this per axis (R <= 64 exact) */

/* The kernel's weights for a radius R: w[i (KMAX + 1) + j] = 2^[i > 0]
 * 2^[j > 0] (i^2 + j^2)^-1.5 for 0 < i^2 + j^2 <= R^2 (else 0), bmax[i]
 * the largest j with a weight in row i (-1: none), kc = min(floor(R), KMAX). */
typedef struct {
    int kc;
    int bmax[CFPO_PROG_HERD_KMAX + 1];
    double w[(CFPO_PROG_HERD_KMAX + 1) * (CFPO_PROG_HERD_KMAX + 1)];
} cfpo_prog_herd_tab;

void cfpo_prog_herd_table(double R, cfpo_prog_herd_tab *T);

/* K(a - b) for the table's radius (above). Symmetric in its arguments only
 * up to rounding: callers that must agree call it with the same order. */
double cfpo_prog_herd_kernel(const double *a, const double *b, const cfpo_prog_herd_tab *T);

/* Points m0 .. m1 - 1 of xy reordered in place: at step t, the free points
 * are the untaken ones none of whose quadtree cells (the paced order's of
 * prog_order.h: depth cfpo_prog_order_depth(m1, per_cell)) has given
 * floor((t + 1) c / q) + tol of its c of the q new points; of those, the
 * candidates are the ones whose distance to the first m0 and the points
 * taken is at least min(dfloor Delta(m), the largest among the free),
 * Delta(m) = sqrt(2 / (sqrt(3) m)), m = m0 + t + 1 the prefix the pick
 * makes; next the candidate with the least phi over the same points
 * (summed in their order; ties: the larger distance, then the lower
 * index). A prefix's delta_min in its own units so stays at or above
 * dfloor, or where the paced choice would leave it. 0, or -1 with one
 * line in err (out of memory, tol < 1, per_cell <= 0, dfloor < 0,
 * freq <= 0). */
int cfpo_prog_order_herded(double *xy, int64_t m0, int64_t m1, double per_cell, int tol, double dfloor, double freq,
                           char *err, size_t errlen);

#endif
