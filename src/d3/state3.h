/* state3.h - the 3-D engine's state, shared by engine3.c (create,
 * buckets, measure), engine3_step.c (the iteration) and engine3_ckpt.c
 * (checkpoints), and engine3_dist.c (several ranks); by no other file.
 *
 * Frame: the grid is shifted by s (each axis in [0, L)); a point's grid
 * coordinate is u = x - s wrapped into [0,1) and its cell floor(u g).
 * Cell index: (k g + j) g + i. Buckets: the ids of cell c are
 * cids[cstart[c] .. cstart[c+1]), increasing. Skip stamps: changed[c] is
 * the last phase that moved a point in or out of (or inside) c, solvedat[c]
 * the phase c was last solved in, needm[c] the largest L - t of its points
 * then; c is solved again when a cell of its block changed since, or the
 * margin fell below needm[c], or the grid moved.
 *
 * Several ranks (engine3_dist.h): B is the cut into bricks; a rank solves
 * its brick's cells and holds its region's points only (cellof -1 for the
 * others, whose pos and prev are stale); the stamps are current for the
 * region. On one rank the brick is the whole grid and every point is
 * held. */
#ifndef CFPO_STATE3_H
#define CFPO_STATE3_H

#include "bricks3.h"
#include "comm.h"
#include "engine3.h"
#include "solve3.h"

/* A point's move in a colour phase, sent to the neighbours that hold
 * either cell (engine3_dist.c). */
typedef struct {
    int64_t id;
    int32_t from, to; /* cells before and after */
    double x[3];      /* the new position */
    double p0[3];     /* the position at the iteration's start */
} cfpo3_move;

typedef struct {
    cfpo3_move *v;
    int64_t len, cap;
} cfpo3_move_list;

struct cfpo3_engine {
    cfpo3_grid G;
    cfpo3_options o;
    int64_t n;
    int iter;              /* iterations done */
    double *pos;           /* 3n, in [0,1), by id */
    double *prev;          /* 3n: the set at the start of the iteration */
    double shift[3];
    int32_t *cellof;       /* n */
    int64_t *cstart;       /* g^3 + 1 */
    int64_t *cids;         /* n */
    uint64_t *changed, *solvedat; /* g^3 */
    double *needm;         /* g^3 */
    int64_t *fill;         /* g^3: the rebucketing's cursors */
    uint64_t phase;        /* phases run (the stamps' clock) */
    int near;              /* 1 while in the near phase (engine3_step.c) */
    double dmin, davg;     /* the current set, over Delta3 */
    cfpo3_solve_count count; /* the solver's work so far (for measuring) */
    /* several ranks (engine3_dist.c) */
    cfpo3_bricks B;
    int dist;              /* 1 when P > 1 */
    cfpo3_move_list mv;    /* this phase's moves on this rank */
    comm_msg *msg;         /* one a neighbour */
    void *sendbuf[26];
    size_t sendcap[26];
    double t_compute, t_halo, t_migrate; /* seconds on this rank */
    double b_halo, b_migrate;            /* bytes this rank sent */
    int64_t phases;
    /* checkpoints: the caller's block after the points (engine3.h,
     * cfpo3_set_checkpoint_tail) and the block a read checkpoint carried */
    cfpo3_tail_fn tail_fn;
    void *tail_user;
    unsigned char *tail_in;
    size_t tail_in_len;
};

/* u of coordinate x under shift s: wrapped into [0,1). */
static inline double cfpo3_u(double x, double s)
{
    double u = x - s;
    if (u < 0.0) u += 1.0;
    return u >= 1.0 ? 0.0 : u;
}
static inline int cfpo3_cell1(double u, int g)
{
    int c = (int)(u * g);
    return c < 0 ? 0 : (c >= g ? g - 1 : c);
}
/* The shift of the grid in force during iteration k (1-based). */
void cfpo3_shift_for(const cfpo3_engine *e, int k, double s[3]);
/* The colour phases of iteration k: their order (a permutation of the 27
 * colours, drawn anew each iteration) and the colours' offset along each
 * axis (0..2, drawn with each grid shift): cell (i, j, l) has colour
 * ((i + off0) % 3, (j + off1) % 3, (l + off2) % 3). With the shift in
 * [0, L) alone a colour class keeps its place on the torus, and the fixed
 * order (z slowest) printed the period 3L into the set: peaks at the axis
 * frequencies 4g/3, near the spectrum's first peak
 * (docs/results/2026-11-29-3d-default.md). The identity and no offset
 * when the grid is fixed (--no-shift). */
void cfpo3_colours_for(const cfpo3_engine *e, int k, int order[27], int off[3]);
/* Puts every point in its cell (after a shift or moves across cells). */
void cfpo3_rebucket(cfpo3_engine *e);
/* Recomputes cellof from pos and the shift, then rebuckets. */
void cfpo3_assign(cfpo3_engine *e);
/* Allocates an engine for n points with the given grid (pos unset).
 * NULL with a message. */
cfpo3_engine *cfpo3_alloc(int64_t n, const cfpo3_options *o, char *err, size_t errlen);
/* Measures the current set into e->dmin, e->davg. 0 or -1 (memory). */
int cfpo3_remeasure(cfpo3_engine *e);

#endif
