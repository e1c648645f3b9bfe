/* tiles.h - layer 2 (includes nothing of the project), the arithmetic
 * half of the cut across ranks: how the g x g cell grid is cut
 * into px x py rectangular tiles, one per rank (rank = ty * px + tx).
 *
 * Owns: choosing px x py for P ranks (or taking a forced cut), the tile
 * extents (uneven when px does not divide g: the first g % px columns of
 * tiles are one cell wider), the owner of any cell, and the checks that
 * every tile is large enough. Pure arithmetic, no MPI, so the dry run and
 * the tests use it without starting anything.
 * Does not own: communication (comm) or the cells' contents (engine). */
#ifndef CFPO_TILES_H
#define CFPO_TILES_H

#include <stddef.h>
#include <stdint.h>

/* Smallest tile side in cells: one colour period, so every rank has cells
 * of every colour and a point never moves past the neighbouring tile. */
#define CFPO_TILE_MIN 3

typedef struct {
    int64_t g;
    int px, py;
} cfpo_tiling;

/* Cuts the grid for P ranks. force_px, force_py: 0 to choose (the most
 * square cut with px <= py... whichever gives the shorter boundary), or a
 * cut given by the user (px * py must equal P). Returns 0, or -1 with a
 * one-line message (naming the largest usable rank count when tiles would
 * be too small). */
int cfpo_tiling_init(cfpo_tiling *T, int64_t g, int P, int force_px, int force_py, char *err,
                     size_t errlen);

/* The largest P for which some cut keeps every tile at least
 * CFPO_TILE_MIN cells on a side. */
int64_t cfpo_tiling_max_ranks(int64_t g);

/* Tile column tx covers cells [x0, x0 + w) (same for rows). */
static inline int64_t cfpo_tile_start(int64_t g, int parts, int t)
{
    int64_t base = g / parts, rem = g % parts;
    return (int64_t)t * base + (t < rem ? t : rem);
}
static inline int64_t cfpo_tile_len(int64_t g, int parts, int t)
{
    return g / parts + (t < g % parts ? 1 : 0);
}
/* Cells in the halo ring of a w x h tile: the rows above and below it
 * (corners included) and the columns left and right of it. */
static inline int64_t cfpo_tile_ring(int64_t w, int64_t h) { return 2 * (w + 2) + 2 * h; }
/* Which tile column holds cell column x. */
static inline int cfpo_tile_of(int64_t g, int parts, int64_t x)
{
    int64_t base = g / parts, rem = g % parts, cut = rem * (base + 1);
    return x < cut ? (int)(x / (base + 1)) : (int)(rem + (x - cut) / base);
}
static inline int cfpo_tiling_owner(const cfpo_tiling *T, int64_t cx, int64_t cy)
{
    return cfpo_tile_of(T->g, T->py, cy) * T->px + cfpo_tile_of(T->g, T->px, cx);
}

#endif
