/* coverage.h - the covering radius of a point set on the unit torus: the
 * largest distance from any point of the torus to its nearest sample. It is
 * the largest circumradius of the periodic Delaunay triangulation (every
 * local maximum of the distance function is a Voronoi vertex, i.e. a
 * circumcentre), computed on CGAL's Periodic_2_Delaunay_triangulation_2
 * with exact predicates. A set is maximal for radius r exactly when its
 * covering radius is at most r. Used by the tests and by nothing else. */
#ifndef CFPO_BASELINES_COVERAGE_H
#define CFPO_BASELINES_COVERAGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* xy: n points (x0 y0 x1 y1 ...) in [0,1)^2, n >= 1, pairwise distinct.
 * Returns the covering radius, or -1 when the points are not distinct. */
double bl_covering_radius(const double *xy, size_t n);

#ifdef __cplusplus
}
#endif
#endif
