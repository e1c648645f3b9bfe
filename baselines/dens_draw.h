/* dens_draw.h - random points drawn with probability proportional to a
 * density (src/density/density.h), for the baselines' --density starts and darts.
 *
 * Draw k: the uniform point (u0, u1) the caller's uniform method would
 * use, kept with probability rho(x) / rho_max (a third number u2); when it
 * is thinned away, a point from the exact inverse CDF over the pixels
 * (u3 picks the pixel by its mass, u4, u5 the place inside it). The first
 * branch has density rho / rho_max, the second is taken with probability
 * 1 - 1 / rho_max (rho has mean 1) and has density rho: together rho,
 * exactly. So every draw costs O(log pixels) at most, whatever the
 * contrast or support, and for a uniform density (rho = 1 everywhere) a
 * draw is the caller's uniform point itself: its bytes are unchanged.
 * Owns: the pixels' cumulative masses and the draw. Does not own: the
 * density (density.c), the random numbers' streams (each caller's). */
#ifndef CFPO_BASELINES_DENS_DRAW_H
#define CFPO_BASELINES_DENS_DRAW_H

#include <stdint.h>

#include "density.h"

typedef struct {
    const cfpo_density *d;
    double *cum;    /* w h + 1 partial sums of rho, cum[0] = 0 */
} dens_draw;

/* 0, or -1 when out of memory. */
int dens_draw_init(dens_draw *s, const cfpo_density *d);
void dens_draw_free(dens_draw *s);

/* The point for uniform numbers u[0..5] in [0, 1) (u[0], u[1]: the
 * uniform candidate's x, y). Always lands on a pixel with rho > 0. */
void dens_draw_point(const dens_draw *s, const double u[6], double *x, double *y);

/* The same with u[0], u[1] = *x, *y (the caller's uniform point, replaced
 * by the draw) and u[2 + j] = cfpo_rand01(seed, stream, 4 k + j): draw k
 * of a caller's stream. */
void dens_draw_at(const dens_draw *s, uint64_t seed, uint64_t stream, uint64_t k, double *x, double *y);

#endif
