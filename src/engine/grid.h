/* grid.h - layer 2 (may include cfpo_types.h, geom.h, rng.h): the cell
 * grid, colours and the stratified start.
 *
 * Owns: choosing g (cells per side) from n, the constraint square of a
 * point's cell, cell coordinates of a position, the colour classes, and the
 * initial point set (one point per cell, the rest in distinct random cells,
 * every coordinate from the counter-based generator keyed by the global
 * cell, so any process can make any cell's points). Point ids are global:
 * cells in row-major order, points of a cell consecutive.
 * Does not own: storage of points (the engine's buckets). */
#ifndef CFPO_GRID_H
#define CFPO_GRID_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"
#include "geom.h"

typedef struct {
    int64_t n;
    int64_t g;      /* cells per side */
    double L;       /* cell side, 1/g */
    double delta;   /* Delta(n) */
    int variant;    /* CFPO_VARIANT_* */
    int period;     /* 3 (CFPO) or 2 (simplified): colours are period^2 */
    double margin;  /* how far S reaches past the cell: L - Delta(n), or 0 */
    uint64_t seed;
    uint64_t extra; /* n - g^2: cells with a second point */
    double shift_x; /* the grid's offsets, each in [0, L): cell (cx, cy) spans */
    double shift_y; /* [cx L + shift_x, (cx + 1) L + shift_x) x [cy L + shift_y,
                       (cy + 1) L + shift_y) (mod 1); 0 except in the
                       adaptive-like variants, which move the grid */
} cfpo_grid;

/* Chooses g: a multiple of the period with g^2 close to 0.8 n and
 * L = 1/g > Delta(n) strictly (full variant; the simplified variant needs
 * L >= Delta(n) only for its own cell but uses the same rule), and
 * g^2 <= n. Returns 0, or -1 with a message when n is too small. */
int cfpo_grid_init(cfpo_grid *G, int64_t n, int variant, uint64_t seed, char *err, size_t errlen);

/* Smallest n the variant accepts. */
int64_t cfpo_grid_min_n(int variant);

/* The cell column (row) of coordinate v on an axis of offset shift. */
static inline int64_t cfpo_grid_axis(const cfpo_grid *G, double v, double shift)
{
    if (shift != 0) {
        v -= shift;
        if (v < 0) v += 1.0;
    }
    int64_t c = (int64_t)(v * (double)G->g);
    return c >= G->g ? G->g - 1 : (c < 0 ? 0 : c);
}

/* The cell column of x and the cell row of y. */
static inline int64_t cfpo_grid_cx(const cfpo_grid *G, double x) { return cfpo_grid_axis(G, x, G->shift_x); }
static inline int64_t cfpo_grid_cy(const cfpo_grid *G, double y) { return cfpo_grid_axis(G, y, G->shift_y); }

static inline int cfpo_grid_colour(const cfpo_grid *G, int64_t cx, int64_t cy)
{
    return (int)((cy % G->period) * G->period + (cx % G->period));
}

/* S for a point of a cell, in the cell's local frame (cell = [0,L]^2). */
static inline cfpo_square cfpo_grid_square(const cfpo_grid *G)
{
    cfpo_square S = {-G->margin, -G->margin, G->L + G->margin, G->L + G->margin};
    return S;
}

/* Number of initial points in cell c (row-major index). */
uint64_t cfpo_grid_cell_count(const cfpo_grid *G, uint64_t c);
/* The k-th initial point of cell (cx, cy), inside that cell. */
void cfpo_grid_cell_point(const cfpo_grid *G, int64_t cx, int64_t cy, uint64_t k, double *x,
                          double *y);

#endif
