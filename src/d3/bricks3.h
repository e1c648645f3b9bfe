/* bricks3.h - layer 1 of the 3-D engine (includes nothing of the engine):
 * the cut of the g x g x g cells into one brick per rank (docs/mpi.md,
 * "Three dimensions").
 *
 * Each axis's g cells are cut into p_a runs of nearly equal length (run k
 * holds cells [k g / p_a, (k + 1) g / p_a)), px py pz = P with each p_a at
 * most g / 3, so a brick is at least 3 cells a side and holds cells of all
 * 27 colours (not the same number of each when a side is not a multiple of
 * 3). The factors are the ones with the fewest halo cells a
 * brick (ties: more cuts along z, then y). A rank's region is its brick
 * and the one layer of cells around it (across the wrap): every 3x3x3
 * block of a cell of the brick lies in the region. Bricks whose regions
 * meet are neighbours: at most 26, fewer when an axis has one or two runs.
 * The cut depends on g and P only, never on the grid's shift or the
 * points, so a cell is solved by the same rank for the whole run.
 * Owns: the factors, the runs, region tests, the neighbour list. */
#ifndef CFPO_BRICKS3_H
#define CFPO_BRICKS3_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int g, P, rank;
    int p[3];      /* runs per axis: x, y, z */
    int me[3];     /* this rank's run on each axis */
    int *lo[3];    /* run k of axis a holds cells [lo[a][k], lo[a][k + 1]) */
    int nnb;       /* neighbour ranks (distinct, not this one), increasing */
    int nb[26];
} cfpo3_bricks;

/* The most ranks a grid of g cells a side can take: (g / 3)^3 (and P
 * must factor into three runs of at most g / 3 each). */
int64_t cfpo3_bricks_max(int g);

/* The cut of the g^3 grid over P ranks, seen from `rank`. 0, or -1 with
 * one line in err (P does not factor into bricks of at least 3 cells a
 * side; out of memory). */
int cfpo3_bricks_init(cfpo3_bricks *B, int g, int P, int rank, char *err, size_t errlen);
void cfpo3_bricks_free(cfpo3_bricks *B);

/* The rank of the brick with runs (i, j, k). */
static inline int cfpo3_bricks_rank(const cfpo3_bricks *B, int i, int j, int k)
{
    return (k * B->p[1] + j) * B->p[0] + i;
}
/* 1 when cell coordinate c of axis a lies in run r or in the layer
 * around it (r's region along a). */
static inline int cfpo3_bricks_near(const cfpo3_bricks *B, int a, int r, int c)
{
    if (B->p[a] == 1) return 1;
    const int lo = B->lo[a][r], w = B->lo[a][r + 1] - lo, g = B->g;
    return (c - lo + 1 + g) % g < w + 2;
}
/* 1 when cell (i, j, k) lies in the region of the brick with runs r[3]. */
static inline int cfpo3_bricks_in_region(const cfpo3_bricks *B, const int r[3], int i, int j, int k)
{
    return cfpo3_bricks_near(B, 0, r[0], i) && cfpo3_bricks_near(B, 1, r[1], j) && cfpo3_bricks_near(B, 2, r[2], k);
}
/* 1 when cell (i, j, k) lies in this rank's brick. */
static inline int cfpo3_bricks_mine(const cfpo3_bricks *B, int i, int j, int k)
{
    return i >= B->lo[0][B->me[0]] && i < B->lo[0][B->me[0] + 1] && j >= B->lo[1][B->me[1]] &&
           j < B->lo[1][B->me[1] + 1] && k >= B->lo[2][B->me[2]] && k < B->lo[2][B->me[2] + 1];
}
/* The runs of rank r. */
static inline void cfpo3_bricks_runs(const cfpo3_bricks *B, int r, int out[3])
{
    out[0] = r % B->p[0];
    out[1] = (r / B->p[0]) % B->p[1];
    out[2] = r / (B->p[0] * B->p[1]);
}

#endif
