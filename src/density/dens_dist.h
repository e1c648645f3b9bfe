/* dens_dist.h - layer 3: the density engine (dens_engine.c) on several
 * ranks (docs/mpi.md, "Under a density").
 *
 * Ownership is by cell of the engine's g x g grid, cut anew whenever the
 * grid takes a new offset (every fourth iteration). The cut balances
 * points, not area or mass: every rank counts its points in each shifted
 * cell, the counts are summed over the ranks (the same numbers on every
 * rank), the cells are ordered column by column (up the even columns, down
 * the odd ones), and the order is cut into P runs of equal count, so a
 * rank holds whole columns and part of one or two more, and n / P points
 * to within about one cell's count, even when the set is still far from
 * the density (a start, an --init set). A grid of g cells a side has
 * (g / 3)^2 cells of one colour; more ranks than that are refused.
 *
 * At each new offset: each rank sends the points that
 * left its cells to their cells' owners (all-to-all), merges what stays and
 * what came in by id, then fetches its halo: the points of the cells within
 * one cell of its own, from their owners, each rank's in id order. The
 * engine's cells, built by a stable sort of this store (own points first),
 * then hold their points in id order, as on one rank. After each of the
 * nine colour phases, the cells of the colour just solved are sent to the
 * ranks that keep them as halo (positions and q only: points stay in their
 * cells within an iteration). Each 3 x 3 block is then assembled from the
 * same points in the same order as on one rank, so every decision, and
 * the output, are the same bytes for any rank count.
 * Owns: the cut, the store of a rank's points, migration, halo fetch and
 * refresh, the gather of the whole set. Does not own: the solve, stats. */
#ifndef CFPO_DENS_DIST_H
#define CFPO_DENS_DIST_H

#include <stddef.h>
#include <stdint.h>

#include "density.h"
#include "geom.h"

/* A rank's points: its own [0, own) in id order, then halo copies [own,
 * loc). gid NULL on one rank (local index = id). q = sqrt(rho) at the
 * point. */
typedef struct {
    int64_t own, loc, cap;
    double *xy, *q;
    int64_t *gid;
} cfpo_dens_store;

/* The column ix and row iy of (x, y)'s cell in the grid of g cells
 * shifted by (sx, sy); cfpo_dens_cell_of: its index iy g + ix. */
static inline void cfpo_dens_cell_xy(int64_t g, double sx, double sy, double x, double y, int64_t *ix, int64_t *iy)
{
    const double gx = cfpo_wrap01(x - sx), gy = cfpo_wrap01(y - sy);
    *ix = (int64_t)(gx * (double)g);
    *iy = (int64_t)(gy * (double)g);
    if (*ix >= g) *ix = g - 1;
    if (*iy >= g) *iy = g - 1;
}

static inline int64_t cfpo_dens_cell_of(int64_t g, double sx, double sy, double x, double y)
{
    int64_t ix, iy;
    cfpo_dens_cell_xy(g, sx, sy, x, y, &ix, &iy);
    return iy * g + ix;
}

/* Marks the 3 x 3 cells around cell c of the g x g grid (those whose
 * block holds c): their next solve may move a point. */
static inline void cfpo_dens_mark_block(unsigned char *dirty, int64_t g, int64_t c)
{
    const int64_t cx = c % g, cy = c / g;
    for (int64_t dy = -1; dy <= 1; dy++)
        for (int64_t dx = -1; dx <= 1; dx++) dirty[((cy + dy + g) % g) * g + (cx + dx + g) % g] = 1;
}

/* Grows the store's arrays to hold cap points (gid too when with_gid). 0, or -1. */
int cfpo_dens_store_reserve(cfpo_dens_store *s, int64_t cap, int with_gid);
void cfpo_dens_store_free(cfpo_dens_store *s);

typedef struct cfpo_dens_dist cfpo_dens_dist;

/* The most ranks a grid of g cells a side supports: (g / 3)^2. */
int64_t cfpo_dens_dist_max_ranks(int64_t g);

/* The cut of the g x g cells over comm_size() ranks (the same on
 * every rank). NULL with one line in err when there are too many ranks for
 * g, or out of memory. */
cfpo_dens_dist *cfpo_dens_dist_create(int64_t g, char *err, size_t errlen);

/* This rank's cells of one colour (ix mod 3 + 3 (iy mod 3)), increasing. */
const int64_t *cfpo_dens_dist_cells(const cfpo_dens_dist *T, int colour, int64_t *count);

/* s holds the whole set (own = loc = n, no gid): keeps this rank's points
 * under the shift (sx, sy), with their ids. 0, or -1 when out of memory. */
int cfpo_dens_dist_keep(cfpo_dens_dist *T, cfpo_dens_store *s, double sx, double sy);

/* Collective: cuts the cells for the new shift, drops the halo, moves
 * every point to the owner of its cell, then fetches the halo; nothing
 * when the shift is the last cut's (points stay in their cells within an
 * offset's iterations, and the halo is kept current by the refreshes). 0,
 * or -1 when out of memory on any rank. */
int cfpo_dens_dist_migrate(cfpo_dens_dist *T, cfpo_dens_store *s, double sx, double sy);

/* Collective, after a colour's phase: sends this rank's cells of the
 * colour (every colour's when colour < 0) to the ranks that keep them as
 * halo, and writes the copies it gets. cstart/cidx: the engine's cells (local indices); cxyq (may be
 * NULL): x, y, q by slot of cidx, written with the copies. A copy that
 * differs from what the rank held marks its 3 x 3 cells in dirty (g x g;
 * may be NULL). 0, or -1 when out of memory or when a copy does not match
 * its cell (a bug). */
int cfpo_dens_dist_refresh(cfpo_dens_dist *T, cfpo_dens_store *s, const int64_t *cstart, const int64_t *cidx,
                           double *cxyq, int colour, unsigned char *dirty, int64_t g);

/* Collective: k doubles of each of the n points (own point i's at v + k i:
 * its position with v = s->xy, k = 2) into all (k n doubles, id order), on
 * every rank. 0, or -1 when out of memory on any rank. */
int cfpo_dens_dist_gather_values(const cfpo_dens_dist *T, const cfpo_dens_store *s, int64_t n, const double *v, int k,
                                 double *all);

void cfpo_dens_dist_free(cfpo_dens_dist *T);

#endif
