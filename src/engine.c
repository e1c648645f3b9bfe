/* engine.c - see engine.h; the engine's files are listed in engine_impl.h.
 *
 * Why a phase is race-free (written once, here): cells of one colour are
 * `period` cells apart in both directions, on the whole torus, whatever the
 * tiles. A point of cell C may move only inside S(x), C grown by a margin
 * below L (L - Delta(n) in the paper's variant, at most L - delta(X) in the
 * adaptive one), so it stays in C's 3x3 block, and solving C reads only
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
#include "engine_impl.h"
#include "start.h"
#include "stoprule.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"
#include "rng.h"


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

int eng_ensure_scratch(cfpo_engine *E)
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
int eng_ensure_cap(cfpo_engine *E, size_t need)
{
    if (need <= E->cap) return 0;
    size_t cap = need + need / 16 + 1024;
    /* Five buffers of 8 bytes a slot swap roles in eng_relocate(), so they
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

/* The adaptive variant's grid offset in iteration k (0 before the first). */
static double shift_of(const cfpo_grid *G, int k)
{
    if (G->variant != CFPO_VARIANT_ADAPTIVE || k <= 0) return 0;
    k -= (k - 1) % SHIFT_EVERY; /* the shift of the group of iterations k belongs to */
    return G->L * cfpo_rand01(G->seed ^ SHIFT_SALT, (uint64_t)k, 0);
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
    ok = E->bsum && E->bmin && E->bdirty && E->start && E->start2 && E->mask && E->scratch && eng_build_neighbours(E) == 0;
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
            rc = eng_load_checkpoint(E, err, errlen);
        }
    } else {
        rc = eng_make_initial(E, err, errlen);
    }
    if (!comm_all(rc == 0)) {
        if (rc == 0) snprintf(err, errlen, "another rank failed to make its points");
        cfpo_engine_free(E);
        return NULL;
    }
    if (eng_ensure_scratch(E) != 0 || eng_ensure_cap(E, (size_t)E->nloc + 1) != 0) rc = -1;
    if (rc == 0 && eng_refresh_halo(E) != 0) rc = -1;
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
        eng_check_migration(E);
        eng_check_halo(E);
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
                cell_slice(E, e, &X, &Y, &a, &b);
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
            cell_slice(E, e, &X, &Y, &a, &b);
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
            eng_mark_block(E, lx, ly);
            for (int bit = 0; bit < 9; bit++)
                if (bit != 4 && (mk >> bit & 1u)) {
                    crossed = 1;
                    eng_mark_block(E, lx + bit % 3 - 1, ly + bit / 3 - 1);
                }
        }
    int rc = 0;
    if (crossed && eng_pack_migrants(E, bx, by, nxc, nyc, p) != 0) rc = -1;
    if (!crossed)
        for (int k = 0; k < E->nnb; k++) E->nb[k].nout = 0;
    if (rc == 0 && eng_exchange_migrants(E) != 0) rc = -1;
    if (rc == 0 && (crossed || E->narr) && eng_relocate(E, colour) != 0) rc = -1;
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
    if (E->cfg.check && !E->shifting) eng_check_migration(E);
    if (eng_refresh_halo(E) != 0) {
        fprintf(stderr, "cfpo: rank %d: out of memory while refreshing the halo\n", E->rank);
        comm_abort(1);
    }
    if (E->cfg.check && !E->shifting) eng_check_halo(E);
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
        eng_check_migration(E);
        eng_check_halo(E);
    }
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
    s->converged = cfpo_net_converged(v[0], s->max_disp, E->o.tol);
    cfpo_engine_deltas(E, &s->delta_min, &s->delta_avg);
    double el = now() - t0;
    comm_max_d(&el, 1);
    s->seconds = el;
}

/* ---- output ---- */

void eng_sort3(uint64_t *id, double *x, double *y, int64_t lo, int64_t hi)
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
        if (j + 1 - lo < hi - i) { eng_sort3(id, x, y, lo, j + 1); lo = i; }
        else { eng_sort3(id, x, y, i, hi); hi = j + 1; }
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
    eng_sort3(E->tid, E->tx, E->ty, 0, E->nloc);
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
            eng_write_checkpoint(E, it, s.converged, err, errlen) != 0) {
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
