/* density_walk.h - layer 2 (includes density.h): a segment of the plane cut
 * at a density's pixel grid, the density continued periodically beyond the
 * unit torus. What the exact integrals of a piecewise-constant density over
 * polygons and along segments walk: the analysis' capacities
 * (analysis/capacity.c) and BNOT under a density (baselines/dens_poly.c).
 * Owns: the cut. Does not own: what is integrated on each piece. */
#ifndef CFPO_DENSITY_WALK_H
#define CFPO_DENSITY_WALK_H

#include <stdint.h>

#include "density.h"

/* One piece of the segment inside one pixel: parameters [t0, t1] of the
 * segment, the pixel's global column i and row j (any integers; the density
 * repeats: cfpo_density_wrap_index gives the pixel on the torus). */
typedef void (*cfpo_pixel_piece_fn)(void *ctx, double t0, double t1, int64_t i, int64_t j);

/* The segment (x0, y0) + t (dx, dy), t in [0, 1], cut at every pixel column
 * and row of d, each piece of positive length passed to fn in order of t;
 * the pixel of a piece is that of its midpoint. */
void cfpo_density_walk(const cfpo_density *d, double x0, double y0, double dx, double dy, cfpo_pixel_piece_fn fn,
                       void *ctx);

/* floor(a / b) for b > 0. */
static inline int64_t cfpo_floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

#endif
