/* sobol.h - the first n points of the two-dimensional Sobol' sequence, a
 * (0,2)-sequence in base 2, unscrambled or Owen-scrambled.
 *
 * Owns: the generator matrices of the sequence's first two coordinates
 * (the identity, i.e. van der Corput's radical inverse, and the Pascal
 * matrix mod 2 of the primitive polynomial x + 1), point i in natural
 * order (not Gray-code order), and nested uniform scrambling (Owen 1995)
 * of the first 32 binary digits of each coordinate: digit j of a
 * coordinate is flipped by a random bit that depends on the seed, the
 * coordinate, j and every digit before j, i.e. one independent bit per
 * node of the binary tree of elementary intervals (hash-based, as Laine
 * and Karras 2011 and Burley 2020 compute it, but with a full hash per
 * node, so the scramble is Owen's, not a linear matrix scramble). The
 * digits past the 32nd are uniform random bits (Owen's scramble of the
 * infinite digit tail), so every coordinate has 53 random bits.
 * Does not own: the run loop, files (bl_direct.c, bl_cli.c). */
#ifndef CFPO_BASELINES_SOBOL_H
#define CFPO_BASELINES_SOBOL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The 32-digit integers of unscrambled point i: x = the bit reversal of i,
 * y = the Pascal matrix mod 2 times i's digits. The point is
 * (x, y) * 2^-32. */
void sobol_point(uint32_t i, uint32_t *x, uint32_t *y);

/* Owen's nested uniform scramble of a 32-digit value v of coordinate dim
 * (0 or 1) under seed: digit j (from the most significant) is flipped by
 * the bit of the node (j, the j leading digits of v). */
uint32_t sobol_owen(uint32_t v, uint64_t seed, int dim);

/* The first n points (x0 y0 x1 y1 ...) into xy: scrambled with seed when
 * scramble is 1 (with 21 uniform bits below the 32 scrambled digits),
 * the plain points otherwise. */
void sobol_points(int64_t n, uint64_t seed, int scramble, double *xy);

#ifdef __cplusplus
}
#endif
#endif
