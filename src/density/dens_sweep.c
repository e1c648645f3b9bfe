/* dens_sweep.c - layer 3: one iteration's phases of the density engine
 * (dens_engine.h): the cells of a grid and their blocks' buffers; the nine
 * colour phases on the one grid, with the skip; and on the levels of
 * cells sized to the local spacing (dens_levels.h), level by level. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "dens_impl.h"
#include "dens_levels.h"
#include "dens_solve.h"
#include "omp_compat.h"

/* Cells of this iteration's grid, points in id order inside each (the
 * store's order: own points by id, then each halo cell's from its owner,
 * by id). */
static void build_from(cfpo_dens_engine *E);

void dens_build_cells(cfpo_dens_engine *E)
{
    for (int64_t i = 0; i < E->s.loc; i++) E->cell[i] = cell_of(E, E->s.xy[2 * i], E->s.xy[2 * i + 1]);
    build_from(E);
}

void dens_build_level(cfpo_dens_engine *E, int l)
{
    const int sh = E->lv.n - 1 - l;
    const int64_t g = E->lv.g0 << l;
    for (int64_t i = 0; i < E->s.loc; i++) E->cell[i] = (int64_t)(E->fine[i] >> 16 >> sh) * g + ((E->fine[i] & 0xffff) >> sh);
    build_from(E);
}

/* the cells from E->cell */
static void build_from(cfpo_dens_engine *E)
{
    const int64_t G = E->g * E->g;
    memset(E->cstart, 0, (size_t)(G + 1) * sizeof *E->cstart);
    for (int64_t i = 0; i < E->s.loc; i++) E->cstart[E->cell[i] + 1]++;
    for (int64_t c = 0; c < G; c++) E->cstart[c + 1] += E->cstart[c];
    for (int64_t i = 0; i < E->s.loc; i++) E->cidx[E->cstart[E->cell[i]]++] = i;
    for (int64_t c = G; c > 0; c--) E->cstart[c] = E->cstart[c - 1];
    E->cstart[0] = 0;
    if (E->slot)
        for (int64_t s = 0; s < E->s.loc; s++) E->slot[E->cidx[s]] = s;
    /* the solves gather their blocks from this copy, one cell's points
     * side by side, instead of from the store in id order */
    for (int64_t s = 0; s < E->s.loc; s++) {
        const int64_t j = E->cidx[s];
        E->cxyq[3 * s] = E->s.xy[2 * j];
        E->cxyq[3 * s + 1] = E->s.xy[2 * j + 1];
        E->cxyq[3 * s + 2] = E->s.q[j];
    }
}

static int64_t block_count(const cfpo_dens_engine *E, int64_t cx, int64_t cy)
{
    int64_t m = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t c = ((cy + dy + E->g) % E->g) * E->g + (cx + dx + E->g) % E->g;
            m += E->cstart[c + 1] - E->cstart[c];
        }
    return m;
}

static int ensure_buffers(cfpo_dens_engine *E, size_t m)
{
    for (int t = 0; t < E->nthreads; t++) {
        tbuf *b = &E->tb[t];
        if (b->cap >= m) continue;
        size_t cap = m + m / 2 + 16;
        free(b->bx); free(b->bid); free(b->bslot); free(b->scratch); free(b->nj);
        b->bx = malloc(6 * cap * sizeof *b->bx + 3 * (KMAX + KADD + 1) * sizeof *b->bx);
        b->bid = malloc(cap * sizeof *b->bid);
        b->bslot = malloc(cap * sizeof *b->bslot);
        b->scratch = malloc((KMAX + cfpo_dens_scratch(KMAX + KADD)) * sizeof *b->scratch);
        b->nj = malloc((KMAX + KADD + 1) * sizeof *b->nj);
        if (!b->bx || !b->bid || !b->bslot || !b->scratch || !b->nj) return -1;
        b->by = b->bx + cap;
        b->br = b->by + cap;
        b->ck = b->br + cap; /* a scan's candidates: their keys, their indices */
        b->cj = b->ck + cap;
        b->nx = b->bx + 6 * cap; /* nx, ny, nr: KMAX + KADD + 1 each */
        b->ny = b->nx + KMAX + KADD + 1;
        b->nr = b->ny + KMAX + KADD + 1;
        b->cap = cap;
    }
    return 0;
}

/* Solves cell c unless nothing in its block changed since it was last
 * solved without a move (then the solve would move nothing again: it
 * reads only the block); marks the cells whose blocks a move changed.
 * Cells of one colour have disjoint 3 x 3 neighbourhoods, so the marks of
 * cells solved in parallel never meet. */
static int64_t visit_cell(cfpo_dens_engine *E, tbuf *b, int64_t c, double *maxd, int64_t *solved)
{
    if (!E->dirty[c]) return 0;
    *solved += E->cstart[c + 1] - E->cstart[c];
    const int64_t moves = dens_solve_cell(E, b, c % E->g, c / E->g, maxd);
    E->dirty[c] = 0;
    if (moves) cfpo_dens_mark_block(E->dirty, E->g, c);
    return moves;
}

/* One iteration's nine phases on the one grid, into *moves, *solved,
 * *maxd (*tm: the phase clock, for the timers). 0, or -1. */
int dens_sweep_grid(cfpo_dens_engine *E, int64_t *moves_, int64_t *solved_, double *maxd_, double *tm_)
{
    int64_t moves = 0, solved = 0;
    double maxd = 0, tm = *tm_;
    dens_build_cells(E);
    const int64_t g = E->g, per = g / 3;
    int64_t mx = 0;
    for (int64_t cy = 0; cy < g; cy++)
        for (int64_t cx = 0; cx < g; cx++) {
            const int64_t m = block_count(E, cx, cy);
            if (m > mx) mx = m;
        }
    if (!comm_all(ensure_buffers(E, (size_t)mx) == 0)) return -1;
    for (int colour = 0; colour < 9; colour++) {
        const int64_t bx = colour % 3, by = colour / 3;
        if (E->T) { /* this rank's cells of the colour, then their copies to the ranks that keep them */
            int64_t m;
            const int64_t *cells = cfpo_dens_dist_cells(E->T, colour, &m);
#pragma omp parallel for num_threads(E->nthreads) schedule(dynamic, 4) reduction(+ : moves, solved) reduction(max : maxd)
            for (int64_t t = 0; t < m; t++) {
                double md = 0;
                moves += visit_cell(E, &E->tb[omp_get_thread_num()], cells[t], &md, &solved);
                if (md > maxd) maxd = md;
            }
            const double th = omp_get_wtime();
            E->t_compute += th - tm;
            if (cfpo_dens_dist_refresh(E->T, &E->s, E->cstart, E->cidx, E->cxyq, colour, E->dirty, g) != 0) return -1;
            tm = omp_get_wtime();
            E->t_halo += tm - th;
            continue;
        }
#pragma omp parallel for num_threads(E->nthreads) schedule(dynamic, 4) reduction(+ : moves, solved) reduction(max : maxd)
        for (int64_t t = 0; t < per * per; t++) {
            double md = 0;
            moves += visit_cell(E, &E->tb[omp_get_thread_num()], (by + 3 * (t / per)) * g + bx + 3 * (t % per), &md,
                                &solved);
            if (md > maxd) maxd = md;
        }
    }
    *moves_ = moves;
    *solved_ = solved;
    *maxd_ = maxd;
    *tm_ = tm;
    return 0;
}

/* Several ranks, level l: this rank's cells of level l (those inside its
 * level-0 cells), grouped by colour into E->lcells, the colour k's from
 * at[k] to at[k + 1]. 0, or -1. */
static int level_cells(cfpo_dens_engine *E, int l, int64_t at[10])
{
    const int64_t g = E->lv.g0 << l, side = (int64_t)1 << l;
    int64_t own = 0, cnt[9] = {0};
    for (int k = 0; k < 9; k++) {
        int64_t m;
        (void)cfpo_dens_dist_cells(E->T, k, &m);
        own += m;
    }
    const int64_t need = own * side * side;
    if (need > E->lcap) {
        int64_t *v = realloc(E->lcells, (size_t)(need > 0 ? need : 1) * sizeof *v);
        if (!v) return -1;
        E->lcells = v;
        E->lcap = need;
    }
    for (int pass = 0; pass < 2; pass++) { /* count, then place */
        if (pass) {
            at[0] = 0;
            for (int k = 0; k < 9; k++) at[k + 1] = at[k] + cnt[k];
            for (int k = 0; k < 9; k++) cnt[k] = at[k];
        }
        for (int k = 0; k < 9; k++) {
            int64_t m;
            const int64_t *c0 = cfpo_dens_dist_cells(E->T, k, &m);
            for (int64_t t = 0; t < m; t++) {
                const int64_t X = c0[t] % E->lv.g0, Y = c0[t] / E->lv.g0;
                for (int64_t b = 0; b < side; b++)
                    for (int64_t a = 0; a < side; a++) {
                        const int64_t i = (X << l) + a, j = (Y << l) + b, col = (i % 3) + 3 * (j % 3);
                        if (pass) E->lcells[cnt[col]++] = j * g + i;
                        else cnt[col]++;
                    }
            }
        }
    }
    return 0;
}

/* One iteration on the levels (dens_levels.h): each own point's level,
 * then level by level the nine phases over the cells that hold points of
 * that level, each solving those points against its whole block; a cell
 * whose block did not change since it was last solved without a move is
 * skipped (a move marks the blocks around its old and new place at every
 * level). Several ranks: level 0's cells are cut as on the one grid; a
 * finer cell lies in one of them and is solved by its owner, and after
 * each phase every cell another rank keeps as halo is sent again, a halo
 * point that moved marking what it marked on its own rank. */
int dens_sweep_levels(cfpo_dens_engine *E, int64_t *moves_, int64_t *solved_, double *maxd_, double *tm_)
{
    int64_t moves = 0, solved = 0;
    double maxd = 0, tm = *tm_;
    const int64_t g0 = E->lv.g0;
    /* each point's finest cell: on one rank, under an offset the levels
     * already hold, the moves kept them (dens_cell.c writes a moved
     * point's cell with its place, by the same function: the same
     * values); else, or with several ranks (the halo moves elsewhere),
     * all of them again */
    const int kept = !E->T && E->fine_kept && E->lv.sx == E->sx && E->lv.sy == E->sy;
    if (!comm_all(cfpo_dens_levels_place(&E->lv, &E->qlow, E->sx, E->sy) == 0)) return -1;
    if (!kept)
        for (int64_t i = 0; i < E->s.loc; i++) E->fine[i] = cfpo_dens_levels_fine(&E->lv, E->s.xy[2 * i], E->s.xy[2 * i + 1]);
    E->fine_kept = !E->T;
    int64_t per_level[CFPO_DENS_LEVELS_MAX] = {0}; /* the points of each level, on every rank */
    for (int64_t i = 0; i < E->s.own; i++) {
        E->lev[i] = (unsigned char)cfpo_dens_levels_of_fine(&E->lv, E->fine[i], E->s.q[i], E->D, CELL_SPACINGS,
                                                                LEVEL_WORTH);
        per_level[E->lev[i]]++;
    }
    if (E->T) comm_sum_i64(per_level, E->lv.n);
    if (E->T) { /* level 0's cells, for the refreshes */
        dens_build_cells(E);
        memcpy(E->cstart0, E->cstart, (size_t)(g0 * g0 + 1) * sizeof *E->cstart0);
        memcpy(E->cidx0, E->cidx, (size_t)E->s.loc * sizeof *E->cidx0);
    }
    int ok = 1;
    for (int l = 0; l < E->lv.n && ok; l++) {
        if (per_level[l] == 0) continue; /* nothing to solve, on any rank */
        E->cur = l;
        E->g = g0 << l;
        E->L = 1.0 / (double)E->g;
        const int64_t g = E->g;
        dens_build_level(E, l);
        unsigned char *has = E->dirty; /* the cells holding a point of this level */
        const uint32_t *touch = E->ltouch[l];
        uint32_t *seen = E->lseen[l]; /* the skip */
        memset(has, 0, (size_t)(g * g));
        int64_t at[10] = {0}, nh = 0;
        for (int64_t i = 0; i < E->s.own; i++)
            if (E->lev[i] == l && !has[E->cell[i]]) {
                has[E->cell[i]] = 1;
                nh++;
            }
        /* one rank: the cells holding a point of this level by colour
         * (cells of one colour are solved in any order: their blocks are
         * apart); several: this rank's cells of the level by colour */
        if (!E->T && nh > E->lcap) {
            int64_t *v = realloc(E->lcells, (size_t)nh * sizeof *v);
            if (v) { E->lcells = v; E->lcap = nh; }
        }
        if (!E->T && nh <= E->lcap) {
            for (int64_t c = 0; c < g * g; c++)
                if (has[c]) at[(c % g) % 3 + 3 * ((c / g) % 3) + 1]++;
            for (int k = 0; k < 9; k++) at[k + 1] += at[k];
            int64_t fill[9];
            for (int k = 0; k < 9; k++) fill[k] = at[k];
            for (int64_t c = 0; c < g * g; c++)
                if (has[c]) E->lcells[fill[(c % g) % 3 + 3 * ((c / g) % 3)]++] = c;
        }
        int64_t mx = 0; /* the largest block a solve gathers */
        for (int64_t c = 0; c < g * g; c++)
            if (has[c]) {
                const int64_t m = block_count(E, c % g, c / g);
                if (m > mx) mx = m;
            }
        if (!comm_all((E->T || nh <= E->lcap) && ensure_buffers(E, (size_t)mx) == 0 &&
                      (!E->T || level_cells(E, l, at) == 0))) {
            ok = 0;
            break;
        }
        for (int colour = 0; colour < 9 && ok; colour++) {
            const int64_t m = at[colour + 1] - at[colour];
            const uint32_t ph = ++E->phase;
#pragma omp parallel for num_threads(E->nthreads) schedule(dynamic, 4) reduction(+ : moves, solved) reduction(max : maxd)
            for (int64_t t = 0; t < m; t++) {
                const int64_t c = E->lcells[at[colour] + t];
                if (!has[c] || !cfpo_dens_levels_touched(touch, g, c % g, c / g, seen[c])) continue;
                seen[c] = ph; /* a move stamps it again (the move lies in it) */
                for (int64_t e = E->cstart[c]; e < E->cstart[c + 1]; e++) solved += E->lev[E->cidx[e]] == l;
                double md = 0;
                moves += dens_solve_cell(E, &E->tb[omp_get_thread_num()], c % g, c / g, &md);
                if (md > maxd) maxd = md;
            }
            if (!E->T) continue;
            const double th = omp_get_wtime();
            E->t_compute += th - tm;
            const int64_t nh = E->s.loc - E->s.own;
            if (nh > E->hcap) {
                double *h = realloc(E->hold, (size_t)nh * 2 * sizeof *h);
                if (h) { E->hold = h; E->hcap = nh; }
            }
            ok = nh <= E->hcap;
            if (ok && nh > 0) memcpy(E->hold, E->s.xy + 2 * E->s.own, (size_t)nh * 2 * sizeof *E->hold);
            ok = comm_all(ok) && cfpo_dens_dist_refresh(E->T, &E->s, E->cstart0, E->cidx0, NULL, -1, NULL, g0) == 0;
            for (int64_t j = E->s.own; j < E->s.loc && ok; j++) { /* the halo's new places into this level's rows */
                double *r = E->cxyq + 3 * E->slot[j];
                const double *was = E->hold + 2 * (j - E->s.own);
                if (was[0] != E->s.xy[2 * j] || was[1] != E->s.xy[2 * j + 1]) { /* moved on its rank: marked as there */
                    const uint32_t f = cfpo_dens_levels_fine(&E->lv, E->s.xy[2 * j], E->s.xy[2 * j + 1]);
                    cfpo_dens_levels_mark_fine(&E->lv, E->ltouch, ph, E->fine[j], f);
                    E->fine[j] = f;
                }
                r[0] = E->s.xy[2 * j];
                r[1] = E->s.xy[2 * j + 1];
                r[2] = E->s.q[j];
            }
            tm = omp_get_wtime();
            E->t_halo += tm - th;
        }
    }
    E->g = g0;
    E->L = 1.0 / (double)g0;
    if (!comm_all(ok)) return -1;
    *moves_ = moves;
    *solved_ = solved;
    *maxd_ = maxd;
    *tm_ = tm;
    return 0;
}

