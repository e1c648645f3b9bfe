/* capacity.h - the capacity of each point of a set under a density: the
 * integral of rho (mean 1 on the torus) over the point's Voronoi cell, the
 * quantity capacity-constrained methods (CCVT, BNOT) make equal to 1/n.
 *
 * Owns the Voronoi cells' exchange format (filled from the periodic
 * Delaunay triangulation, analysis/measures/delaunay.h) and the exact
 * integral of a piecewise-constant density over a polygon, by Green's
 * theorem: the integral over the cell is the contour integral of
 * F(x, y) = int_0^x rho(t, y) dt along its boundary (dy), F linear in x
 * inside each pixel, so the boundary cut at the pixels' edges gives it
 * exactly (up to rounding) with work proportional to the perimeter in
 * pixels, not the area. F is continued past x = 1 by the row's sum, and a
 * closed contour's integral of a function of y alone is 0: a cell may
 * cross the torus' edges. The capacity deviation is std / mean of the
 * capacities over the points (the mean is 1/n: the cells tile the
 * torus); with rho = 1 it is the square root of the Voronoi area
 * variance of the Delaunay measures. */
#ifndef AN_CAPACITY_H
#define AN_CAPACITY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#include "density.h"

typedef struct {
    size_t n;
    size_t *start; /* cell i: vertices start[i] .. start[i+1]) */
    double *v;     /* x, y of each vertex, counter-clockwise, unwrapped:
                      near the cell's point, possibly outside [0, 1) */
} an_vcells;

void an_vcells_free(an_vcells *c);

/* The integral of rho over the polygon of m vertices v (x, y pairs,
 * counter-clockwise; negative if clockwise). */
double an_capacity_polygon(const cfpo_density *d, const double *v, size_t m);

/* cap[i] = the integral of rho over cell i, for every cell. 0, or -1 when
 * out of memory. */
int an_capacity_compute(const cfpo_density *d, const an_vcells *c, double *cap);

/* std / mean of n values (population std): sqrt(n sum c^2 / (sum c)^2 - 1). */
double an_capacity_deviation(const double *cap, size_t n);

#ifdef __cplusplus
}
#endif
#endif
