/* dens_levels.h - layer 3: cells sized to the local spacing, for the
 * density engine (dens_engine.h; docs/method.md, "Density", item 6).
 *
 * The engine's grid is sized to the sparsest spacing (L >= 1.25 r_max),
 * so at high contrast a dense point's 3 x 3 block holds hundreds of points
 * and no block is flat enough for the near solve. Levels of nested grids
 * fix that: level l has g0 2^l cells a side (g0 the one grid's), all under
 * the same offset, so each cell of level l lies in one cell of every
 * coarser level (cell_of's floor of x g0 2^l is that of x g0 times 2^l,
 * exactly). A point is solved in the finest level whose cells are at least
 * 1.25 of its own spacing and where a spot one cell from its block's edge,
 * worth a value a little above a spread set's (the engine's LEVEL_WORTH),
 * would pass the outside bound below; the points of every level are its
 * neighbours.
 *
 * The outside bound. A move must not bring the point nearer, in the
 * measure, to a point beyond its block than its old value. On the one grid
 * the block's edge is at least L away and every point has q >= q_min
 * (= sqrt(rho_min)), and L is sized so that this suffices. On a finer level
 * it does not, and the bound takes tiers: the block grown by r_k = 2^(k-1)
 * L (r_0 = 0), k = 1 .. CFPO_DENS_TIERS: a point outside the block grown
 * by r_(k-1) and inside the one grown by r_k lies at least e + r_(k-1)
 * from a spot e from the block's edge, and has q at least the least q over
 * the level's cells within 2^(k-1) + 1 cells of the point's cell (they
 * hold that grown block); beyond the last tier, q_min. The spot passes
 * when every tier's distance squared times its q, times the spot's q,
 * reaches the old value (the tiers stop where q_min alone suffices).
 *
 * The least q per cell is a function of the offset and the density alone
 * (the pyramid of minima, dens_qbound.h, over each cell of the finest
 * level, then 2 x 2 minima up the levels, then each tier's square of cells
 * by a running minimum along rows and columns), computed when the offset
 * changes; so the levels, like everything else, do not depend on threads,
 * ranks or a resume.
 * Owns: the levels' count, each point's level, the tiers' bounds. */
#ifndef CFPO_DENS_LEVELS_H
#define CFPO_DENS_LEVELS_H

#include <stdint.h>

#include "dens_qbound.h"
#include "density.h"

#define CFPO_DENS_LEVELS_MAX 8
#define CFPO_DENS_TIERS 4

typedef struct {
    int n;                 /* levels (1: the one grid alone) */
    int64_t g0;            /* level 0's cells a side; level l has g0 << l */
    double qmin;           /* sqrt(rho_min) */
    double sx, sy;         /* the offset tq was computed for (NAN: none) */
    float *tq[CFPO_DENS_LEVELS_MAX][CFPO_DENS_TIERS]; /* per level and tier, per cell: at most the least q over the
                                                        cells within 2^(k-1) + 1 of it */
    float *work;           /* the finest level's cells: a cell's own least q */
} cfpo_dens_levels;

/* The levels under d on a grid of g0 cells a side, with
 * spacing unit D (Delta(n)): as many as halve the cell while it stays at
 * least 1.25 times the densest spacing, at most CFPO_DENS_LEVELS_MAX. One
 * level holds no arrays. 0, or -1 when out of memory. */
int cfpo_dens_levels_init(cfpo_dens_levels *V, const cfpo_density *d, int64_t g0, double D, double spacings);

/* The least-q arrays for the offset (sx, sy) (nothing when they are
 * already for it). 0, or -1 when out of memory. */
int cfpo_dens_levels_place(cfpo_dens_levels *V, const cfpo_dens_qbound *qlow, double sx, double sy);

/* The tiers' q for the cell (cx, cy) of level l: t[k - 1] for tier k.
 * Returns their count, CFPO_DENS_TIERS. */
int cfpo_dens_levels_tiers(const cfpo_dens_levels *V, int l, int64_t cx, int64_t cy, double *t);

/* Whether a spot e from the edge of its level-l block (cell side L), of q
 * rc, keeps every point beyond the block at least oldf away in the
 * squared measure, by the tiers t (cfpo_dens_levels_tiers, nt of them). */
static inline int cfpo_dens_levels_clear(const double *t, int nt, double qmin, double L, double e, double rc, double oldf)
{
    double r = 0;
    for (int k = 1; k <= nt; k++) {
        const double dk = e + r;
        if (dk * dk * qmin * rc >= oldf) return 1;
        if (!(dk * dk * t[k - 1] * rc >= oldf)) return 0;
        r = k == 1 ? L : 2 * r;
    }
    return (e + r) * (e + r) * qmin * rc >= oldf;
}

/* The level of a point at (x, y) with q = sqrt(rho) there, spacing unit
 * D: the finest whose cells are at least `spacings` of D / q and where a
 * spot one cell from the block's edge, worth (worth D)^2, passes the
 * tiers. 0 for a point on zero density. */
int cfpo_dens_levels_of(const cfpo_dens_levels *V, double x, double y, double q, double D, double spacings,
                        double worth);
/* The same from the point's finest cell (cfpo_dens_levels_fine). */
int cfpo_dens_levels_of_fine(const cfpo_dens_levels *V, uint32_t fine, double q, double D, double spacings,
                             double worth);

/* Stamps, in every level's touch (g0 2^l cells a side each), the cells
 * holding the finest cells a and b (cfpo_dens_levels_fine: a move's old
 * and new places under the placed offset) with the phase: a cell's block changed since it was last
 * solved when a cell of its 3 x 3 holds a stamp at least that solve's
 * phase (cfpo_dens_levels_touched). One stamp a cell, where marking the
 * 3 x 3 around each spot took nine. Relaxed atomic stores (cells of
 * other levels than the one being solved can be stamped by several
 * threads at once, all with the same phase). */
void cfpo_dens_levels_mark_fine(const cfpo_dens_levels *V, uint32_t *const *touch, uint32_t phase, uint32_t a, uint32_t b);

/* The finest level's cell of (x, y) under the placed offset, as y << 16 |
 * x (at most 3 * 8192 cells a side). A coarser level l's cell is its
 * coordinates shifted right by n - 1 - l: cell_of's floor of x g0 2^f is
 * that of x g0 2^l times 2^(f - l), exactly (dens_dist.h). */
uint32_t cfpo_dens_levels_fine(const cfpo_dens_levels *V, double x, double y);

/* Whether a cell of the 3 x 3 around (cx, cy) of a g x g level holds a
 * stamp at least `since` (wrapping). */
static inline int cfpo_dens_levels_touched(const uint32_t *touch, int64_t g, int64_t cx, int64_t cy, uint32_t since)
{
    const int64_t x0 = cx ? cx - 1 : g - 1, x2 = cx + 1 < g ? cx + 1 : 0;
    const int64_t r[3] = {(cy ? cy - 1 : g - 1) * g, cy * g, (cy + 1 < g ? cy + 1 : 0) * g};
    uint32_t m = 0;
    for (int b = 0; b < 3; b++) {
        const uint32_t *row = touch + r[b];
        const uint32_t u = row[x0] > row[cx] ? row[x0] : row[cx];
        m = u > m ? u : m;
        m = row[x2] > m ? row[x2] : m;
    }
    return m >= since;
}

void cfpo_dens_levels_free(cfpo_dens_levels *V);

#endif
