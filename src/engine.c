/* engine.c - see engine.h.
 *
 * Why a phase is race-free (written once, here): cells of one colour are
 * `period` cells apart in both directions, on the whole torus, whatever the
 * tiles. A point of cell C may move only inside S(x), C grown by
 * L - Delta(n) < L, so it stays in C's 3x3 block, and solving C reads only
 * C's 3x3 block. With period 3 the blocks of two same-colour cells are
 * disjoint, so no cell is written by one thread (or rank) and read by
 * another (Parallelization Theorem). The simplified variant keeps points in
 * their own cell, so period 2 suffices. Inside a cell, points are solved in
 * id order, each seeing the moves of the ones before it.
 *
 * Between phases: points that crossed into another cell of this tile are
 * moved there; points that crossed into a halo cell migrate to the rank
 * that owns it; then every rank sends the cells next to its tile's border
 * to the neighbours whose halo holds them. So the next phase sees exactly
 * what one process would see, and the output is the same bytes for any
 * number of ranks and threads.
 *
 * Skipping: a cell is solved again only if some cell of its 3x3 block
 * changed (a point moved in it, left it or arrived; for halo cells: the
 * refreshed copy differs) since its last solve. An unchanged block means
 * the same inputs (same Y in the same order, same x), hence the same
 * answer, which last time was "do not move", so the output is
 * byte-identical to recomputing everything.
 *
 * Net displacement over an iteration is kept per point (two floats that
 * travel with the point); a move there and back cancels exactly, so a
 * point cycling between cells does not keep the run from converging. */
#include "engine.h"
#include "start.h"
#include "stoprule.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"
#include "rng.h"

#define ARRIVE_BIT (1u << 9) /* mask: the cell receives points from other ranks */
#define NEED_BIT (1u << 15)  /* mask: the cell must be solved (its block changed) */
#define ARRIVAL_CODE (1ull << 63)
#define CENTRE_BIT (1u << 4)
#define SUM_SCALE 16777216.0 /* nearest-neighbour distances summed in units of Delta / 2^24 */
#define SB 8 /* statistics blocks: SB x SB cells */
#define SHIFT_SALT 0x3c6ef372fe94f82aULL
#define SHIFT_EVERY 4 /* the grid moves before iterations 1, 5, 9, ...; in between, skipping works */
#define ADAPTIVE_THETA 0.7 /* the adaptive margin never reaches past L - 0.7 Delta(n) */
#define CKPT_MAGIC "CFPOCKP1"
#define CKPT_HEADER 64

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

struct cfpo_engine {
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
    double max_move;  /* largest single move this iteration */
    double t_born;    /* when cfpo_engine_create_ex began */
    int shifting;     /* inside move_grid: cells hold points of the old grid */
    int cur;          /* the iteration under way (or last done) */
    double dmin_now;  /* delta_min / Delta(n) of the set as it stands (1 until measured) */
    uint64_t id_sum;  /* checksum of all ids (check mode) */
    /* timing and traffic */
    double t_compute, t_migrate, t_halo, b_halo, b_migrate;
    int64_t phases, chk_mig, chk_halo;
};

static double now(void) { return omp_get_wtime(); }

const cfpo_grid *cfpo_engine_grid(const cfpo_engine *E) { return &E->G; }
const cfpo_tiling *cfpo_engine_tiling(const cfpo_engine *E) { return &E->T; }
int cfpo_engine_iteration(const cfpo_engine *E) { return E->iter0; }

static size_t thread_scratch_doubles(size_t m) { return 2 * m + cfpo_solver_scratch(m); }

/* Per point: positions 16 + spare 16, ids 8 + spare 8, displacement 8
 * (relocation rotates five 8-byte buffers, so it needs no spare). Per
 * cell: two offsets and the mask. Per halo cell: two offsets and two
 * copies of about 1.25 points. */
uint64_t cfpo_engine_bytes_local(int64_t nlocal, int64_t cells, int64_t ring, int threads)
{
    return (uint64_t)nlocal * (16 + 16 + 8 + 8 + 8) + (uint64_t)cells * (4 + 4 + 2) +
           (uint64_t)ring * (2 * 4 + 4 + 2 * 2 * 16 * 5 / 4) +
           (uint64_t)(threads > 0 ? threads : 1) * thread_scratch_doubles(64) * 8;
}

uint64_t cfpo_engine_bytes(int64_t n, int variant, int threads)
{
    cfpo_grid G;
    char err[8];
    if (cfpo_grid_init(&G, n, variant, 0, err, sizeof err) != 0) return 0;
    return cfpo_engine_bytes_local(n, G.g * G.g, 0, threads);
}

void cfpo_engine_free(cfpo_engine *E)
{
    if (!E) return;
    free(E->px); free(E->py); free(E->pid); free(E->dq);
    free(E->tx); free(E->ty); free(E->tid);
    free(E->start); free(E->start2); free(E->mask);
    free(E->bsum); free(E->bmin); free(E->bdirty);
    free(E->hstart); free(E->hstart2); free(E->hx); free(E->hy); free(E->hx2); free(E->hy2);
    free(E->hcnt);
    for (int i = 0; i < E->nnb; i++) {
        free(E->nb[i].send_cells);
        free(E->nb[i].recv_ring);
        free(E->nb[i].out);
        free(E->nb[i].hbuf);
        if (E->msg) free(E->msg[i].recv);
    }
    free(E->nb);
    free(E->msg);
    free(E->arr);
    if (E->scratch)
        for (int t = 0; t < E->nthreads; t++) free(E->scratch[t]);
    free(E->scratch);
    free(E);
}

static int ensure_scratch(cfpo_engine *E)
{
    size_t m = (size_t)9 * (size_t)E->maxcell + 1;
    if (m <= E->scratch_m) return 0;
    m = m < 64 ? 64 : m + m / 2;
    for (int t = 0; t < E->nthreads; t++) {
        double *b = realloc(E->scratch[t], thread_scratch_doubles(m) * sizeof(double));
        if (!b) return -1;
        E->scratch[t] = b;
    }
    E->scratch_m = m;
    return 0;
}

/* Grows the point arrays to hold at least `need` points. */
static int ensure_cap(cfpo_engine *E, size_t need)
{
    if (need <= E->cap) return 0;
    size_t cap = need + need / 16 + 1024;
    /* Five buffers of 8 bytes a slot swap roles in relocate(), so they
     * all have the same capacity. */
#define GROW(p, T, per)                                       \
    do {                                                      \
        T *q_ = realloc(E->p, cap * (per) * sizeof(T));       \
        if (!q_) return -1;                                   \
        E->p = q_;                                            \
    } while (0)
    GROW(px, double, 1); GROW(py, double, 1); GROW(tx, double, 1); GROW(ty, double, 1);
    GROW(pid, uint64_t, 1); GROW(tid, uint64_t, 1); GROW(dq, float, 2);
#undef GROW
    E->cap = cap;
    return 0;
}

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
static inline int64_t own_cell_of(const cfpo_engine *E, double x, double y)
{
    int64_t lx = cfpo_grid_coord(&E->G, x) - E->x0, ly = cfpo_grid_coord(&E->G, y) - E->y0;
    if (lx < 0 || lx >= E->w || ly < 0 || ly >= E->h) return -1;
    return ly * E->w + lx;
}

static inline int wrap_offset(int64_t d, int64_t g)
{
    if (d > 1) d -= g;
    if (d < -1) d += g;
    return (int)d;
}

/* Is cell e's mask bit for the neighbour at offset (dx, dy) set? */
static inline int sends_to(unsigned mk, int dx, int dy) { return mk >> ((dy + 1) * 3 + (dx + 1)) & 1u; }

static int neighbour_of_rank(const cfpo_engine *E, int r)
{
    for (int i = 0; i < E->nnb; i++)
        if (E->nb[i].rank == r) return i;
    return -1;
}

/* ---- moving points between cells, tiles and ranks ---- */

static int cmp_arrival(const void *a, const void *b)
{
    const arrival *p = a, *q = b;
    if (p->cell != q->cell) return p->cell < q->cell ? -1 : 1;
    return p->r.id < q->r.id ? -1 : p->r.id > q->r.id;
}

/* First arrival of cell c in the sorted list. */
static size_t first_arrival(const cfpo_engine *E, int64_t c)
{
    size_t lo = 0, hi = E->narr;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (E->arr[mid].cell < c) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* The adaptive variant's grid offset in iteration k (0 before the first). */
static double shift_of(const cfpo_grid *G, int k)
{
    if (G->variant != CFPO_VARIANT_ADAPTIVE || k <= 0) return 0;
    k -= (k - 1) % SHIFT_EVERY; /* the shift of the group of iterations k belongs to */
    return G->L * cfpo_rand01(G->seed ^ SHIFT_SALT, (uint64_t)k, 0);
}

/* v's offset from the low edge of global cell column (or row) c, for v
 * in that cell: in [0, L) up to rounding, whatever the grid's shift. */
static inline double cell_offset(const cfpo_engine *E, double v, int64_t c)
{
    double d = v - ((double)c * E->G.L + E->G.shift);
    return d < -0.5 ? d + 1.0 : d;
}

static inline int in_cell(const cfpo_engine *E, double x, double y, int64_t lx, int64_t ly)
{
    return cfpo_grid_coord(&E->G, x) - E->x0 == lx && cfpo_grid_coord(&E->G, y) - E->y0 == ly;
}

/* Moves points that changed cell in the last phase into their new cells.
 * Only the cells of that phase's colour can have sent points (their masks
 * say where to), plus arrivals from other ranks, so each own cell gathers
 * its own new content: the points of its old slice that stayed, then
 * arrivals from the neighbours whose mask points at it, then those from
 * other ranks, then id order. Parallel over cells, deterministic. */
static inline uint64_t id_of(const cfpo_engine *E, uint64_t code)
{
    return (code & ARRIVAL_CODE) ? E->arr[code & ~ARRIVAL_CODE].r.id : E->pid[code];
}

/* The cells that can have sent points into own cell (lx, ly) in the phase
 * of colour (a, b): the cell itself and, with period 3, the one cell of
 * that colour in its 3x3 block (every 3x3 block holds one cell of each
 * colour); with another period, all nine. Returns the count. */
static int senders(const cfpo_engine *E, int64_t lx, int64_t ly, int a, int b, int off[9][2])
{
    if (E->G.period != 3) {
        int m = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) off[m][0] = dx, off[m][1] = dy, m++;
        return m;
    }
    int sx = (int)(((b - (E->x0 + lx)) % 3 + 3) % 3), sy = (int)(((a - (E->y0 + ly)) % 3 + 3) % 3);
    if (sx == 2) sx = -1;
    if (sy == 2) sy = -1;
    off[0][0] = 0, off[0][1] = 0;
    if (sx == 0 && sy == 0) return 1;
    off[1][0] = sx, off[1][1] = sy;
    return 2;
}

static int relocate(cfpo_engine *E, int colour)
{
    const int a_ = colour / E->G.period, b_ = colour % E->G.period;
    const int64_t w = E->w, cells = E->cells;
    const uint32_t *st = E->start;
    uint32_t *ns = E->start2;
    const uint16_t *mask = E->mask;
    if (ensure_cap(E, (size_t)E->nloc + E->narr) != 0) return -1;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t c = 0; c < cells; c++) {
        const int64_t lx = c % w, ly = c / w;
        uint32_t cnt = 0;
        int off[9][2];
        const int no = senders(E, lx, ly, a_, b_, off);
        for (int o = 0; o < no; o++) {
                const int dx = off[o][0], dy = off[o][1];
                const int64_t e = locate(E, lx + dx, ly + dy);
                if (e < 0) continue;
                const unsigned mk = mask[e] & 0x1ffu;
                if (dx == 0 && dy == 0) {
                    if (!(mk & ~CENTRE_BIT)) { cnt += st[c + 1] - st[c]; continue; }
                } else if (!sends_to(mk, -dx, -dy)) continue;
                for (uint32_t k = st[e]; k < st[e + 1]; k++) cnt += in_cell(E, E->px[k], E->py[k], lx, ly);
            }
        if (mask[c] & ARRIVE_BIT)
            for (size_t a = first_arrival(E, c); a < E->narr && E->arr[a].cell == c; a++) cnt++;
        ns[c + 1] = cnt;
    }
    ns[0] = 0;
    for (int64_t c = 0; c < cells; c++) ns[c + 1] += ns[c];
    int maxcell = 0;
#pragma omp parallel for schedule(static) reduction(max : maxcell) num_threads(E->nthreads)
    for (int64_t c = 0; c < cells; c++) {
        const int64_t lx = c % w, ly = c / w;
        uint32_t wpos = ns[c];
        int arrivals = 0;
        int off[9][2];
        const int no = senders(E, lx, ly, a_, b_, off);
        for (int o = 0; o < no; o++) {
                const int dx = off[o][0], dy = off[o][1];
                const int64_t e = locate(E, lx + dx, ly + dy);
                if (e < 0) continue;
                const unsigned mk = mask[e] & 0x1ffu;
                int check;
                if (dx == 0 && dy == 0) check = (mk & ~CENTRE_BIT) != 0;
                else if (sends_to(mk, -dx, -dy)) check = 1, arrivals = 1;
                else continue;
                for (uint32_t k = st[e]; k < st[e + 1]; k++) {
                    if (check && !in_cell(E, E->px[k], E->py[k], lx, ly)) continue;
                    E->tx[wpos] = E->px[k];
                    E->ty[wpos] = E->py[k];
                    E->tid[wpos] = k;
                    wpos++;
                }
            }
        if (mask[c] & ARRIVE_BIT) {
            arrivals = 1;
            for (size_t a = first_arrival(E, c); a < E->narr && E->arr[a].cell == c; a++) {
                const mig_rec *r = &E->arr[a].r;
                E->tx[wpos] = r->x;
                E->ty[wpos] = r->y;
                E->tid[wpos] = ARRIVAL_CODE | a;
                wpos++;
            }
        }
        if (arrivals) /* insertion sort by id; cells hold a handful of points */
            for (uint32_t k = ns[c] + 1; k < wpos; k++) {
                const uint64_t code = E->tid[k], id = id_of(E, code);
                const double x = E->tx[k], y = E->ty[k];
                uint32_t j = k;
                while (j > ns[c] && id_of(E, E->tid[j - 1]) > id) {
                    E->tid[j] = E->tid[j - 1];
                    E->tx[j] = E->tx[j - 1];
                    E->ty[j] = E->ty[j - 1];
                    j--;
                }
                E->tid[j] = code;
                E->tx[j] = x;
                E->ty[j] = y;
            }
        if ((int)(wpos - ns[c]) > maxcell) maxcell = (int)(wpos - ns[c]);
    }
    /* Ids and displacements follow the sources recorded in tid; the new
     * displacements go into the old positions' buffer, free by now. */
    const uint32_t total = ns[cells];
    float *ndq = (float *)E->px;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (uint32_t j = 0; j < total; j++) {
        const uint64_t code = E->tid[j];
        if (code & ARRIVAL_CODE) {
            const mig_rec *r = &E->arr[code & ~ARRIVAL_CODE].r;
            ndq[2 * j] = r->dq[0];
            ndq[2 * j + 1] = r->dq[1];
            E->tid[j] = r->id;
        } else {
            ndq[2 * j] = E->dq[2 * code];
            ndq[2 * j + 1] = E->dq[2 * code + 1];
            E->tid[j] = E->pid[code];
        }
    }
    double *oldx = E->px, *oldy = E->py;
    float *olddq = E->dq;
    E->px = E->tx;
    E->py = E->ty;
    E->dq = (float *)oldx;
    E->tx = (double *)olddq;
    E->ty = oldy;
    uint64_t *u = E->pid; E->pid = E->tid; E->tid = u;
    uint32_t *s = E->start; E->start = E->start2; E->start2 = s;
    E->nloc = E->start[cells];
    E->maxcell = maxcell;
    return ensure_scratch(E);
}

static inline void mark_cell(cfpo_engine *E, int64_t x, int64_t y)
{
    E->mask[y * E->w + x] |= NEED_BIT;
    E->bdirty[(y / SB) * E->nbx + x / SB] = 1;
}

/* Marks the own cells of the 3x3 block around (lx, ly) (an own cell or a
 * halo cell) to be solved again, and their statistics blocks stale. */
static void mark_block(cfpo_engine *E, int64_t lx, int64_t ly)
{
    if (lx >= 1 && lx < E->w - 1 && ly >= 1 && ly < E->h - 1) { /* inside: no wrap, no halo */
        for (int64_t y = ly - 1; y <= ly + 1; y++)
            for (int64_t x = lx - 1; x <= lx + 1; x++) mark_cell(E, x, y);
        return;
    }
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int64_t x = lx + dx, y = ly + dy;
            if (E->wrapx) x = (x % E->w + E->w) % E->w;
            else if (x < 0 || x >= E->w) continue;
            if (E->wrapy) y = (y % E->h + E->h) % E->h;
            else if (y < 0 || y >= E->h) continue;
            mark_cell(E, x, y);
        }
}

/* ---- the halo ---- */

/* Builds, for this tile and its neighbours, which cells go where. The
 * cells of my ring that other ranks own, grouped by owner in my ring
 * order; and for each such owner, the cells of its ring that I own, in its
 * ring order (the order it will unpack them in). */
static int build_neighbours(cfpo_engine *E)
{
    const int64_t g = E->G.g;
    E->nring = 2 * (E->w + 2) + 2 * E->h;
    int *owner = malloc((size_t)E->nring * sizeof *owner);
    if (!owner) return -1;
    for (int64_t i = 0; i < E->nring; i++) {
        int64_t lx, ly;
        ring_coords(E, i, &lx, &ly);
        owner[i] = -1;
        if (locate(E, lx, ly) != -1 - i) continue; /* wraps onto an own cell or another ring cell */
        int64_t gx = (E->x0 + lx + g) % g, gy = (E->y0 + ly + g) % g;
        int r = cfpo_tiling_owner(&E->T, gx, gy);
        owner[i] = r;
        if (neighbour_of_rank(E, r) < 0) {
            neighbour *nb = realloc(E->nb, (size_t)(E->nnb + 1) * sizeof *nb);
            if (!nb) { free(owner); return -1; }
            E->nb = nb;
            memset(&E->nb[E->nnb], 0, sizeof *nb);
            E->nb[E->nnb].rank = r;
            E->nnb++;
        }
    }
    for (int k = 0; k < E->nnb; k++) {
        neighbour *nb = &E->nb[k];
        nb->recv_ring = malloc((size_t)E->nring * sizeof(int64_t));
        if (!nb->recv_ring) { free(owner); return -1; }
        for (int64_t i = 0; i < E->nring; i++)
            if (owner[i] == nb->rank) nb->recv_ring[nb->nrecv++] = i;
        /* The neighbour's tile and ring, walked in its order. */
        const int qx = nb->rank % E->T.px, qy = nb->rank / E->T.px;
        const int64_t qx0 = cfpo_tile_start(g, E->T.px, qx), qw = cfpo_tile_len(g, E->T.px, qx);
        const int64_t qy0 = cfpo_tile_start(g, E->T.py, qy), qh = cfpo_tile_len(g, E->T.py, qy);
        const int64_t qring = 2 * (qw + 2) + 2 * qh;
        nb->send_cells = malloc((size_t)qring * sizeof(int64_t));
        if (!nb->send_cells) { free(owner); return -1; }
        const int qwrapx = E->T.px == 1, qwrapy = E->T.py == 1;
        for (int64_t i = 0; i < qring; i++) {
            int64_t lx, ly, W = qw + 2;
            if (i < W) { lx = i - 1; ly = -1; }
            else if (i < 2 * W) { lx = i - W - 1; ly = qh; }
            else if (i < 2 * W + qh) { lx = -1; ly = i - 2 * W; }
            else { lx = qw; ly = i - 2 * W - qh; }
            /* Skip positions that wrap inside its own tile or onto another
             * ring position (as its locate() would). */
            int64_t wx = lx, wy = ly;
            if (qwrapx) wx = (lx + qw) % qw;
            if (qwrapy) wy = (ly + qh) % qh;
            if (wx != lx || wy != ly) continue;
            int64_t gx = (qx0 + lx + g) % g, gy = (qy0 + ly + g) % g;
            if (cfpo_tiling_owner(&E->T, gx, gy) != E->rank) continue;
            nb->send_cells[nb->nsend++] = (gy - E->y0) * E->w + (gx - E->x0);
        }
    }
    free(owner);
    E->msg = calloc((size_t)(E->nnb > 0 ? E->nnb : 1), sizeof(comm_msg));
    E->hstart = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    E->hstart2 = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    E->hcnt = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    if (!E->msg || !E->hstart || !E->hstart2 || !E->hcnt) return -1;
    for (int k = 0; k < E->nnb; k++) E->msg[k].rank = E->nb[k].rank;
    return 0;
}

/* Sends my border cells to the neighbours that keep them and receives my
 * halo; marks the blocks around every halo cell whose content changed. */
static int refresh_halo(cfpo_engine *E)
{
    if (E->nnb == 0) return 0;
    double t0 = now();
    for (int k = 0; k < E->nnb; k++) {
        neighbour *nb = &E->nb[k];
        size_t pts = 0;
        for (int64_t i = 0; i < nb->nsend; i++) {
            int64_t c = nb->send_cells[i];
            pts += E->start[c + 1] - E->start[c];
        }
        const size_t head = ((size_t)nb->nsend * 4 + 7) & ~(size_t)7;
        const size_t bytes = head + pts * 16;
        if (bytes > nb->hcap) {
            unsigned char *b = realloc(nb->hbuf, bytes + bytes / 2 + 64);
            if (!b) return -1;
            nb->hbuf = b;
            nb->hcap = bytes + bytes / 2 + 64;
        }
        uint32_t *cnt = (uint32_t *)nb->hbuf;
        double *xy = (double *)(nb->hbuf + head);
        size_t m = 0;
        for (int64_t i = 0; i < nb->nsend; i++) {
            int64_t c = nb->send_cells[i];
            cnt[i] = E->start[c + 1] - E->start[c];
            for (uint32_t j = E->start[c]; j < E->start[c + 1]; j++) {
                xy[2 * m] = E->px[j];
                xy[2 * m + 1] = E->py[j];
                m++;
            }
        }
        E->msg[k].send = nb->hbuf;
        E->msg[k].sendbytes = bytes;
        E->b_halo += (double)bytes;
    }
    if (comm_exchange(E->msg, E->nnb) != 0) return -1;
    /* New ring contents: counts, offsets, then coordinates. */
    memset(E->hcnt, 0, ((size_t)E->nring + 1) * sizeof(uint32_t));
    for (int k = 0; k < E->nnb; k++) {
        const neighbour *nb = &E->nb[k];
        const uint32_t *cnt = E->msg[k].recv;
        for (int64_t i = 0; i < nb->nrecv; i++) E->hcnt[nb->recv_ring[i]] = cnt[i];
    }
    E->hstart2[0] = 0;
    for (int64_t i = 0; i < E->nring; i++) E->hstart2[i + 1] = E->hstart2[i] + E->hcnt[i];
    size_t tot = E->hstart2[E->nring];
    if (tot > E->hcap2) {
        size_t c = tot + tot / 2 + 64;
        double *a = realloc(E->hx2, c * sizeof(double)), *b;
        if (!a) return -1;
        E->hx2 = a;
        if (!(b = realloc(E->hy2, c * sizeof(double)))) return -1;
        E->hy2 = b;
        E->hcap2 = c;
    }
    for (int k = 0; k < E->nnb; k++) {
        const neighbour *nb = &E->nb[k];
        const unsigned char *b = E->msg[k].recv;
        const double *xy = (const double *)(b + (((size_t)nb->nrecv * 4 + 7) & ~(size_t)7));
        size_t m = 0;
        for (int64_t i = 0; i < nb->nrecv; i++) {
            int64_t r = nb->recv_ring[i];
            for (uint32_t j = E->hstart2[r]; j < E->hstart2[r + 1]; j++, m++) {
                E->hx2[j] = xy[2 * m];
                E->hy2[j] = xy[2 * m + 1];
            }
        }
    }
    /* Blocks around changed halo cells must be solved again. */
    for (int64_t i = 0; i < E->nring; i++) {
        uint32_t a = E->hstart[i], b = E->hstart[i + 1], a2 = E->hstart2[i], b2 = E->hstart2[i + 1];
        int same = (b - a) == (b2 - a2) && (b == a || (memcmp(E->hx + a, E->hx2 + a2, (b - a) * 8) == 0 &&
                                                       memcmp(E->hy + a, E->hy2 + a2, (b - a) * 8) == 0));
        if (!same) {
            int64_t lx, ly;
            ring_coords(E, i, &lx, &ly);
            mark_block(E, lx, ly);
        }
    }
    uint32_t *s = E->hstart; E->hstart = E->hstart2; E->hstart2 = s;
    double *t = E->hx; E->hx = E->hx2; E->hx2 = t;
    t = E->hy; E->hy = E->hy2; E->hy2 = t;
    size_t c = E->hcap; E->hcap = E->hcap2; E->hcap2 = c;
    E->t_halo += now() - t0;
    return 0;
}

/* ---- checks (config.check) ---- */

static void check_fail(const cfpo_engine *E, const char *what)
{
    fprintf(stderr, "cfpo: rank %d: check failed: %s\n", E->rank, what);
    comm_abort(3);
}

static void check_migration(cfpo_engine *E)
{
    int64_t v[2] = {E->nloc, 0};
    uint64_t sum = 0;
    for (int64_t c = 0; c < E->cells; c++)
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
            sum += cfpo_mix64(E->pid[k]);
            if (!in_cell(E, E->px[k], E->py[k], c % E->w, c / E->w)) check_fail(E, "a point lies outside its cell");
            if (k > E->start[c] && E->pid[k - 1] >= E->pid[k]) check_fail(E, "ids out of order in a cell");
        }
    comm_sum_i64(v, 1);
    int64_t s = (int64_t)sum;
    comm_sum_i64(&s, 1);
    if (v[0] != E->n) check_fail(E, "the global point count changed");
    if ((uint64_t)s != E->id_sum) check_fail(E, "the checksum of point ids changed");
    E->chk_mig++;
}

typedef struct {
    double x, y;
    uint64_t id;
} pt_rec;

static int cmp_cell_id(const void *a, const void *b, const cfpo_grid *G)
{
    const pt_rec *p = a, *q = b;
    int64_t cp = cfpo_grid_coord(G, p->y) * G->g + cfpo_grid_coord(G, p->x);
    int64_t cq = cfpo_grid_coord(G, q->y) * G->g + cfpo_grid_coord(G, q->x);
    if (cp != cq) return cp < cq ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}
static const cfpo_grid *sort_grid;
static int cmp_cell_id_q(const void *a, const void *b) { return cmp_cell_id(a, b, sort_grid); }

/* Every halo cell equals its owner's cell: gathers the whole (small) set. */
static void check_halo(cfpo_engine *E)
{
    if (E->n > 200000) return;
    pt_rec *mine = malloc(((size_t)E->nloc + 1) * sizeof *mine);
    if (!mine) check_fail(E, "out of memory");
    for (int64_t k = 0; k < E->nloc; k++) mine[k] = (pt_rec){E->px[k], E->py[k], E->pid[k]};
    void *all;
    size_t total;
    if (comm_allgatherv(mine, (size_t)E->nloc * sizeof *mine, &all, &total) != 0) check_fail(E, "out of memory");
    free(mine);
    pt_rec *A = all;
    size_t na = total / sizeof *A;
    if ((int64_t)na != E->n) check_fail(E, "gathered set has the wrong size");
    sort_grid = &E->G;
    qsort(A, na, sizeof *A, cmp_cell_id_q);
    const int64_t g = E->G.g;
    int64_t *first = malloc(((size_t)(g * g) + 1) * sizeof *first);
    if (!first) check_fail(E, "out of memory");
    size_t j = 0;
    for (int64_t c = 0; c <= g * g; c++) {
        while (j < na && cfpo_grid_coord(&E->G, A[j].y) * g + cfpo_grid_coord(&E->G, A[j].x) < c) j++;
        first[c] = (int64_t)j;
    }
    for (int64_t i = 0; i < E->nring; i++) {
        int64_t lx, ly;
        ring_coords(E, i, &lx, &ly);
        if (locate(E, lx, ly) != -1 - i) continue;
        int64_t gx = (E->x0 + lx + g) % g, gy = (E->y0 + ly + g) % g, c = gy * g + gx;
        uint32_t a = E->hstart[i], b = E->hstart[i + 1];
        if ((int64_t)(b - a) != first[c + 1] - first[c]) check_fail(E, "a halo cell has the wrong point count");
        for (uint32_t k = a; k < b; k++) {
            const pt_rec *p = &A[first[c] + (k - a)];
            if (p->x != E->hx[k] || p->y != E->hy[k]) check_fail(E, "a halo cell differs from its owner's cell");
        }
    }
    free(first);
    free(A);
    E->chk_halo++;
}

/* ---- the initial set ---- */

/* Ids: cells in row-major order over the whole grid, points of a cell
 * consecutive. The first id of each own cell needs the point counts of all
 * earlier cells: every rank counts a share of the rows, then all share. */
/* The adaptive start: every rank makes the start's points of a band of
 * rows (its share for the row sums, then its tile's rows). */
static int make_initial_adaptive(cfpo_engine *E, char *err, size_t errlen)
{
    const int64_t g = E->G.g;
    int64_t *rowsum = calloc((size_t)g, sizeof *rowsum);
    cfpo_start_pt *pt = NULL;
    if (!rowsum) goto oom;
    int64_t r0 = g * E->rank / E->nranks, r1 = g * (E->rank + 1) / E->nranks;
    int64_t m = cfpo_start_band(&E->G, r0, r1, &pt);
    if (m < 0) goto oom;
    for (int64_t i = 0; i < m; i++) rowsum[pt[i].cell / g]++;
    free(pt);
    pt = NULL;
    comm_sum_i64(rowsum, (int)g); /* rows are disjoint: the sum gathers them */
    int64_t id = 0;
    for (int64_t y = 0; y < E->y0; y++) id += rowsum[y];
    m = cfpo_start_band(&E->G, E->y0, E->y0 + E->h, &pt);
    if (m < 0) goto oom;
    int64_t nloc = 0;
    for (int64_t i = 0; i < m; i++) {
        const int64_t lx = pt[i].cell % g - E->x0;
        if (lx >= 0 && lx < E->w) nloc++;
    }
    if (ensure_cap(E, (size_t)nloc) != 0) goto oom;
    int64_t k = 0, c = 0;
    int maxcell = 0;
    for (int64_t i = 0; i < m; i++, id++) { /* sorted by global cell: row-major */
        const int64_t lx = pt[i].cell % g - E->x0, ly = pt[i].cell / g - E->y0;
        if (lx < 0 || lx >= E->w) continue;
        const int64_t cc = ly * E->w + lx;
        while (c <= cc) E->start[c++] = (uint32_t)k;
        E->px[k] = pt[i].x;
        E->py[k] = pt[i].y;
        E->pid[k] = (uint64_t)id;
        k++;
        if ((int)(k - E->start[cc]) > maxcell) maxcell = (int)(k - E->start[cc]);
    }
    while (c <= E->cells) E->start[c++] = (uint32_t)k;
    E->nloc = k;
    E->maxcell = maxcell;
    free(pt);
    free(rowsum);
    return 0;
oom:
    free(pt);
    free(rowsum);
    snprintf(err, errlen, "out of memory");
    return -1;
}

static int make_initial(cfpo_engine *E, char *err, size_t errlen)
{
    if (E->G.variant == CFPO_VARIANT_ADAPTIVE) return make_initial_adaptive(E, err, errlen);
    const int64_t g = E->G.g;
    const uint64_t cells = (uint64_t)(g * g);
    const int simple = E->G.extra % cells == 0;
    int64_t *rowsum = calloc((size_t)g, sizeof *rowsum);
    if (!rowsum) { snprintf(err, errlen, "out of memory"); return -1; }
    if (!simple) {
        int64_t r0 = g * E->rank / E->nranks, r1 = g * (E->rank + 1) / E->nranks;
#pragma omp parallel for schedule(dynamic, 1) num_threads(E->nthreads)
        for (int64_t y = r0; y < r1; y++) {
            int64_t s = 0;
            for (int64_t x = 0; x < g; x++) s += (int64_t)cfpo_grid_cell_count(&E->G, (uint64_t)(y * g + x));
            rowsum[y] = s;
        }
        comm_sum_i64(rowsum, (int)g); /* rows are disjoint: the sum gathers them */
    } else {
        for (int64_t y = 0; y < g; y++) rowsum[y] = g * (int64_t)(1 + E->G.extra / cells);
    }
    int64_t total = 0;
    for (int64_t y = 0; y < E->y0; y++) total += rowsum[y];
    /* Count own points first (and the points left of the tile in its rows,
     * for the ids). */
    int64_t *cnt = malloc(((size_t)E->cells + (size_t)E->h) * sizeof *cnt);
    if (!cnt) { free(rowsum); snprintf(err, errlen, "out of memory"); return -1; }
    int64_t *left = cnt + E->cells;
#pragma omp parallel for schedule(dynamic, 1) num_threads(E->nthreads)
    for (int64_t ly = 0; ly < E->h; ly++) {
        int64_t s = 0;
        for (int64_t x = 0; x < E->x0; x++) s += (int64_t)cfpo_grid_cell_count(&E->G, (uint64_t)((E->y0 + ly) * g + x));
        left[ly] = s;
        for (int64_t lx = 0; lx < E->w; lx++) cnt[ly * E->w + lx] = (int64_t)cfpo_grid_cell_count(&E->G, (uint64_t)((E->y0 + ly) * g + E->x0 + lx));
    }
    int64_t nloc = 0;
    for (int64_t c = 0; c < E->cells; c++) nloc += cnt[c];
    if (ensure_cap(E, (size_t)nloc) != 0) {
        free(rowsum); free(cnt);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int64_t k = 0;
    int maxcell = 0;
    for (int64_t ly = 0; ly < E->h; ly++) {
        const int64_t gy = E->y0 + ly;
        int64_t id = total + left[ly];
        for (int64_t lx = 0; lx < E->w; lx++) {
            const int64_t c = ly * E->w + lx;
            E->start[c] = (uint32_t)k;
            if ((int)cnt[c] > maxcell) maxcell = (int)cnt[c];
            for (int64_t j = 0; j < cnt[c]; j++) E->pid[k + j] = (uint64_t)(id + j);
            k += cnt[c];
            id += cnt[c];
        }
        total += rowsum[gy];
    }
    E->start[E->cells] = (uint32_t)k;
#pragma omp parallel for schedule(dynamic, 16) num_threads(E->nthreads)
    for (int64_t c = 0; c < E->cells; c++)
        for (int64_t j = 0; j < cnt[c]; j++)
            cfpo_grid_cell_point(&E->G, E->x0 + c % E->w, E->y0 + c / E->w, (uint64_t)j,
                                 &E->px[E->start[c] + j], &E->py[E->start[c] + j]);
    E->nloc = k;
    E->maxcell = maxcell;
    free(rowsum);
    free(cnt);
    return 0;
}

/* ---- checkpoints ---- */

static void put64(unsigned char *b, uint64_t v) { for (int i = 0; i < 8; i++) b[i] = (unsigned char)(v >> (8 * i)); }
static uint64_t get64(const unsigned char *b)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--) v = v << 8 | b[i];
    return v;
}

int cfpo_checkpoint_peek(const char *path, cfpo_checkpoint_info *info, char *err, size_t errlen)
{
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER];
    int ok = size >= CKPT_HEADER && comm_file_read_at(f, 0, h, CKPT_HEADER) == 0;
    comm_file_close(f);
    if (!ok || memcmp(h, CKPT_MAGIC, 8) != 0) {
        snprintf(err, errlen, "%s: not a cfpo checkpoint (bad magic)", path);
        return -1;
    }
    info->n = (int64_t)get64(h + 8);
    info->seed = get64(h + 16);
    info->variant = (int)get64(h + 24);
    uint64_t tb = get64(h + 32);
    memcpy(&info->tol, &tb, 8);
    info->iteration = (int64_t)get64(h + 40);
    info->converged = (int)get64(h + 48);
    if (info->n < 1 || (info->variant != CFPO_VARIANT_PAPER && info->variant != CFPO_VARIANT_SIMPLIFIED &&
                        info->variant != CFPO_VARIANT_ADAPTIVE) ||
        !(info->tol >= 0 && info->tol < 0.5) || info->iteration < 0 || info->iteration > 1000000000) {
        snprintf(err, errlen, "%s: corrupt checkpoint header", path);
        return -1;
    }
    if (size != CKPT_HEADER + 16 * (uint64_t)info->n) {
        snprintf(err, errlen, "%s: checkpoint of %lld points should be %llu bytes, file has %llu (truncated?)",
                 path, (long long)info->n, (unsigned long long)(CKPT_HEADER + 16 * (uint64_t)info->n),
                 (unsigned long long)size);
        return -1;
    }
    return 0;
}

typedef struct {
    double x, y;
    uint64_t id;
} ck_rec;

static void sort3(uint64_t *id, double *x, double *y, int64_t lo, int64_t hi);

/* Every rank reads a contiguous share of ids, sends each point to the rank
 * owning its cell, then builds its buckets. */
static int load_checkpoint(cfpo_engine *E, char *err, size_t errlen)
{
    const char *path = E->cfg.resume;
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    const int P = E->nranks;
    const int64_t lo = E->n * E->rank / P, hi = E->n * (E->rank + 1) / P;
    const int64_t CH = (int64_t)1 << 20;
    int64_t rounds = (hi - lo + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    double *buf = malloc((size_t)CH * 16);
    void **send = calloc((size_t)P, sizeof *send);
    size_t *sb = calloc((size_t)P, sizeof *sb), *scap = calloc((size_t)P, sizeof *scap);
    void **recv = calloc((size_t)P, sizeof *recv);
    size_t *rb = calloc((size_t)P, sizeof *rb);
    int bad = !buf || !send || !sb || !scap || !recv || !rb;
    int64_t badpos = -1;
    size_t have = 0;
    /* received points land in tx/ty/tid */
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = lo + r * CH, b = a + CH < hi ? a + CH : hi;
        if (a > b) a = b;
        for (int q = 0; q < P; q++) sb[q] = 0;
        if (!bad && b > a && comm_file_read_at(f, CKPT_HEADER + 16 * (uint64_t)a, buf, (size_t)(b - a) * 16) != 0)
            bad = 1;
        for (int64_t i = a; !bad && i < b; i++) {
            double x = buf[2 * (i - a)], y = buf[2 * (i - a) + 1];
            if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) {
                badpos = i;
                bad = 1;
                break;
            }
            int q = cfpo_tiling_owner(&E->T, cfpo_grid_coord(&E->G, x), cfpo_grid_coord(&E->G, y));
            if (sb[q] + sizeof(ck_rec) > scap[q]) {
                size_t c = (sb[q] + sizeof(ck_rec)) * 2;
                void *p = realloc(send[q], c);
                if (!p) { bad = 1; break; }
                send[q] = p;
                scap[q] = c;
            }
            ck_rec rec = {x, y, (uint64_t)i};
            memcpy((char *)send[q] + sb[q], &rec, sizeof rec);
            sb[q] += sizeof rec;
        }
        if (!comm_all(!bad)) break;
        if (comm_alltoallv(send, sb, recv, rb) != 0) { bad = 1; break; }
        size_t add = 0;
        for (int q = 0; q < P; q++) add += rb[q] / sizeof(ck_rec);
        if (ensure_cap(E, have + add) != 0) bad = 1;
        for (int q = 0; q < P; q++) {
            const ck_rec *rr = recv[q];
            for (size_t i = 0; !bad && i < rb[q] / sizeof(ck_rec); i++, have++) {
                E->tx[have] = rr[i].x;
                E->ty[have] = rr[i].y;
                E->tid[have] = rr[i].id;
            }
            free(recv[q]);
            recv[q] = NULL;
        }
        if (!comm_all(!bad)) break;
    }
    comm_file_close(f);
    for (int q = 0; send && q < P; q++) free(send[q]);
    free(send); free(sb); free(scap); free(recv); free(rb); free(buf);
    int64_t bp = badpos;
    comm_max_i64(&bp, 1);
    if (!comm_all(!bad)) {
        if (bp >= 0)
            snprintf(err, errlen, "%s: corrupt checkpoint: point %lld at offset %llu is not in [0,1)^2",
                     path, (long long)bp, (unsigned long long)(CKPT_HEADER + 16 * (uint64_t)bp));
        else snprintf(err, errlen, "%s: cannot read the checkpoint (or out of memory)", path);
        return -1;
    }
    /* Counting sort into cells, then id order inside each cell. */
    memset(E->start, 0, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        int64_t c = own_cell_of(E, E->tx[i], E->ty[i]);
        E->start[c + 1]++;
    }
    int maxcell = 0;
    for (int64_t c = 0; c < E->cells; c++) {
        if ((int)E->start[c + 1] > maxcell) maxcell = (int)E->start[c + 1];
        E->start[c + 1] += E->start[c];
    }
    memcpy(E->start2, E->start, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        int64_t c = own_cell_of(E, E->tx[i], E->ty[i]);
        uint32_t k = E->start2[c]++;
        E->px[k] = E->tx[i];
        E->py[k] = E->ty[i];
        E->pid[k] = E->tid[i];
    }
    for (int64_t c = 0; c < E->cells; c++) sort3(E->pid, E->px, E->py, E->start[c], E->start[c + 1]);
    E->nloc = (int64_t)have;
    E->maxcell = maxcell;
    int64_t tot = E->nloc;
    comm_sum_i64(&tot, 1);
    if (tot != E->n) {
        snprintf(err, errlen, "%s: corrupt checkpoint (point count)", path);
        return -1;
    }
    return 0;
}

/* ---- create ---- */

cfpo_engine *cfpo_engine_create(int64_t n, const cfpo_options *o, char *err, size_t errlen)
{
    cfpo_engine_config cfg = {0};
    return cfpo_engine_create_ex(n, o, &cfg, err, errlen);
}

cfpo_engine *cfpo_engine_create_ex(int64_t n, const cfpo_options *o, const cfpo_engine_config *cfg,
                                   char *err, size_t errlen)
{
    const double born = now();
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o->variant, o->seed, err, errlen) != 0) return NULL;
    cfpo_tiling T;
    if (cfpo_tiling_init(&T, G.g, comm_size(), cfg->px, cfg->py, err, errlen) != 0) return NULL;
    cfpo_engine *E = calloc(1, sizeof *E);
    int ok = E != NULL;
    if (!comm_all(ok)) {
        free(E);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    E->G = G;
    E->t_born = born;
    E->dmin_now = 1.0;
    E->T = T;
    E->o = *o;
    E->cfg = *cfg;
    E->n = n;
    E->rank = comm_rank();
    E->nranks = comm_size();
    const int tx = E->rank % T.px, ty = E->rank / T.px;
    E->x0 = cfpo_tile_start(G.g, T.px, tx);
    E->w = cfpo_tile_len(G.g, T.px, tx);
    E->y0 = cfpo_tile_start(G.g, T.py, ty);
    E->h = cfpo_tile_len(G.g, T.py, ty);
    E->wrapx = T.px == 1;
    E->wrapy = T.py == 1;
    E->cells = E->w * E->h;
    E->nthreads = o->threads > 0 ? o->threads : omp_get_num_procs();
    size_t nc = (size_t)E->cells;
    E->start = malloc((nc + 1) * sizeof(uint32_t));
    E->start2 = malloc((nc + 1) * sizeof(uint32_t));
    E->mask = calloc(nc, sizeof(uint16_t));
    E->scratch = calloc((size_t)E->nthreads, sizeof(double *));
    E->nbx = (E->w + SB - 1) / SB;
    E->nby = (E->h + SB - 1) / SB;
    E->bsum = calloc((size_t)(E->nbx * E->nby), sizeof(uint64_t));
    E->bmin = calloc((size_t)(E->nbx * E->nby), sizeof(double));
    E->bdirty = malloc((size_t)(E->nbx * E->nby));
    if (E->bdirty) memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    ok = E->bsum && E->bmin && E->bdirty && E->start && E->start2 && E->mask && E->scratch && build_neighbours(E) == 0;
    if (!comm_all(ok)) {
        snprintf(err, errlen, "out of memory for n = %lld (%.1f GB per rank needed)", (long long)n,
                 (double)cfpo_engine_bytes_local(n / E->nranks, G.g * G.g / E->nranks, 0, E->nthreads) / 1e9);
        cfpo_engine_free(E);
        return NULL;
    }
    for (size_t c = 0; c < nc; c++) E->mask[c] = NEED_BIT;
    int rc = 0;
    if (cfg->resume) {
        cfpo_checkpoint_info info;
        rc = cfpo_checkpoint_peek(cfg->resume, &info, err, errlen);
        if (rc == 0 && (info.n != n || info.seed != o->seed || info.variant != o->variant || info.tol != o->tol)) {
            snprintf(err, errlen, "%s: checkpoint is for another run (n, seed, variant or tol differ)", cfg->resume);
            rc = -1;
        }
        if (rc == 0) {
            E->iter0 = (int)info.iteration;
            E->cur = E->iter0;
            E->G.shift = shift_of(&E->G, E->iter0);
            E->resumed_converged = info.converged;
            rc = load_checkpoint(E, err, errlen);
        }
    } else {
        rc = make_initial(E, err, errlen);
    }
    if (!comm_all(rc == 0)) {
        if (rc == 0) snprintf(err, errlen, "another rank failed to make its points");
        cfpo_engine_free(E);
        return NULL;
    }
    if (ensure_scratch(E) != 0 || ensure_cap(E, (size_t)E->nloc + 1) != 0) rc = -1;
    if (rc == 0 && refresh_halo(E) != 0) rc = -1;
    if (!comm_all(rc == 0)) {
        snprintf(err, errlen, "out of memory");
        cfpo_engine_free(E);
        return NULL;
    }
    if (cfg->check) {
        uint64_t s = 0;
        for (int64_t k = 0; k < E->nloc; k++) s += cfpo_mix64(E->pid[k]);
        int64_t v = (int64_t)s;
        comm_sum_i64(&v, 1);
        E->id_sum = (uint64_t)v;
        check_migration(E);
        check_halo(E);
    }
    E->t_halo = 0;
    E->b_halo = 0;
    return E;
}

/* ---- solving ---- */

/* Copies the 3x3 block around own cell (lx, ly) into local coordinates
 * (origin at the cell's lower-left corner), cells in row-major order, ids
 * ascending inside each: the canonical order of Y. Returns the count;
 * *centre is the index of the centre cell's first point. */
static int gather(const cfpo_engine *E, int64_t lx, int64_t ly, double *ox_, double *oy_, int *centre)
{
    const int64_t g = E->G.g, cx = E->x0 + lx, cy = E->y0 + ly;
    const double L = E->G.L, sh = E->G.shift;
    const double ox = (double)cx * L + sh, oy = (double)cy * L + sh;
    int m = 0;
    if (sh != 0) { /* a shifted grid: the last cell wraps, so unwrap point by point */
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                if (dx == 0 && dy == 0) *centre = m;
                const double mx = ((double)(cx + dx) + 0.5) * L + sh, my = ((double)(cy + dy) + 0.5) * L + sh;
                const int64_t e = locate(E, lx + dx, ly + dy);
                const double *X, *Y;
                uint32_t a, b;
                if (e >= 0) { X = E->px; Y = E->py; a = E->start[e]; b = E->start[e + 1]; }
                else { X = E->hx; Y = E->hy; a = E->hstart[-1 - e]; b = E->hstart[-e]; }
                for (uint32_t k = a; k < b; k++, m++) {
                    ox_[m] = (X[k] + nearbyint(mx - X[k])) - ox;
                    oy_[m] = (Y[k] + nearbyint(my - Y[k])) - oy;
                }
            }
        return m;
    }
    for (int dy = -1; dy <= 1; dy++) {
        const int64_t ny = cy + dy;
        const double sy = ny < 0 ? -1.0 : (ny >= g ? 1.0 : 0.0);
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t nx = cx + dx;
            const double sx = nx < 0 ? -1.0 : (nx >= g ? 1.0 : 0.0);
            if (dx == 0 && dy == 0) *centre = m;
            const int64_t e = locate(E, lx + dx, ly + dy);
            const double *X, *Y;
            uint32_t a, b;
            if (e >= 0) { X = E->px; Y = E->py; a = E->start[e]; b = E->start[e + 1]; }
            else { X = E->hx; Y = E->hy; a = E->hstart[-1 - e]; b = E->hstart[-e]; }
            for (uint32_t k = a; k < b; k++, m++) {
                ox_[m] = (X[k] + sx) - ox;
                oy_[m] = (Y[k] + sy) - oy;
            }
        }
    }
    return m;
}


/* Solves every point of own cell (lx, ly) in id order. Returns moves. */
static int64_t solve_cell(cfpo_engine *E, int64_t lx, int64_t ly, double *buf, int64_t *solved, double *maxmove)
{
    const int64_t g = E->G.g, c = ly * E->w + lx, cx = E->x0 + lx, cy = E->y0 + ly;
    const uint32_t s = E->start[c], e = E->start[c + 1];
    if (s == e) return 0;
    if (E->o.skip && !(E->mask[c] & NEED_BIT)) return 0;
    const size_t mcap = E->scratch_m;
    double *lxs = buf, *lys = buf + mcap, *sol = buf + 2 * mcap;
    int off = 0;
    const int m = gather(E, lx, ly, lxs, lys, &off);
    const cfpo_square S = cfpo_grid_square(&E->G);
    const double tolL = E->o.tol * E->G.L;
    const int adaptive = E->G.variant == CFPO_VARIANT_ADAPTIVE;
    const double ox = (double)cx * E->G.L + E->G.shift, oy = (double)cy * E->G.L + E->G.shift;
    int64_t moves = 0;
    unsigned mask = 0;
    for (uint32_t k = 0; k < e - s; k++) {
        const int gi = off + (int)k;
        const double x = lxs[gi], y = lys[gi];
        const double r02 = cfpo_min_dist2(x, y, lxs, lys, m, gi);
        if (isinf(r02)) continue;
        const double thr = sqrt(r02) + tolL, floor2 = thr * thr;
        double nx, ny;
        cfpo_square Sx = S;
        if (adaptive) {
            /* The square reaches no closer than thr to the points outside
             * the block (negative margins shrink it), so a move raises x's
             * distance to all of X, not only to Y(x): without this, points
             * in holes (r0 > L) cycle between spots forever. */
            if (thr >= 1.5 * E->G.L) continue;
            const double ex = fmin(E->G.margin, E->G.L - thr);
            Sx = (cfpo_square){-ex, -ex, E->G.L + ex, E->G.L + ex};
        }
        const double v = cfpo_local_solve(lxs, lys, m, gi, Sx, x, y, floor2, &nx, &ny, sol);
        (*solved)++;
        if (!(v > floor2)) continue;
        lxs[gi] = nx;
        lys[gi] = ny;
        const double gx = cfpo_wrap01(nx + ox), gy = cfpo_wrap01(ny + oy);
        E->px[s + k] = gx;
        E->py[s + k] = gy;
        const double ddx_ = nx - x, ddy_ = ny - y;
        const double mv = ddx_ * ddx_ + ddy_ * ddy_;
        if (mv > *maxmove) *maxmove = mv;
        E->dq[2 * (s + k)] += (float)ddx_;
        E->dq[2 * (s + k) + 1] += (float)ddy_;
        int ddx = wrap_offset(cfpo_grid_coord(&E->G, gx) - cx, g);
        int ddy = wrap_offset(cfpo_grid_coord(&E->G, gy) - cy, g);
        mask |= 1u << ((ddy + 1) * 3 + (ddx + 1));
        moves++;
    }
    E->mask[c] = (uint16_t)mask; /* and no longer NEED_BIT */
    return moves;
}

/* Own cells of one colour: tile column lx = bx, bx + p, ... */
static inline int64_t first_of(int64_t origin, int p, int64_t want)
{
    return ((want - origin) % p + p) % p;
}

/* Points that crossed into another rank's cell: packed per neighbour. */
static int pack_migrants(cfpo_engine *E, int64_t bx, int64_t by, int64_t nxc, int64_t nyc, int p)
{
    for (int k = 0; k < E->nnb; k++) E->nb[k].nout = 0;
    if (E->nnb == 0) return 0;
    const int64_t g = E->G.g;
    for (int64_t j = 0; j < nyc; j++)
        for (int64_t i = 0; i < nxc; i++) {
            const int64_t lx = bx + p * i, ly = by + p * j, c = ly * E->w + lx;
            const unsigned mk = E->mask[c];
            if (!(mk & ~CENTRE_BIT & 0x1ffu)) continue;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
                const int64_t gx = cfpo_grid_coord(&E->G, E->px[k]), gy = cfpo_grid_coord(&E->G, E->py[k]);
                const int64_t dlx = lx + wrap_offset(gx - (E->x0 + lx), g), dly = ly + wrap_offset(gy - (E->y0 + ly), g);
                if (locate(E, dlx, dly) >= 0) continue;
                const int q = neighbour_of_rank(E, cfpo_tiling_owner(&E->T, gx, gy));
                if (q < 0) return -1;
                neighbour *nb = &E->nb[q];
                if (nb->nout == nb->outcap) {
                    size_t cap = nb->outcap * 2 + 16;
                    mig_rec *o = realloc(nb->out, cap * sizeof *o);
                    if (!o) return -1;
                    nb->out = o;
                    nb->outcap = cap;
                }
                mig_rec *r = &nb->out[nb->nout++];
                memset(r, 0, sizeof *r);
                r->x = E->px[k];
                r->y = E->py[k];
                r->id = E->pid[k];
                r->dq[0] = E->dq[2 * k];
                r->dq[1] = E->dq[2 * k + 1];
            }
        }
    return 0;
}

/* Sends the packed migrants, receives arrivals, sorts them into cells. */
static int exchange_migrants(cfpo_engine *E)
{
    E->narr = 0;
    if (E->nnb == 0) return 0;
    for (int k = 0; k < E->nnb; k++) {
        E->msg[k].send = E->nb[k].out;
        E->msg[k].sendbytes = E->nb[k].nout * sizeof(mig_rec);
        E->b_migrate += (double)E->msg[k].sendbytes;
    }
    if (comm_exchange(E->msg, E->nnb) != 0) return -1;
    size_t tot = 0;
    for (int k = 0; k < E->nnb; k++) tot += E->msg[k].recvbytes / sizeof(mig_rec);
    if (tot > E->arrcap) {
        arrival *a = realloc(E->arr, (tot + 16) * sizeof *a);
        if (!a) return -1;
        E->arr = a;
        E->arrcap = tot + 16;
    }
    for (int k = 0; k < E->nnb; k++) {
        const mig_rec *r = E->msg[k].recv;
        for (size_t i = 0; i < E->msg[k].recvbytes / sizeof(mig_rec); i++) {
            mig_rec rec;
            memcpy(&rec, &r[i], sizeof rec);
            int64_t c = own_cell_of(E, rec.x, rec.y);
            if (c < 0) {
                fprintf(stderr, "cfpo: rank %d received a point outside its tile\n", E->rank);
                comm_abort(3);
            }
            E->arr[E->narr].cell = c;
            E->arr[E->narr].r = rec;
            E->narr++;
        }
    }
    if (E->narr > 1) qsort(E->arr, E->narr, sizeof *E->arr, cmp_arrival);
    for (size_t i = 0; i < E->narr; i++) {
        int64_t c = E->arr[i].cell;
        E->mask[c] |= ARRIVE_BIT;
        mark_block(E, c % E->w, c / E->w);
    }
    return 0;
}

/* After the cells of one colour changed (points moved, or the grid moved
 * under them): mark the blocks that changed, send points that left the
 * tile, move points that changed cell, clear the masks, refresh the halo.
 * `moves`: whether any cell of the colour has mask bits. */
static void settle(cfpo_engine *E, int colour, int64_t moves)
{
    const int p = E->G.period;
    const int64_t a = colour / p, b = colour % p;
    const int64_t bx = first_of(E->x0, p, b), by = first_of(E->y0, p, a);
    const int64_t nxc = bx < E->w ? (E->w - bx + p - 1) / p : 0, nyc = by < E->h ? (E->h - by + p - 1) / p : 0;
    const int64_t T = nxc * nyc;
    double t1 = now();
    int crossed = 0;
    if (moves)
        for (int64_t t = 0; t < T; t++) {
            const int64_t ly = by + p * (t / nxc), lx = bx + p * (t % nxc), c = ly * E->w + lx;
            const unsigned mk = E->mask[c] & 0x1ffu;
            if (!mk) continue;
            mark_block(E, lx, ly);
            for (int bit = 0; bit < 9; bit++)
                if (bit != 4 && (mk >> bit & 1u)) {
                    crossed = 1;
                    mark_block(E, lx + bit % 3 - 1, ly + bit / 3 - 1);
                }
        }
    int rc = 0;
    if (crossed && pack_migrants(E, bx, by, nxc, nyc, p) != 0) rc = -1;
    if (!crossed)
        for (int k = 0; k < E->nnb; k++) E->nb[k].nout = 0;
    if (rc == 0 && exchange_migrants(E) != 0) rc = -1;
    if (rc == 0 && (crossed || E->narr) && relocate(E, colour) != 0) rc = -1;
    if (rc != 0) {
        fprintf(stderr, "cfpo: rank %d: out of memory while moving points between cells\n", E->rank);
        comm_abort(1);
    }
    if (moves)
        for (int64_t t = 0; t < T; t++) E->mask[(by + p * (t / nxc)) * E->w + bx + p * (t % nxc)] &= NEED_BIT;
    for (size_t i = 0; i < E->narr; i++) E->mask[E->arr[i].cell] &= (uint16_t)~ARRIVE_BIT;
    E->narr = 0;
    double t2 = now();
    E->t_migrate += t2 - t1;
    if (E->cfg.check && !E->shifting) check_migration(E);
    if (refresh_halo(E) != 0) {
        fprintf(stderr, "cfpo: rank %d: out of memory while refreshing the halo\n", E->rank);
        comm_abort(1);
    }
    if (E->cfg.check && !E->shifting) check_halo(E);
}

int64_t cfpo_engine_phase(cfpo_engine *E, int colour, int64_t *solved)
{
    const int p = E->G.period;
    const int64_t a = colour / p, b = colour % p;
    const int64_t bx = first_of(E->x0, p, b), by = first_of(E->y0, p, a);
    const int64_t nxc = bx < E->w ? (E->w - bx + p - 1) / p : 0, nyc = by < E->h ? (E->h - by + p - 1) / p : 0;
    const int64_t T = nxc * nyc;
    int64_t moves = 0, solv = 0;
    double mm = E->max_move;
    double t0 = now();
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : moves, solv) reduction(max : mm) num_threads(E->nthreads)
    for (int64_t t = 0; t < T; t++) {
        const int64_t ly = by + p * (t / nxc), lx = bx + p * (t % nxc);
        moves += solve_cell(E, lx, ly, E->scratch[omp_get_thread_num()], &solv, &mm);
    }
    E->max_move = mm;
    *solved = solv;
    E->t_compute += now() - t0;
    E->phases++;
    settle(E, colour, moves);
    return moves;
}

/* Moves the grid under the points to offset `shift` (both axes): colour by
 * colour, the points of each cell go to the cell that holds them now
 * (the same or a neighbour, as |change| < L), through the same steps as a
 * phase's moves. Then every cell is solved again and every statistics
 * block recomputed (each cell's frame and constraint square moved). */
static void move_grid(cfpo_engine *E, double shift)
{
    E->G.shift = shift;
    E->shifting = 1;
    const int p = E->G.period, g = (int)E->G.g;
    for (int colour = 0; colour < p * p; colour++) {
        const int64_t a = colour / p, b = colour % p;
        const int64_t bx = first_of(E->x0, p, b), by = first_of(E->y0, p, a);
        const int64_t nxc = bx < E->w ? (E->w - bx + p - 1) / p : 0, nyc = by < E->h ? (E->h - by + p - 1) / p : 0;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
        for (int64_t t = 0; t < nxc * nyc; t++) {
            const int64_t ly = by + p * (t / nxc), lx = bx + p * (t % nxc), c = ly * E->w + lx;
            const int64_t cx = E->x0 + lx, cy = E->y0 + ly;
            unsigned mask = 0;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
                int ddx = wrap_offset(cfpo_grid_coord(&E->G, E->px[k]) - cx, g);
                int ddy = wrap_offset(cfpo_grid_coord(&E->G, E->py[k]) - cy, g);
                mask |= 1u << ((ddy + 1) * 3 + (ddx + 1));
            }
            E->mask[c] = (uint16_t)((E->mask[c] & NEED_BIT) | mask);
        }
        settle(E, colour, 1);
    }
    E->shifting = 0;
    for (int64_t c = 0; c < E->cells; c++) E->mask[c] |= NEED_BIT;
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    if (E->cfg.check) {
        check_migration(E);
        check_halo(E);
    }
}

/* ---- statistics ---- */

typedef struct {
    double x, y, best;
    uint64_t id;
    int64_t owner;
} nn_query;

/* Nearest-neighbour distance^2 of own point k of own cell (lx, ly) within
 * the 3x3 block; *sure says whether no point outside the block can be
 * nearer. */
static double nn2_block(const cfpo_engine *E, int64_t lx, int64_t ly, uint32_t k, int *sure)
{
    const double L = E->G.L, x = E->px[k], y = E->py[k];
    const double ex = cell_offset(E, x, E->x0 + lx), ey = cell_offset(E, y, E->y0 + ly);
    double edge = fmin(fmin(ex, L - ex), fmin(ey, L - ey));
    if (edge < 0) edge = 0;
    double best = INFINITY;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t e = locate(E, lx + dx, ly + dy);
            const double *X, *Y;
            uint32_t a, b;
            if (e >= 0) { X = E->px; Y = E->py; a = E->start[e]; b = E->start[e + 1]; }
            else { X = E->hx; Y = E->hy; a = E->hstart[-1 - e]; b = E->hstart[-e]; }
            for (uint32_t j = a; j < b; j++) {
                if (e >= 0 && j == k) continue;
                double d2 = cfpo_torus_dist2(x, y, X[j], Y[j]);
                if (d2 < best) best = d2;
            }
        }
    /* With 3 or fewer cells per side the block already wraps onto the
     * whole torus. */
    const double reach = L + edge;
    *sure = best <= reach * reach || E->G.g <= 3;
    return best;
}

/* Nearest own point to a query (excluding its id) among own cells within
 * B cells of the query's cell. */
static double box_min(const cfpo_engine *E, const nn_query *q, int64_t B)
{
    const int64_t g = E->G.g;
    double best = INFINITY;
    if (2 * B + 1 >= g) {
        for (int64_t k = 0; k < E->nloc; k++)
            if (E->pid[k] != q->id) {
                double d2 = cfpo_torus_dist2(q->x, q->y, E->px[k], E->py[k]);
                if (d2 < best) best = d2;
            }
        return best;
    }
    const int64_t qx = cfpo_grid_coord(&E->G, q->x), qy = cfpo_grid_coord(&E->G, q->y);
    for (int64_t dy = -B; dy <= B; dy++) {
        int64_t ly = (qy + dy + g) % g - E->y0;
        if (ly < 0 || ly >= E->h) continue;
        for (int64_t dx = -B; dx <= B; dx++) {
            int64_t lx = (qx + dx + g) % g - E->x0;
            if (lx < 0 || lx >= E->w) continue;
            int64_t c = ly * E->w + lx;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++)
                if (E->pid[k] != q->id) {
                    double d2 = cfpo_torus_dist2(q->x, q->y, E->px[k], E->py[k]);
                    if (d2 < best) best = d2;
                }
        }
    }
    return best;
}

void cfpo_engine_deltas(cfpo_engine *E, double *dmin, double *davg)
{
    const double inv = 1.0 / E->G.delta;
    uint64_t sum = 0;
    double mn = INFINITY;
    nn_query *un = NULL;
    size_t nun = 0, uncap = 0;
    int oom = 0;
    /* Blocks whose cells' neighbourhoods did not change keep their sums. */
    const int64_t nb = E->nbx * E->nby;
#pragma omp parallel for schedule(dynamic, 4) num_threads(E->nthreads)
    for (int64_t bi = 0; bi < nb; bi++) {
        if (!E->bdirty[bi]) continue;
        const int64_t bx0 = (bi % E->nbx) * SB, by0 = (bi / E->nbx) * SB;
        const int64_t bx1 = bx0 + SB < E->w ? bx0 + SB : E->w, by1 = by0 + SB < E->h ? by0 + SB : E->h;
        uint64_t bs = 0;
        double bm = INFINITY;
        int unsure = 0;
        for (int64_t ly = by0; ly < by1; ly++)
            for (int64_t lx = bx0; lx < bx1; lx++) {
            const int64_t c = ly * E->w + lx;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
                int sure;
                double d2 = nn2_block(E, lx, ly, k, &sure);
                if (sure) {
                    double d = sqrt(d2) * inv;
                    bs += (uint64_t)llround(fmin(d, 1e6) * SUM_SCALE);
                    if (d < bm) bm = d;
                } else {
                    unsure = 1;
#pragma omp critical(cfpo_unresolved)
                    {
                        if (nun == uncap) {
                            size_t cap = uncap * 2 + 64;
                            nn_query *q = realloc(un, cap * sizeof *q);
                            if (q) { un = q; uncap = cap; }
                            else oom = 1;
                        }
                        if (nun < uncap) un[nun++] = (nn_query){E->px[k], E->py[k], d2, E->pid[k], E->rank};
                    }
                }
            }
        }
        E->bsum[bi] = bs;
        E->bmin[bi] = bm;
        E->bdirty[bi] = (uint8_t)unsure; /* blocks with unresolved points: every time */
    }
    for (int64_t bi = 0; bi < nb; bi++) {
        sum += E->bsum[bi];
        if (E->bmin[bi] < mn) mn = E->bmin[bi];
    }
    if (!comm_all(!oom)) {
        fprintf(stderr, "cfpo: rank %d: out of memory in statistics\n", E->rank);
        comm_abort(1);
    }
    /* Points whose nearest neighbour may lie outside their block: ask every
     * rank for its nearest points within B cells, doubling B until the
     * answer is certain. Rare after the first iteration. */
    void *allv;
    size_t total;
    if (comm_allgatherv(un, nun * sizeof *un, &allv, &total) != 0) {
        fprintf(stderr, "cfpo: rank %d: out of memory in statistics\n", E->rank);
        comm_abort(1);
    }
    free(un);
    nn_query *Q = allv;
    size_t nq = total / sizeof *Q;
    if (nq) {
        double *res = malloc(nq * sizeof *res);
        int64_t *B = malloc(nq * sizeof *B);
        uint8_t *done = calloc(nq, 1);
        if (!res || !B || !done) {
            fprintf(stderr, "cfpo: rank %d: out of memory in statistics\n", E->rank);
            comm_abort(1);
        }
        for (size_t i = 0; i < nq; i++) B[i] = 2;
        const double L = E->G.L;
        for (;;) {
#pragma omp parallel for schedule(dynamic, 64) num_threads(E->nthreads)
            for (size_t i = 0; i < nq; i++) res[i] = done[i] ? INFINITY : box_min(E, &Q[i], B[i]);
            comm_min_d(res, (int)nq);
            int left = 0;
            for (size_t i = 0; i < nq; i++) {
                if (done[i]) continue;
                const nn_query *q = &Q[i];
                int64_t cx = cfpo_grid_coord(&E->G, q->x), cy = cfpo_grid_coord(&E->G, q->y);
                double ex = cell_offset(E, q->x, cx), ey = cell_offset(E, q->y, cy);
                double edge = fmax(0, fmin(fmin(ex, L - ex), fmin(ey, L - ey)));
                double reach = (double)B[i] * L + edge;
                if (res[i] <= reach * reach || 2 * B[i] + 1 >= E->G.g) {
                    done[i] = 1;
                    if (q->owner == E->rank) {
                        double d = sqrt(res[i]) * inv;
                        sum += (uint64_t)llround(fmin(d, 1e6) * SUM_SCALE);
                        if (d < mn) mn = d;
                    }
                } else {
                    B[i] *= 2;
                    left = 1;
                }
            }
            if (!left) break;
        }
        free(res);
        free(B);
        free(done);
    }
    free(Q);
    /* Exact integer sums: the same bits for any split into ranks. */
    int64_t *all = malloc((size_t)E->nranks * sizeof *all);
    if (!all) comm_abort(1);
    comm_allgather_i64((int64_t)sum, all);
    unsigned __int128 S = 0;
    for (int r = 0; r < E->nranks; r++) S += (uint64_t)all[r];
    free(all);
    comm_min_d(&mn, 1);
    E->dmin_now = mn;
    *dmin = mn;
    *davg = (double)((long double)S / SUM_SCALE / (long double)E->n);
}

/* The adaptive variant's margin for the coming iteration: S reaches
 * L - max(delta(X), theta Delta(n)) past the cell, the most the
 * convergence argument allows while delta(X) is large, and no more than
 * L - theta Delta(n) early on (delta(X) taken a hair high, so rounding
 * can only shrink S). */
void cfpo_engine_begin(cfpo_engine *E)
{
    E->cur++;
    if (E->G.variant != CFPO_VARIANT_ADAPTIVE) return;
    const double d = fmax(E->dmin_now * (1 + 1e-9), ADAPTIVE_THETA) * E->G.delta;
    E->G.margin = d < E->G.L ? E->G.L - d : 0;
    const double sh = shift_of(&E->G, E->cur);
    if (sh != E->G.shift) move_grid(E, sh);
}

void cfpo_engine_iterate(cfpo_engine *E, cfpo_iter_stats *s)
{
    double t0 = now();
    cfpo_engine_begin(E);
    memset(E->dq, 0, 2 * (size_t)E->nloc * sizeof(float));
    E->max_move = 0;
    int64_t moved = 0, solved = 0;
    const int ncol = E->G.period * E->G.period;
    for (int colour = 0; colour < ncol; colour++) {
        int64_t sv = 0;
        moved += cfpo_engine_phase(E, colour, &sv);
        solved += sv;
    }
    /* Every rank looks: a point that moved may have migrated to a rank
     * that moved none itself. */
    double maxd2 = 0;
#pragma omp parallel for schedule(static) reduction(max : maxd2) num_threads(E->nthreads)
    for (int64_t i = 0; i < E->nloc; i++) {
        double dx = E->dq[2 * i], dy = E->dq[2 * i + 1];
        double d2 = dx * dx + dy * dy;
        if (d2 > maxd2) maxd2 = d2;
    }
    int64_t v[2] = {moved, solved};
    comm_sum_i64(v, 2);
    double mx[2] = {maxd2, E->max_move};
    comm_max_d(mx, 2);
    s->moved = v[0];
    s->solved = v[1];
    s->max_disp = sqrt(mx[0]) / E->G.L;
    s->max_move = sqrt(mx[1]) / E->G.L;
    s->converged = v[0] == 0 || s->max_disp < E->o.tol;
    cfpo_engine_deltas(E, &s->delta_min, &s->delta_avg);
    double el = now() - t0;
    comm_max_d(&el, 1);
    s->seconds = el;
}

/* ---- output ---- */

static void sort3(uint64_t *id, double *x, double *y, int64_t lo, int64_t hi)
{
    while (hi - lo > 16) {
        int64_t mid = lo + (hi - lo) / 2;
        uint64_t a = id[lo], b = id[mid], c = id[hi - 1];
        uint64_t piv = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
        int64_t i = lo, j = hi - 1;
        while (i <= j) {
            while (id[i] < piv) i++;
            while (id[j] > piv) j--;
            if (i <= j) {
                uint64_t t = id[i]; id[i] = id[j]; id[j] = t;
                double u = x[i]; x[i] = x[j]; x[j] = u;
                u = y[i]; y[i] = y[j]; y[j] = u;
                i++;
                j--;
            }
        }
        if (j + 1 - lo < hi - i) { sort3(id, x, y, lo, j + 1); lo = i; }
        else { sort3(id, x, y, i, hi); hi = j + 1; }
    }
    for (int64_t k = lo + 1; k < hi; k++) {
        uint64_t t = id[k];
        double u = x[k], v = y[k];
        int64_t j = k;
        while (j > lo && id[j - 1] > t) { id[j] = id[j - 1]; x[j] = x[j - 1]; y[j] = y[j - 1]; j--; }
        id[j] = t; x[j] = u; y[j] = v;
    }
}

int cfpo_engine_write_points(cfpo_engine *E, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    /* Own points in id order, in the spare buffers. */
    memcpy(E->tid, E->pid, (size_t)E->nloc * sizeof(uint64_t));
    memcpy(E->tx, E->px, (size_t)E->nloc * sizeof(double));
    memcpy(E->ty, E->py, (size_t)E->nloc * sizeof(double));
    sort3(E->tid, E->tx, E->ty, 0, E->nloc);
    /* In pieces of CH points: each piece is one collective write of its
     * runs of consecutive ids. */
    const int64_t CH = (int64_t)1 << 20;
    int64_t rounds = (E->nloc + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    double *buf = malloc((size_t)CH * 16);
    uint64_t *first = malloc((size_t)CH * sizeof *first), *len = malloc((size_t)CH * sizeof *len);
    int ok = buf && first && len;
    if (!comm_all(ok)) {
        free(buf); free(first); free(len);
        snprintf(err, errlen, "out of memory while writing");
        return -1;
    }
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = r * CH, b = a + CH < E->nloc ? a + CH : E->nloc;
        if (a > b) a = b;
        int64_t nr = 0;
        for (int64_t i = a; i < b; i++) {
            buf[2 * (i - a)] = E->tx[i];
            buf[2 * (i - a) + 1] = E->ty[i];
            if (nr > 0 && first[nr - 1] + len[nr - 1] == E->tid[i]) len[nr - 1]++;
            else { first[nr] = E->tid[i]; len[nr] = 1; nr++; }
        }
        if (comm_file_write_runs(f, base, 16, buf, nr, first, len) != 0) ok = 0;
    }
    free(buf); free(first); free(len);
    if (!comm_all(ok)) {
        snprintf(err, errlen, "write failed (disk full or file system error)");
        return -1;
    }
    return 0;
}

int cfpo_engine_write(cfpo_engine *E, pf_writer *w, char *err, size_t errlen)
{
    for (int64_t i = 0; i < E->nloc; i++) {
        E->tx[E->pid[i]] = E->px[i];
        E->ty[E->pid[i]] = E->py[i];
    }
    enum { CHUNK = 4096 };
    double buf[2 * CHUNK];
    for (int64_t i = 0; i < E->n; i += CHUNK) {
        int64_t cnt = E->n - i < CHUNK ? E->n - i : CHUNK;
        for (int64_t j = 0; j < cnt; j++) {
            buf[2 * j] = E->tx[i + j];
            buf[2 * j + 1] = E->ty[i + j];
        }
        if (pf_writer_put(w, buf, (size_t)cnt, err, errlen) != 0) return -1;
    }
    return 0;
}

void cfpo_engine_points(const cfpo_engine *E, double *xy)
{
    for (int64_t i = 0; i < E->nloc; i++) {
        xy[2 * E->pid[i]] = E->px[i];
        xy[2 * E->pid[i] + 1] = E->py[i];
    }
}

static int write_checkpoint(cfpo_engine *E, int iteration, int converged, char *err, size_t errlen)
{
    comm_file *f = comm_file_create(E->cfg.checkpoint, err, errlen);
    if (!f) return -1;
    int ok = 1;
    if (E->rank == 0) {
        unsigned char h[CKPT_HEADER] = {0};
        memcpy(h, CKPT_MAGIC, 8);
        put64(h + 8, (uint64_t)E->n);
        put64(h + 16, E->o.seed);
        put64(h + 24, (uint64_t)E->o.variant);
        uint64_t tb;
        memcpy(&tb, &E->o.tol, 8);
        put64(h + 32, tb);
        put64(h + 40, (uint64_t)iteration);
        put64(h + 48, (uint64_t)converged);
        ok = comm_file_write_at(f, 0, h, sizeof h) == 0;
    }
    char e2[256];
    if (cfpo_engine_write_points(E, f, CKPT_HEADER, e2, sizeof e2) != 0) ok = 0;
    return comm_file_commit(f, ok, err, errlen);
}

int cfpo_engine_run(cfpo_engine *E, cfpo_result *res, char *err, size_t errlen)
{
    double t0 = now();
    cfpo_iter_stats s = {0};
    s.iteration = E->iter0;
    s.converged = E->resumed_converged;
    cfpo_engine_deltas(E, &s.delta_min, &s.delta_avg);
    s.seconds = now() - t0;
    /* Seconds since the engine was created, the start included, reduced
     * over ranks: every rank stops at the same iteration. */
    double elapsed = now() - E->t_born;
    comm_max_d(&elapsed, 1);
    int why = cfpo_stop_check(&E->o.stop, &s, elapsed, E->o.max_iter);
    if (E->o.progress && E->o.progress(&s, E->o.user) && !why) why = CFPO_STOP_CALLER;
    int it = E->iter0, rc = 0;
    while (!why) {
        cfpo_engine_iterate(E, &s);
        s.iteration = ++it;
        elapsed += s.seconds;
        why = cfpo_stop_check(&E->o.stop, &s, elapsed, E->o.max_iter);
        if (E->o.progress && E->o.progress(&s, E->o.user) && !why) why = CFPO_STOP_CALLER;
        if (E->cfg.checkpoint && E->cfg.checkpoint_every > 0 && it % E->cfg.checkpoint_every == 0 &&
            write_checkpoint(E, it, s.converged, err, errlen) != 0) {
            rc = -1;
            break;
        }
    }
    E->iter0 = it;
    res->iterations = it;
    res->converged = s.converged;
    res->stop = why;
    res->seconds = now() - t0;
    res->delta_min = s.delta_min;
    res->delta_avg = s.delta_avg;
    res->cells_per_side = E->G.g;
    return rc;
}

void cfpo_engine_timing_get(cfpo_engine *E, cfpo_engine_timing *t)
{
    double v[5] = {E->t_compute, E->t_migrate, E->t_halo, E->b_halo, E->b_migrate};
    double mn[5], mx[5], sm[5];
    for (int i = 0; i < 5; i++) mn[i] = mx[i] = sm[i] = v[i];
    comm_min_d(mn, 5);
    comm_max_d(mx, 5);
    comm_sum_d(sm, 5);
    double *dst[5] = {t->compute, t->migrate, t->halo, t->halo_bytes, t->migrate_bytes};
    for (int i = 0; i < 5; i++) {
        dst[i][0] = mn[i];
        dst[i][1] = sm[i] / E->nranks;
        dst[i][2] = mx[i];
    }
    t->phases = E->phases;
    t->checked_migrations = E->chk_mig;
    t->checked_halos = E->chk_halo;
}
