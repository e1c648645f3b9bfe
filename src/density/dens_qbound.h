/* dens_qbound.h - layer 2: an upper bound of q = sqrt(rho) over a box of
 * the torus, for the local solve's prunings (dens_solve.h).
 *
 * The solve abandons a polygon or a vertex when even the largest q its
 * spot can have cannot lift it above the best value found. With the
 * density's global maximum for that q, the bound is loose wherever rho is
 * below its maximum (4.4x at the trough of cos a=0.9), and little is
 * pruned there. A pyramid of maxima (level 0 the pixels' q, each level
 * above the max of 2 x 2 texels of the one below) gives the largest q
 * over the pixels a box touches in at most 16 reads. Any spot the solve
 * evaluates in the box reads one of those pixels (the box is widened by
 * one pixel each side against rounding), so the bound holds bit for bit
 * and the solve's result does not change; only its work does.
 * The same pyramid of minima (over the non-zero pixels: no point sits on
 * a zero-density pixel) bounds q from below, for the measure's search
 * (dens_measure.c): how far a point must look before no unvisited point
 * can come nearer in the measure.
 * Where q is flat within CFPO_QBOUND_FLAT over the whole density, the
 * query answers the density's own largest (smallest non-zero) q: a bound
 * as good to within that ratio, with no read of the pyramid.
 * Owns: the pyramids and their box query. */
#ifndef CFPO_DENS_QBOUND_H
#define CFPO_DENS_QBOUND_H

#include <stdint.h>

#include "density.h"

#define CFPO_QBOUND_LEVELS 24
#define CFPO_QBOUND_FLAT 1.02

typedef struct {
    const cfpo_density *d; /* level 0 */
    int levels;
    int lowest; /* 0: maxima (floats rounded up); 1: minima over the non-zero pixels (rounded down) */
    double flat; /* > 0: the answer to every query (q flat within CFPO_QBOUND_FLAT) */
    int64_t w[CFPO_QBOUND_LEVELS], h[CFPO_QBOUND_LEVELS];
    float *q[CFPO_QBOUND_LEVELS]; /* level l >= 1: w[l] x h[l] texels, row after row, each at least its max
                                     (at most its min) */
} cfpo_dens_qbound;

/* Builds the pyramid of d (which must outlive it); 0, or -1 when out of
 * memory (nothing held). */
int cfpo_dens_qbound_build(cfpo_dens_qbound *b, const cfpo_density *d);

/* The pyramid of minima of q over the non-zero pixels (+inf where a
 * texel covers none); the same ownership and result. */
int cfpo_dens_qbound_build_min(cfpo_dens_qbound *b, const cfpo_density *d);

/* The largest q over the pixels that the torus points of [x0, x1] x [y0,
 * y1] fall in (x0 <= x1, y0 <= y1, any reals: the box is taken modulo 1);
 * for a pyramid of minima, at most the smallest non-zero q there. */
double cfpo_dens_qbound_box(const cfpo_dens_qbound *b, double x0, double y0, double x1, double y1);
/* The same read from `finer` levels further down the pyramid (at most
 * (2^(finer + 1) + 1)^2 texels a range instead of 2 x 2): a tighter bound, for
 * a caller whose work it prunes outweighs the reads. */
double cfpo_dens_qbound_box_finer(const cfpo_dens_qbound *b, double x0, double y0, double x1, double y1, int finer);

void cfpo_dens_qbound_free(cfpo_dens_qbound *b);

#endif
