/* cellradius.h - the largest empty circle of one cell of the certificate's
 * grid (cellradius.c): its bound from the cell's centre, the exact radius
 * through the farthest-point solver, and the order cells are solved in.
 * The covering radius rho of the set (certify.c) and of the set without
 * one point (vmax.c) are built from it. */
#ifndef AN_CELLRADIUS_H
#define AN_CELLRADIUS_H

#include <stddef.h>

#include "certwork.h"

/* A grid cell and a radius (or a bound of it); qsort's order: largest
 * radius first, then the lower cell index (certify.c). */
typedef struct {
    double r;
    size_t c;
} an_cell_key;
int an_cell_key_desc(const void *a, const void *b);

/* An upper bound of cell c's largest empty circle radius with X \ {skip}
 * (skip = n: none): its centre's distance to the set plus its
 * half-diagonal, raised against rounding. */
double an_cell_bound(const an_cert_ctx *C, size_t c, size_t skip);

/* Cell c's largest empty circle radius with X \ {skip} into *out and
 * where it is reached (wrapped) into arg[0..1], given ub = an upper bound
 * of it. 0, -1 out of memory, -2 the solver found nothing. */
int an_cell_radius(const an_cert_ctx *C, size_t c, double ub, size_t skip, an_cert_work *w, double *out, double *arg);

#endif
