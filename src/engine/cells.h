/* cells.h - layer 3, the bottom of the engine: its state (the tile of
 * cells plus the halo ring around it, points stored cell by cell),
 * addressing cells, growing the storage, change marks. Not a public
 * header: only src/engine/engine*.c, src/engine/cells.c and src/engine/backend*.c include it.
 * May include engine.h and the layers below it.
 *
 * The engine is split by concept, each file on top of this one:
 *   cells.c           storage growth, the memory model, change marks,
 *                     the brick shifts' table, eng_fatal (out of
 *                     memory mid-run)
 *   engine.c          creation, getters, timing
 *   engine_schedule.c the colour schedule: phase, grid shift, sweep,
 *                     iteration and run loop (the host side of the seam);
 *                     asks policy.c (layer 2) for each iteration's
 *                     decisions, which the backends read from E->pol
 *   backend.h         the seam: the per-phase work a compute backend does
 *   backend_cpu.c     the OpenMP backend: solving the cells of a colour
 *   engine_move.c     points moving between cells, tiles and ranks
 *   engine_halo.c     the halo ring (who keeps which cell, the refresh
 *                     after every phase)
 *   engine_check.c    the --check verifications
 *   engine_init.c     the initial set of each variant
 *   engine_given.c    a start given by the caller (--init FILE)
 *   engine_ckpt.c     checkpoints: reading, validating, writing
 *   engine_stats.c    delta_min and delta_avg of the set, exact and cached
 *                     per block of cells
 *   engine_output.c   the points out, in id order */
#ifndef CFPO_CELLS_H
#define CFPO_CELLS_H

#include <math.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "gridmodes.h"
#include "transport.h"
#include "omp_compat.h"
#include "policy.h"
#include "rng.h"

#define ARRIVE_BIT (1u << 9) /* mask: the cell receives points from other ranks */
#define MOVED_BIT (1u << 10) /* mask, inside eng_relocate only: the cell's content changes */
#define NEED_BIT (1u << 15)  /* mask: the cell must be solved (its block changed) */
#define ARRIVAL_CODE (1ull << 63)
#define CENTRE_BIT (1u << 4)
#define SUM_SCALE 16777216.0 /* nearest-neighbour distances summed in units of Delta / 2^24 */
#define SB 8 /* statistics blocks: SB x SB cells */

typedef struct { /* a point on the move between ranks */
    double x, y;
    uint64_t id;
    float dq[2];
} mig_rec;

typedef struct { /* arrival, sorted into its cell */
    int64_t cell;
    mig_rec r;
} arrival;

typedef struct {
    int rank;
    int64_t nsend, nrecv;
    int64_t *send_cells; /* own cells this neighbour keeps in its halo, in its ring order */
    int64_t *recv_ring;  /* my ring cells it owns, in my ring order */
    /* migration out */
    mig_rec *out;
    size_t nout, outcap;
    /* halo out */
    unsigned char *hbuf;
    size_t hcap;
} neighbour;

struct cfpo_backend;

struct cfpo_engine {
    const struct cfpo_backend *be; /* who solves, marks and relocates (backend.h) */
    cfpo_grid G;
    cfpo_options o;
    cfpo_engine_config cfg;
    cfpo_tiling T;
    int rank, nranks;
    int64_t n, x0, y0, w, h, cells;
    int wrapx, wrapy;
    int64_t nloc;
    size_t cap;       /* capacity of the point arrays */
    double *px, *py;  /* positions, cell by cell */
    uint64_t *pid;    /* global ids, ascending inside a cell */
    float *dq;        /* 2 per slot: net displacement this iteration */
    double *tx, *ty;  /* spare buffers for rebuilding and output */
    uint64_t *tid;    /* while relocating: where each new slot comes from */
    uint32_t *start;  /* CSR: own cell c holds [start[c], start[c+1]) */
    uint32_t *start2; /* the next CSR offsets, while relocating */
    uint16_t *mask;   /* this phase: bit (dy+1)*3+(dx+1) set if a point of
                         the cell moved into the cell at offset (dx,dy);
                         ARRIVE_BIT if points arrive from another rank;
                         NEED_BIT if the cell must be solved again */
    /* halo ring: bottom row, top row, left column, right column */
    int64_t nring;
    uint32_t *hstart, *hstart2;
    double *hx, *hy, *hx2, *hy2;
    size_t hcap, hcap2;
    uint32_t *hcnt;
    int nnb;
    neighbour *nb;
    comm_msg *msg;
    arrival *arr;
    size_t narr, arrcap;
    /* statistics cached per block of SB x SB cells, recomputed only when a
     * cell of the block was marked (its 3x3 neighbourhood changed) */
    int64_t nbx, nby;
    uint64_t *bsum;
    double *bmin;
    uint8_t *bdirty;
    int nthreads;
    int maxcell;
    double **scratch; /* per thread */
    size_t scratch_m; /* points the scratch is sized for */
    int iter0;        /* iteration the engine stands at */
    int resumed_converged;
    cfpo_transport lf;  /* the hyperuniform variant's transport (transport.h) */
    cfpo_gridmodes gm;  /* the grid's print on the set (gridmodes.h) */
    int near;         /* 1 while the adaptive variant's near phase runs:
                         cfpo_near_solve, until a sweep moves nothing */
    double max_move;  /* largest single move this iteration */
    double t_born;    /* when cfpo_engine_create_ex began */
    int shifting;     /* inside move_grid: cells hold points of the old grid */
    int cur;          /* the iteration under way (or last done) */
    cfpo_policy pol;  /* iteration cur's decisions (policy.h): what every
                         backend reads of the variant's schedule */
    uint8_t *brick_sh;     /* under a brick colouring: global row (column) i's
                              shift, cfpo_policy_brick_shift(pol.brick_key, i),
                              i < g (eng_brick_table); NULL until first made */
    uint64_t brick_sh_key; /* the key brick_sh was made for */
    double dmin_now;  /* delta_min / Delta(n) of the set as it stands (1 until measured) */
    int start_raw;    /* eng_make_initial makes the start without its
                         relaxation (the checkpoint's bound, engine_ckpt.c) */
    uint64_t id_sum;  /* checksum of all ids (check mode) */
    /* timing and traffic */
    double t_compute, t_migrate, t_halo, b_halo, b_migrate;
    int64_t phases, chk_mig, chk_halo;
    /* Set by cfpo_engine_run on one rank: where eng_fatal returns to, so a
     * failure mid-run (out of memory) comes back as an error, never exit(). */
    jmp_buf *fail;
    char fail_msg[160];
};


static inline double now(void) { return omp_get_wtime(); }

/* ---- where cells live ---- */

static inline int64_t ring_index(const cfpo_engine *E, int64_t lx, int64_t ly)
{
    if (ly == -1) return lx + 1;
    if (ly == E->h) return E->w + 2 + lx + 1;
    if (lx == -1) return 2 * (E->w + 2) + ly;
    return 2 * (E->w + 2) + E->h + ly; /* lx == w */
}

static inline void ring_coords(const cfpo_engine *E, int64_t i, int64_t *lx, int64_t *ly)
{
    const int64_t W = E->w + 2;
    if (i < W) { *lx = i - 1; *ly = -1; }
    else if (i < 2 * W) { *lx = i - W - 1; *ly = E->h; }
    else if (i < 2 * W + E->h) { *lx = -1; *ly = i - 2 * W; }
    else { *lx = E->w; *ly = i - 2 * W - E->h; }
}

/* The cell at tile coordinates (lx, ly), lx in [-1, w], ly in [-1, h]:
 * >= 0 an own cell's index, < 0 the halo cell -1 - ring index. A tile that
 * spans the whole torus in a direction wraps onto itself. */
static inline int64_t locate(const cfpo_engine *E, int64_t lx, int64_t ly)
{
    if (E->wrapx) { if (lx < 0) lx += E->w; else if (lx >= E->w) lx -= E->w; }
    if (E->wrapy) { if (ly < 0) ly += E->h; else if (ly >= E->h) ly -= E->h; }
    if (lx >= 0 && lx < E->w && ly >= 0 && ly < E->h) return ly * E->w + lx;
    return -1 - ring_index(E, lx, ly);
}

/* Own cell index of a position, or -1 if another rank owns its cell. */
/* The points of cell e as locate() returns it: own (e >= 0) or halo. */
static inline void cell_slice(const cfpo_engine *E, int64_t e, const double **X, const double **Y, uint32_t *a,
                              uint32_t *b)
{
    if (e >= 0) { *X = E->px; *Y = E->py; *a = E->start[e]; *b = E->start[e + 1]; }
    else { *X = E->hx; *Y = E->hy; *a = E->hstart[-1 - e]; *b = E->hstart[-e]; }
}

static inline int64_t own_cell_of(const cfpo_engine *E, double x, double y)
{
    int64_t lx = cfpo_grid_cx(&E->G, x) - E->x0, ly = cfpo_grid_cy(&E->G, y) - E->y0;
    if (lx < 0 || lx >= E->w || ly < 0 || ly >= E->h) return -1;
    return ly * E->w + lx;
}

static inline int wrap_offset(int64_t d, int64_t g)
{
    if (d > 1) d -= g;
    if (d < -1) d += g;
    return (int)d;
}

/* Whether the 3x3 block around own cell (lx, ly) is own cells that do
 * not wrap: inside the tile, and away from the torus's seam (the column
 * or row of cells that crosses coordinate 0: cell g - 1 when the grid is
 * shifted, and the pair g - 1, 0 always). Its points then lie in three
 * runs of slots, one a row (cells lx - 1 .. lx + 1 of rows ly - 1 .. ly + 1),
 * and, with 8 or more cells a side, periodic differences between them are
 * plain differences (|difference| < 3 L <= 0.5). */
static inline int eng_plain_block(const cfpo_engine *E, int64_t lx, int64_t ly)
{
    const int64_t lastx = E->G.g - (E->G.shift_x != 0 ? 3 : 2), lasty = E->G.g - (E->G.shift_y != 0 ? 3 : 2);
    const int64_t cx = E->x0 + lx, cy = E->y0 + ly;
    return E->G.g >= 8 && lx >= 1 && lx < E->w - 1 && ly >= 1 && ly < E->h - 1 && cx >= 1 && cx <= lastx &&
           cy >= 1 && cy <= lasty;
}

/* Is cell e's mask bit for the neighbour at offset (dx, dy) set? */
static inline int sends_to(unsigned mk, int dx, int dy) { return mk >> ((dy + 1) * 3 + (dx + 1)) & 1u; }

static inline int neighbour_of_rank(const cfpo_engine *E, int r)
{
    for (int i = 0; i < E->nnb; i++)
        if (E->nb[i].rank == r) return i;
    return -1;
}

/* v's offset from the low edge of global cell column (or row) c on the
 * axis of offset shift, for v in that cell: in [0, L) up to rounding,
 * whatever the grid's shift. */
static inline double cell_offset(const cfpo_engine *E, double v, int64_t c, double shift)
{
    double d = v - ((double)c * E->G.L + shift);
    return d < -0.5 ? d + 1.0 : d;
}

static inline int in_cell(const cfpo_engine *E, double x, double y, int64_t lx, int64_t ly)
{
    return cfpo_grid_cx(&E->G, x) - E->x0 == lx && cfpo_grid_cy(&E->G, y) - E->y0 == ly;
}

/* Own cells of one colour: tile column lx = bx, bx + p, ... */
static inline int64_t first_of(int64_t origin, int p, int64_t want)
{
    return ((want - origin) % p + p) % p;
}

/* The own cells of one colour (the iteration's colouring, E->pol,
 * policy.h: cfpo_policy_colour_at), in nyc rows of nxc slots: slot
 * (i, j) is the cell at tile coordinates (bx + p i, by + p j) in the
 * plain colouring; in the brick rows one, row by + p j from the x start of
 * its own global row (bx unused), in the brick columns one column
 * bx + p i from the y start of its own global column (by unused). There
 * nxc (nyc) is the most a row (column) of the tile holds, and the slots of
 * a row (column) that holds one cell fewer lie past the tile. */
typedef struct {
    int colour, p, brick;
    const uint8_t *sh; /* brick: E->brick_sh */
    int64_t x0, y0, w, h;
    int64_t bx, by, nxc, nyc;
    int64_t start3[3]; /* brick: a row's (column's) start for shift 0, 1, 2 */
} eng_colour;

static inline eng_colour eng_colour_of(const cfpo_engine *E, int colour)
{
    eng_colour C;
    C.colour = colour;
    C.p = E->G.period;
    C.brick = C.p == 3 ? E->pol.brick : 0;
    C.sh = E->brick_sh;
    C.x0 = E->x0, C.y0 = E->y0, C.w = E->w, C.h = E->h;
    C.bx = first_of(E->x0, C.p, colour % C.p);
    C.by = first_of(E->y0, C.p, colour / C.p);
    C.nxc = C.bx < E->w ? (E->w - C.bx + C.p - 1) / C.p : 0;
    C.nyc = C.by < E->h ? (E->h - C.by + C.p - 1) / C.p : 0;
    if (C.brick == CFPO_BRICK_ROWS) C.nxc = (E->w + C.p - 1) / C.p;
    if (C.brick == CFPO_BRICK_COLUMNS) C.nyc = (E->h + C.p - 1) / C.p;
    for (int s = 0; s < 3; s++)
        C.start3[s] = C.brick == CFPO_BRICK_ROWS ? first_of(E->x0, C.p, (colour % C.p + s) % C.p)
                                                 : first_of(E->y0, C.p, (colour / C.p + s) % C.p);
    return C;
}

/* The cell of slot t of colour C (t < nxc nyc), rows of slots in order:
 * 1, or 0 for a slot past the tile (no cell). */
static inline int eng_colour_cell(const eng_colour *C, int64_t t, int64_t *lx, int64_t *ly)
{
    const int64_t i = t % C->nxc, j = t / C->nxc;
    if (C->brick == CFPO_BRICK_ROWS) {
        *ly = C->by + C->p * j;
        *lx = C->start3[C->sh[C->y0 + *ly]] + C->p * i;
        return *lx < C->w;
    }
    if (C->brick == CFPO_BRICK_COLUMNS) {
        *lx = C->bx + C->p * i;
        *ly = C->start3[C->sh[C->x0 + *lx]] + C->p * j;
        return *ly < C->h;
    }
    *ly = C->by + C->p * j;
    *lx = C->bx + C->p * i;
    return 1;
}

/* Shared between the engine's files. */
int eng_ensure_cap(cfpo_engine *E, size_t need);
/* Makes E->brick_sh for E->pol's brick colouring (the g shifts once per
 * key, where the enumerations would hash a row's key at every cell they
 * visit); nothing without one. 0, or -1 when out of memory. */
int eng_brick_table(cfpo_engine *E);
void eng_mark_block(cfpo_engine *E, int64_t lx, int64_t ly);
void eng_sort3(uint64_t *id, double *x, double *y, int64_t lo, int64_t hi);
int eng_build_neighbours(cfpo_engine *E);
int eng_refresh_halo(cfpo_engine *E);
/* Out of memory while `what`, mid-run: back to cfpo_engine_run (one rank;
 * it returns -1 with the message) or, on several ranks, the job ends. */
void eng_fatal(cfpo_engine *E, const char *what);
void eng_check_migration(cfpo_engine *E);
void eng_check_halo(cfpo_engine *E);
int eng_ensure_scratch(cfpo_engine *E);
int eng_relocate(cfpo_engine *E, int colour);
int eng_pack_migrants(cfpo_engine *E, const eng_colour *C);
int eng_exchange_migrants(cfpo_engine *E);
int eng_make_initial(cfpo_engine *E, char *err, size_t errlen);
/* A state from outside (a given start, config.start_xy, or a checkpoint)
 * with more than this many points in one cell is refused: a cell's work
 * grows with the cube of its count. cfpo's own runs hold far fewer: the
 * most seen in one cell, over 48 runs to convergence (n = 1,000 and 4,096,
 * seeds 1-8, all three variants) and one of 65,536 points, was 10
 * (adaptive; paper 5, simplified 4), and a uniform random set of 10^9
 * points almost surely has fewer than 20 in every cell. */
#define CFPO_CELL_MAX 64
int eng_take_points(cfpo_engine *E, const double *xy, char *err, size_t errlen);
int eng_load_checkpoint(cfpo_engine *E, char *err, size_t errlen);
int eng_write_checkpoint(cfpo_engine *E, int iteration, int converged, char *err, size_t errlen);

#endif
