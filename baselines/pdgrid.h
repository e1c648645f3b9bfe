/* pdgrid.h - the background grid of the Poisson-disk samplers (dart
 * throwing, boundary sampling, Bridson) on the unit torus.
 *
 * Owns: g x g cells of side c = 1/g <= r/sqrt(2), so a cell's diagonal is
 * at most r and a set with minimum distance r holds at most one point per
 * cell; each cell stores that point's coordinates inline (no indirection)
 * and its index. Queries: is any point closer than r to (x, y) (the
 * conflict test), and the points within a distance R of (x, y). Every
 * distance is the periodic one, computed with cfpo_torus_dist2, so a test
 * that recomputes distances the same way sees exactly the same numbers.
 * Does not own: the points' array or any sampling policy. */
#ifndef CFPO_BASELINES_PDGRID_H
#define CFPO_BASELINES_PDGRID_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int64_t g;      /* cells per side */
    double c;       /* cell side 1/g */
    double r, r2;   /* the spacing radius and its square */
    int reach;      /* cells to look at on each side for the conflict test */
    double *cx;     /* 2 per cell: x, y of the cell's point; x < 0 when empty */
    uint32_t *id;   /* index of the cell's point */
    int8_t (*order)[2]; /* conflict window offsets, nearest rings first */
    int norder;
} pdgrid;

/* r in (0, 0.5). Returns 0, or -1 when out of memory or the grid would
 * have more than 2^32 cells (r too small). */
int pdgrid_init(pdgrid *G, double r);
void pdgrid_free(pdgrid *G);

/* Cells for a given radius, without allocating (for messages). */
double pdgrid_cells(double r);

static inline int64_t pdgrid_coord(const pdgrid *G, double v)
{
    int64_t k = (int64_t)(v * (double)G->g);
    return k >= G->g ? G->g - 1 : (k < 0 ? 0 : k);
}

/* 1 when some stored point lies at torus distance < r from (x, y). */
int pdgrid_conflict(const pdgrid *G, double x, double y);

/* Stores point `id` at (x, y); its cell must be empty (the caller has
 * checked the conflict test). */
void pdgrid_put(pdgrid *G, double x, double y, uint32_t id);

/* Up to `cap` ids of the points with torus distance < R from (x, y), R < 0.5,
 * in a fixed order (by cell, row-major around (x, y)); returns how many. */
int pdgrid_near(const pdgrid *G, double x, double y, double R, uint32_t *ids, int cap);

#endif
