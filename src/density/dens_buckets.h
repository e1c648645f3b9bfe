/* dens_buckets.h - layer 2: the bucket grid of one 3 x 3 block of the
 * density engine (dens_engine.c), so that a point's neighbour queries look
 * at the points near it instead of the whole block.
 *
 * Under a density the engine's cells are sized to the sparsest spacing, so
 * a block in a dense region holds up to (r_max / r_min)^2 times more points
 * than its spacing needs; scanning the whole block for every point made an
 * iteration cost grow with the block's count squared. The block's points
 * (local frame, coordinates in [x0, x0 + B h)) are kept in B x B buckets of
 * side h; a query scans rings of buckets around a position, ring k holding
 * the buckets at Chebyshev distance k, and every point not yet scanned after
 * ring k is at least k h away. With `wrap` (the block is the whole torus,
 * B h = 1) the rings are periodic and stop at half the grid.
 * Owns: bucket membership (linked lists, updated when a point moves) and
 * the ring enumeration. */
#ifndef CFPO_DENS_BUCKETS_H
#define CFPO_DENS_BUCKETS_H

#include <stddef.h>

typedef struct {
    int B, wrap;
    double x0, y0, h;
    int *head, *next; /* head[bucket]: first point (-1: none); next[point] */
    size_t cap_b, cap_m;
} cfpo_dens_buckets;

/* Fills the grid with the m points (x, y) over the square [x0, x0 + side)
 * x [y0, y0 + side), about `per` points a bucket on average. 0, or -1 when
 * out of memory. */
int cfpo_dens_buckets_build(cfpo_dens_buckets *b, const double *x, const double *y, int m, double x0, double y0,
                            double side, int wrap, double per);

/* The bucket (row-major) of position (x, y), clamped to the grid. */
int cfpo_dens_bucket_of(const cfpo_dens_buckets *b, double x, double y);

/* Moves point p from bucket `from` to bucket `to`. */
void cfpo_dens_buckets_move(cfpo_dens_buckets *b, int p, int from, int to);

/* The buckets of ring k around bucket c into out (at most 8 k + 1 of
 * them); their count, or -1 when rings 0..k-1 already held every bucket.
 * With wrap a bucket may come twice once 2 k + 1 > B (harmless to the
 * minima the engine takes over rings). */
int cfpo_dens_ring(const cfpo_dens_buckets *b, int c, int k, int *out);

/* The first and count of the bucket columns (or rows) that cover
 * [lo, hi) on one axis, each once (with wrap, taken modulo B). */
void cfpo_dens_span(const cfpo_dens_buckets *b, double lo, double hi, double origin, int *first, int *count);

void cfpo_dens_buckets_free(cfpo_dens_buckets *b);

#endif
