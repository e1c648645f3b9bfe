/* dens_start.h - layer 2: the start of a run under a density: exactly n
 * points, none on a zero-density pixel, their counts following the
 * density. The pixels are ordered along a Hilbert curve; point k takes the
 * mass (k + u_k) / n of the total along that order (systematic sampling,
 * u_k uniform from the seed), lands in the pixel holding that mass, at a
 * uniform place inside it. Any stretch of the curve then holds its mass
 * times n points, to within one.
 * Owns: the Hilbert order and the systematic sampling. */
#ifndef CFPO_DENS_START_H
#define CFPO_DENS_START_H

#include <stdint.h>

#include "density.h"

/* The pixels of positive density in the order of cfpo_hilbert (hilbert.h)
 * on the s x s grid that holds the raster (s the least power of 2 at
 * least w and h), found by walking the curve, not by sorting: into pix (w
 * h entries); returns their count. */
int64_t cfpo_dens_hilbert_order(const cfpo_density *d, uint32_t *pix);

/* xy: 2 n doubles. 0, or -1 when out of memory. */
int cfpo_dens_start(const cfpo_density *d, int64_t n, uint64_t seed, double *xy);

#endif
