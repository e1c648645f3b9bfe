/* pd3grid.h - the background grid of the 3-D Poisson-disk samplers (dart
 * throwing, Bridson) on the unit 3-torus: cells of side at most r/sqrt(3),
 * so a cell holds at most one point of a set with minimum distance r, and a
 * conflict test (is any point closer than r?) looks at the 5x5x5 cells
 * around. Only makes the test O(1); decides nothing about the method. */
#ifndef CFPO_PD3GRID_H
#define CFPO_PD3GRID_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double r, r2;
    long G;          /* cells a side */
    int32_t *cell;   /* point id or -1, G^3 */
    const double *p; /* the points (3 doubles each), the caller's */
} pd3grid;

/* 0, or -1 (memory; r too small for a grid of at most 2^31 cells). */
int pd3grid_init(pd3grid *g, double r, const double *points);
void pd3grid_free(pd3grid *g);
/* 1 when a stored point lies closer than r to (x, y, z) (periodic). */
int pd3grid_conflict(const pd3grid *g, const double *x);
/* Stores point id (its coordinates at points[3 id]). */
void pd3grid_put(pd3grid *g, const double *x, int32_t id);

#endif
