/* measures3_vor.h - the Voronoi cells of a set on the unit 3-torus, from
 * CGAL's Periodic_3_Delaunay_triangulation_3 (built only where CGAL is:
 * CFPO_HAVE_CGAL).
 *
 * Owns: each point's Voronoi cell as its faces (one per Delaunay edge; a
 * face's vertices the circumcentres of the cells around the edge, in
 * circulation order, taken relative to the point so that periodic images
 * agree), its face count (faces of area above 1e-9 of the mean cell's
 * face scale (1/n)^(2/3): the zero-area faces of co-spherical points, as
 * in FCC and simple cubic lattices, are not counted), its volume and
 * centroid (a fan of tetrahedra from the point over each face). The
 * volumes sum to 1. Used by cfpo3d-analyze --voronoi and by 3-D Lloyd
 * (baselines). */
#ifndef CFPO_MEASURES3_VOR_H
#define CFPO_MEASURES3_VOR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* p: n points in [0,1)^3, distinct. Any output may be NULL: faces[n],
 * volume[n], centroid[3n] (in [0,1)). 0, or -1 with a message (duplicates,
 * a set too small or too uneven for CGAL's one-sheeted periodic
 * triangulation, memory). */
int cfpo3_voronoi(const double *p, size_t n, int *faces, double *volume, double *centroid, char *err,
                  size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
