/* vmax.h - T of the farthest point test for one point (vmax.c): the
 * largest distance to the rest of the set over the point's Voronoi cell. */
#ifndef AN_VMAX_H
#define AN_VMAX_H

#include <stddef.h>

#include "certwork.h"

/* T of the farthest point test for point i at (x, y) (certify.c says what
 * it is): the square of half-side s, the images of the touching points
 * gathered within Chebyshev Hg. *T = -1 when V(x) is empty or T < rho
 * for certain. 0, -1 out of memory, or -2 the solver found no vertex. */
int an_vmax(const an_cert_ctx *C, size_t i, an_cert_work *w, double x, double y, double s, double Hg, double *T,
            double *tx, double *ty);

#endif
