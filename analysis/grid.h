/* grid.h - the points of a set on the unit torus by the cells of a g x g
 * grid of about 2 points a cell, g = floor(sqrt(n / 2)): the grid the
 * core's nearest-neighbour statistics use (src/stats.c), in the same order
 * (cells by rows, points by index inside a cell). */
#ifndef AN_GRID_H
#define AN_GRID_H

#include <stddef.h>

typedef struct {
    size_t g;
    double L;            /* the cell side, 1 / g */
    size_t *start, *idx; /* cell c holds the points idx[start[c] .. start[c + 1]) */
} an_grid;

/* 0, or -1 out of memory; an_grid_free in either case. */
int an_grid_build(const double *xy, size_t n, an_grid *G);
void an_grid_free(an_grid *G);

#endif
