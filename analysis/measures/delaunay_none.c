/* delaunay_none.c - delaunay.h in a build without CGAL (CMakeLists.txt,
 * CFPO_HAVE_CGAL off): no triangulation, so no Delaunay measures and no
 * Voronoi cells. cfpo-analyze then runs as with --no-delaunay, and under
 * --density reports no capacities. */
#include "delaunay.h"

#include <stdio.h>

double an_delaunay_bytes(size_t n)
{
    (void)n;
    return 0;
}

int an_delaunay_compute(const double *xy, size_t n, an_delaunay *out, char *err, size_t errlen)
{
    return an_delaunay_compute_cells(xy, n, out, NULL, err, errlen);
}

int an_delaunay_compute_cells(const double *xy, size_t n, an_delaunay *out, an_vcells *cells, char *err,
                              size_t errlen)
{
    (void)xy;
    (void)n;
    (void)out;
    if (cells) *cells = (an_vcells){0};
    snprintf(err, errlen, "built without CGAL: no Delaunay measures");
    return -1;
}
