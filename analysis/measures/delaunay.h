/* delaunay.h - measures of a point set on the unit torus from its periodic
 * Delaunay triangulation (CGAL's Periodic_2_Delaunay_triangulation_2,
 * exact predicates, baselines/cgal_types.h): one triangulation gives all.
 *
 * Owns the definitions (analysis/README.md gives the references):
 *   psi6        bond-orientational order as psa computes it (Schloemer and
 *               Deussen): for each site i with Delaunay neighbours
 *               v_1..v_m in circular order, z_i = sum_j exp(6 i arg(v_j -
 *               v_{j+1})) (v_{m+1} = v_1); psi6 = sum_i |z_i| / sum_i m_i.
 *               1 on the hexagonal lattice; about 0.365 for white noise.
 *   area_var    the variance of the Voronoi cell areas A_i over the squared
 *               mean area (the mean is 1/n on the torus): n sum_i A_i^2 - 1.
 *               0 on any lattice.
 *   covering    the covering radius h: the largest distance from a point of
 *               the torus to its nearest sample, the largest circumradius of
 *               the triangles (every local maximum of the distance to the
 *               set is a Voronoi vertex).
 *   mesh_ratio  h / q with q = delta_min / 2 the separation radius
 *               (delta_min the shortest distance, a Delaunay edge):
 *               2 h / delta_min; 2 / sqrt(3) on the hexagonal lattice, the
 *               least any set can have.
 * The Voronoi cells and the circumcentres are computed in double from the
 * exact triangulation; the cells themselves (capacity.h) on request, for
 * the capacities under a density. */
#ifndef AN_DELAUNAY_H
#define AN_DELAUNAY_H

#include <stddef.h>

#include "capacity.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double psi6, area_var, covering, delta_min, mesh_ratio; /* covering, delta_min: absolute */
} an_delaunay;

/* Bytes the triangulation of n points needs, about. */
double an_delaunay_bytes(size_t n);

/* Coordinates in [0, 1), n >= 1. 0; or -1 with a message when the points
 * are not distinct or too few or too clustered for a triangulation of the
 * torus itself (CGAL's 1-sheeted cover), or out of memory. */
int an_delaunay_compute(const double *xy, size_t n, an_delaunay *out, char *err, size_t errlen);

/* The same, and each point's Voronoi cell into cells (an_vcells_free
 * frees it; left empty on failure). */
int an_delaunay_compute_cells(const double *xy, size_t n, an_delaunay *out, an_vcells *cells, char *err,
                              size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
