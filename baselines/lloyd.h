/* lloyd.h - Lloyd's algorithm (Lloyd 1982) on the unit torus: every site
 * moves to the centroid of its Voronoi cell, towards a centroidal Voronoi
 * tessellation (CVT), on CGAL's periodic Delaunay triangulation.
 *
 * Owns: the engine (uniform random start; an iteration triangulates the
 * sites, takes each site's Voronoi cell as the polygon of the circumcentres
 * of its incident faces in counter-clockwise order, and moves every site
 * at once to that polygon's centroid, wrapped into [0, 1)); the iteration
 * statistics; converged when no site moved tol * L (L cfpo's cell side),
 * or after `iterations` steps when that is not 0 (the benchmark's cap).
 * Does not own: the run loop and its stop rules (bl_loop.c), files.
 * A C interface over a C++ implementation (CGAL). */
#ifndef CFPO_BASELINES_LLOYD_H
#define CFPO_BASELINES_LLOYD_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct lloyd_engine lloyd_engine;

/* Bytes for n sites (the triangulation as FPO's, rebuilt every iteration). */
double lloyd_bytes(int64_t n);

/* LLOYD_ITERATIONS: the default cap, as the blue-noise comparisons stop
 * Lloyd before the hexagonal CVT. */
#define LLOYD_ITERATIONS 100

/* The uniform start; NULL with a message (n too small for cfpo's grid,
 * coincident points, out of memory). */
lloyd_engine *lloyd_create(int64_t n, uint64_t seed, double tol, int iterations, char *err, size_t errlen);
void lloyd_free(lloyd_engine *E);

/* One Lloyd step of every site; fills everything but s->iteration. */
void lloyd_iterate(lloyd_engine *E, cfpo_iter_stats *s);

void lloyd_deltas(lloyd_engine *E, double *dmin, double *davg);
const double *lloyd_points(const lloyd_engine *E);

/* The Voronoi cells of the current sites: area[i] and the centroid
 * (cx[i], cy[i]) (unwrapped, near site i); 0, or -1 when coincident sites
 * leave a cell undefined. For tests and the step itself. */
int lloyd_cells(const lloyd_engine *E, double *area, double *cx, double *cy);

#ifdef __cplusplus
}
#endif
#endif
