/* engine_move.c - points moving between cells, tiles and ranks after a
 * phase: relocation into the new cells, packing and exchanging migrants,
 * marking the blocks that must be solved again (see cells.h). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
 * that colour in its 3x3 block (in every colouring of policy.h, every 3x3
 * block holds one cell of each colour); with another period, all nine.
 * Returns the count. */
static inline int near_offset(int64_t want, int64_t at)
{
    const int d = (int)(((want - at) % 3 + 3) % 3);
    return d == 2 ? -1 : d;
}
static inline __attribute__((always_inline)) int senders(const cfpo_engine *E, int64_t lx, int64_t ly, int a, int b,
                                                       int off[9][2])
{
    if (E->G.period != 3) {
        int m = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) off[m][0] = dx, off[m][1] = dy, m++;
        return m;
    }
    const int64_t g = E->G.g, X = E->x0 + lx, Y = E->y0 + ly;
    int sx, sy;
    if (E->pol.brick == CFPO_BRICK_ROWS) {
        sy = near_offset(a, Y);
        sx = near_offset(b + E->brick_sh[(Y + sy + g) % g], X);
    } else if (E->pol.brick == CFPO_BRICK_COLUMNS) {
        sx = near_offset(b, X);
        sy = near_offset(a + E->brick_sh[(X + sx + g) % g], Y);
    } else {
        sx = near_offset(b, X);
        sy = near_offset(a, Y);
    }
    off[0][0] = 0, off[0][1] = 0;
    if (sx == 0 && sy == 0) return 1;
    off[1][0] = sx, off[1][1] = sy;
    return 2;
}

/* How many points own cell c holds after the moves of colour (a_, b_)
 * and the arrivals. (st, mask, w: E's, loaded once by the caller; inlined
 * by force: otherwise the pass costs 4% more instructions.) */
static inline __attribute__((always_inline)) uint32_t count_cell(const cfpo_engine *E, const uint32_t *st,
                                                                  const uint16_t *mask, int64_t w, int64_t c, int a_,
                                                                  int b_)
{
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
    return cnt;
}

/* Slots [lo, hi) of the spare buffers by id (insertion sort: cells hold a
 * handful of points). */
static void sort_slots(cfpo_engine *E, uint32_t lo, uint32_t hi)
{
    for (uint32_t k = lo + 1; k < hi; k++) {
        const uint64_t code = E->tid[k], id = id_of(E, code);
        const double x = E->tx[k], y = E->ty[k];
        uint32_t j = k;
        while (j > lo && id_of(E, E->tid[j - 1]) > id) {
            E->tid[j] = E->tid[j - 1];
            E->tx[j] = E->tx[j - 1];
            E->ty[j] = E->ty[j - 1];
            j--;
        }
        E->tid[j] = code;
        E->tx[j] = x;
        E->ty[j] = y;
    }
}

/* Writes own cell c's new points into the spare buffers from slot
 * start2[c] on, in id order, each with its source in tid (an old slot, or
 * ARRIVAL_CODE | arrival). Returns the count. */
static int fill_cell(cfpo_engine *E, int64_t c, int a_, int b_)
{
    const int64_t lx = c % E->w, ly = c / E->w;
    const uint32_t *st = E->start, lo = E->start2[c];
    uint32_t wpos = lo;
    int arrivals = 0;
    int off[9][2];
    const int no = senders(E, lx, ly, a_, b_, off);
    for (int o = 0; o < no; o++) {
        const int dx = off[o][0], dy = off[o][1];
        const int64_t e = locate(E, lx + dx, ly + dy);
        if (e < 0) continue;
        const unsigned mk = E->mask[e] & 0x1ffu;
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
    if (E->mask[c] & ARRIVE_BIT) {
        arrivals = 1;
        for (size_t a = first_arrival(E, c); a < E->narr && E->arr[a].cell == c; a++) {
            const mig_rec *r = &E->arr[a].r;
            E->tx[wpos] = r->x;
            E->ty[wpos] = r->y;
            E->tid[wpos] = ARRIVAL_CODE | a;
            wpos++;
        }
    }
    if (arrivals) sort_slots(E, lo, wpos);
    return (int)(wpos - lo);
}

/* The next run of own cells in [c, c1) that keep their content (no
 * MOVED_BIT): returns its end (c itself when cell c changed). */
static int64_t unchanged_run(const cfpo_engine *E, int64_t c, int64_t c1)
{
    const uint64_t moved4 = MOVED_BIT * 0x0001000100010001ull; /* four masks at a time */
    while (c + 4 <= c1) {
        uint64_t m4;
        memcpy(&m4, E->mask + c, sizeof m4);
        if (m4 & moved4) break;
        c += 4;
    }
    while (c < c1 && !(E->mask[c] & MOVED_BIT)) c++;
    return c;
}

/* Cells [c0, c1) into the spare buffers: a changed cell by fill_cell
 * (sources in tid), a run of unchanged ones by one copy of positions. */
static void fill_cells(cfpo_engine *E, int64_t c0, int64_t c1, int a_, int b_)
{
    const uint32_t *st = E->start, *ns = E->start2;
    for (int64_t c = c0; c < c1;) {
        const int64_t e = unchanged_run(E, c, c1);
        if (e == c) {
            fill_cell(E, c++, a_, b_);
            continue;
        }
        memcpy(E->tx + ns[c], E->px + st[c], (size_t)(st[e] - st[c]) * sizeof(double));
        memcpy(E->ty + ns[c], E->py + st[c], (size_t)(st[e] - st[c]) * sizeof(double));
        c = e;
    }
}

/* Ids and displacements of cells [c0, c1) follow their sources: the ones
 * recorded in tid for a changed cell, the old slots of a run of unchanged
 * ones (copied at once). The new displacements go into ndq, the old
 * positions' buffer, free by now. */
static void follow_cells(cfpo_engine *E, int64_t c0, int64_t c1, float *ndq)
{
    const uint32_t *st = E->start, *ns = E->start2;
    for (int64_t c = c0; c < c1;) {
        const int64_t e = unchanged_run(E, c, c1);
        if (e > c) {
            memcpy(E->tid + ns[c], E->pid + st[c], (size_t)(st[e] - st[c]) * sizeof(uint64_t));
            memcpy(ndq + 2 * (size_t)ns[c], E->dq + 2 * (size_t)st[c], 2 * (size_t)(st[e] - st[c]) * sizeof(float));
            c = e;
            continue;
        }
        for (uint32_t j = ns[c]; j < ns[c + 1]; j++) {
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
        c++;
    }
}

/* The spare buffers become the live ones. */
static void swap_buffers(cfpo_engine *E)
{
    double *oldx = E->px, *oldy = E->py;
    float *olddq = E->dq;
    E->px = E->tx;
    E->py = E->ty;
    E->dq = (float *)oldx;
    E->tx = (double *)olddq;
    E->ty = oldy;
    uint64_t *u = E->pid; E->pid = E->tid; E->tid = u;
    uint32_t *s = E->start; E->start = E->start2; E->start2 = s;
    E->nloc = E->start[E->cells];
}

/* Sets MOVED_BIT on the own cells whose content the moves of colour
 * `colour` and the arrivals change: a cell of that colour a point left,
 * the cells its mask sends points to, the cells with arrivals. Only the
 * cells of the phase's colour carry move bits (the others were cleared
 * after their own phase), so every other cell keeps its slice as it is. */
static void flag_moved(cfpo_engine *E, int colour)
{
    const eng_colour C = eng_colour_of(E, colour);
    for (int64_t t = 0; t < C.nxc * C.nyc; t++) {
        int64_t lx, ly;
        if (!eng_colour_cell(&C, t, &lx, &ly)) continue;
        const int64_t c = ly * E->w + lx;
        const unsigned mk = E->mask[c] & 0x1ffu & ~CENTRE_BIT;
        if (!mk) continue;
        E->mask[c] |= MOVED_BIT;
        for (int bit = 0; bit < 9; bit++) {
            if (!(mk >> bit & 1u)) continue;
            const int64_t e = locate(E, lx + bit % 3 - 1, ly + bit / 3 - 1);
            if (e >= 0) E->mask[e] |= MOVED_BIT;
        }
    }
    for (size_t a = 0; a < E->narr; a++) E->mask[E->arr[a].cell] |= MOVED_BIT;
}

/* The cells flagged by flag_moved are rebuilt (count_cell, fill_cell);
 * runs of the others, most cells late in a run, keep their content and are
 * copied whole: the same result as rebuilding every cell. Cells go to the
 * threads in contiguous chunks. */
int eng_relocate(cfpo_engine *E, int colour)
{
    const int a_ = colour / E->G.period, b_ = colour % E->G.period;
    const int64_t cells = E->cells;
    uint32_t *ns = E->start2;
    if (eng_ensure_cap(E, (size_t)E->nloc + E->narr) != 0) return -1;
    flag_moved(E, colour);
    const uint32_t *st = E->start;
    const uint16_t *mask = E->mask;
    const int64_t w = E->w;
    uint32_t maxcell = 0;
#pragma omp parallel for schedule(static) reduction(max : maxcell) num_threads(E->nthreads)
    for (int64_t c = 0; c < cells; c++) {
        const uint32_t m = (mask[c] & MOVED_BIT) ? count_cell(E, st, mask, w, c, a_, b_) : st[c + 1] - st[c];
        ns[c + 1] = m;
        if (m > maxcell) maxcell = m;
    }
    ns[0] = 0;
    for (int64_t c = 0; c < cells; c++) ns[c + 1] += ns[c];
    const int64_t chunks = (int64_t)E->nthreads * 8, per = (cells + chunks - 1) / chunks;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t k = 0; k < chunks; k++) fill_cells(E, k * per, per * (k + 1) < cells ? per * (k + 1) : cells, a_, b_);
    float *ndq = (float *)E->px;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t k = 0; k < chunks; k++) follow_cells(E, k * per, per * (k + 1) < cells ? per * (k + 1) : cells, ndq);
    for (int64_t c = 0; c < cells; c++) E->mask[c] &= (uint16_t)~MOVED_BIT;
    swap_buffers(E);
    E->maxcell = (int)maxcell;
    return eng_ensure_scratch(E);
}

/* Points that crossed into another rank's cell: packed per neighbour. */
int eng_pack_migrants(cfpo_engine *E, const eng_colour *C)
{
    for (int k = 0; k < E->nnb; k++) E->nb[k].nout = 0;
    if (E->nnb == 0) return 0;
    const int64_t g = E->G.g;
    for (int64_t t = 0; t < C->nxc * C->nyc; t++) {
        int64_t lx, ly;
        if (!eng_colour_cell(C, t, &lx, &ly)) continue;
        const int64_t c = ly * E->w + lx;
        const unsigned mk = E->mask[c];
        if (!(mk & ~CENTRE_BIT & 0x1ffu)) continue;
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
            const int64_t gx = cfpo_grid_cx(&E->G, E->px[k]), gy = cfpo_grid_cy(&E->G, E->py[k]);
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
int eng_exchange_migrants(cfpo_engine *E)
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
        eng_mark_block(E, c % E->w, c / E->w);
    }
    return 0;
}
