/* jitter.h - the two independent random samplers of the suite: white
 * noise (n uniform points) and jittered sampling (one uniform point in
 * each of n strata).
 *
 * Owns: the points of both from (n, seed) by counter-based random numbers
 * (rng.h), and the strata of the jittered set for any n: r = round(sqrt(n))
 * rows of height 1/r, row k split into c_k = floor((k+1) n / r) -
 * floor(k n / r) equal cells (c_k is floor(n/r) or its ceiling), so every
 * stratum holds exactly one point and the areas differ by at most one
 * part in floor(n/r); for n = m^2 the plain m x m jitter.
 * Does not own: the run loop, files (bl_direct.c, bl_cli.c). */
#ifndef CFPO_BASELINES_JITTER_H
#define CFPO_BASELINES_JITTER_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* n uniform points (x0 y0 x1 y1 ...) into xy. */
void white_points(int64_t n, uint64_t seed, double *xy);

/* The number of rows of the jittered strata for n. */
int64_t jitter_rows(int64_t n);

/* The strata of row k: [first, first + count) of the n points, in rows
 * of height 1 / jitter_rows(n). */
void jitter_row(int64_t n, int64_t k, int64_t *first, int64_t *count);

/* The jittered set: point first + c of row k uniform in the stratum
 * [c/count, (c+1)/count) x [k/r, (k+1)/r). */
void jitter_points(int64_t n, uint64_t seed, double *xy);

#ifdef __cplusplus
}
#endif
#endif
