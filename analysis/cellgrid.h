/* cellgrid.h - the points of a set on the unit torus by the cells of a g x g
 * grid of about 2 points a cell, g = floor(sqrt(n / 2)): the grid the
 * core's nearest-neighbour statistics use (src/solver/stats.c), in the same order
 * (cells by rows, points by index inside a cell). */
#ifndef AN_CELLGRID_H
#define AN_CELLGRID_H

#include <stddef.h>

typedef struct {
    size_t g;
    double L;            /* the cell side, 1 / g */
    size_t *start, *idx; /* cell c holds the points idx[start[c] .. start[c + 1]) */
} an_cellgrid;

/* 0, or -1 out of memory; an_cellgrid_free in either case. */
int an_cellgrid_build(const double *xy, size_t n, an_cellgrid *G);
void an_cellgrid_free(an_cellgrid *G);

#endif
