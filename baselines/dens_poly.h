/* dens_poly.h - exact integrals of a piecewise-constant density
 * (src/density/density.h) over polygons and along segments of the plane, the
 * density continued periodically beyond the unit torus: what BNOT under a
 * density needs of its power cells (bnot_power.cpp).
 *
 * Owns: the per-row prefix sums of rho, rho x and rho x^2 and the two
 * integrals. Polygon: Green's theorem, int int g dA = closed int G dy with
 * dG/dx = g, for g = rho, rho u, rho v, rho (u^2 + v^2) about a point p
 * (u = x - p_x, v = y - p_y); G is continuous in x along each pixel row
 * and its y-dependent constant drops out of a closed path, so each edge is
 * cut where it crosses a pixel column or row, and on each piece (one
 * pixel) G is a polynomial of degree <= 3 in the edge's parameter,
 * integrated exactly by the two-point Gauss rule. Segment: the sum of each
 * piece's rho times its length. The analysis's capacity (analysis/capacity.c)
 * gives the mass the same way; both cut their edges with
 * cfpo_density_walk (src/density/density_walk.h).
 * Does not own: the density (density.c), the cells (bnot_power.cpp). */
#ifndef CFPO_BASELINES_DENS_POLY_H
#define CFPO_BASELINES_DENS_POLY_H

#include <stddef.h>

#include "density.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const cfpo_density *d;
    double *pre; /* 3 (w + 1) h: row j, order l: pre[(3 j + l) (w + 1) + i] =
                  * int_0^{i/w} rho(s, row j) s^l ds */
} dens_poly;

/* 0, or -1 when out of memory. */
int dens_poly_init(dens_poly *t, const cfpo_density *d);
void dens_poly_free(dens_poly *t);

/* The polygon's k vertices (v: xy interleaved, counter-clockwise,
 * relative to p = (px, py), absolute coordinates p + v anywhere in the
 * plane): out[0] = int rho dA (the mass), out[1], out[2] = int rho u dA,
 * int rho v dA, out[3] = int rho (u^2 + v^2) dA. Signed: a clockwise
 * polygon gives the negatives. */
void dens_poly_moments(const dens_poly *t, double px, double py, const double *v, size_t k, double out[4]);

/* int rho ds along the segment (x0, y0) -> (x1, y1) (absolute coordinates,
 * anywhere in the plane). */
double dens_poly_segment(const dens_poly *t, double x0, double y0, double x1, double y1);

#ifdef __cplusplus
}
#endif
#endif
