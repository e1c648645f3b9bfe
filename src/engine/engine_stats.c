/* engine_stats.c - delta_min and delta_avg of the set, exact (see
 * cells.h). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- statistics ---- */

/* min(a, b) for numbers that are not NaN (fmin is a library call). */
static inline double min2(double a, double b) { return a < b ? a : b; }

/* A distance d (in units of Delta) in the exact sum's units: llround of
 * min(d, 1e6) 2^24, without the library calls. v + 0.5 rounds only where
 * its exponent exceeds v's, which for v >= 0.5 cannot carry it past the
 * next integer; below 0.5 the answer is 0. (NaN counts as 1e6, as fmin
 * had it.) */
static inline uint64_t sum_units(double d)
{
    const double v = (d < 1e6 ? d : 1e6) * SUM_SCALE;
    return v < 0.5 ? 0 : (uint64_t)(v + 0.5);
}

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
    const double ex = cell_offset(E, x, E->x0 + lx, E->G.shift_x), ey = cell_offset(E, y, E->y0 + ly, E->G.shift_y);
    double edge = min2(min2(ex, L - ex), min2(ey, L - ey));
    if (edge < 0) edge = 0;
    double best = INFINITY;
    if (eng_plain_block(E, lx, ly)) { /* three runs of slots; |differences| < 0.5, so no wrapping */
        const int64_t c = ly * E->w + lx;
        const uint32_t *st = E->start;
        const double *X = E->px, *Y = E->py;
        for (int dy = -1; dy <= 1; dy++) {
            const int64_t r = c + dy * E->w;
            for (uint32_t j = st[r - 1]; j < st[r + 2]; j++) {
                const double ddx = x - X[j], ddy = y - Y[j], d2 = ddx * ddx + ddy * ddy;
                if (j != k && d2 < best) best = d2;
            }
        }
    } else
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t e = locate(E, lx + dx, ly + dy);
            const double *X, *Y;
            uint32_t a, b;
            cell_slice(E, e, &X, &Y, &a, &b);
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
    const int64_t qx = cfpo_grid_cx(&E->G, q->x), qy = cfpo_grid_cy(&E->G, q->y);
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

static void stats_oom(cfpo_engine *E) { eng_fatal(E, "computing statistics"); }

/* Points whose nearest neighbour may lie outside their block. */
typedef struct {
    nn_query *q;
    size_t n, cap;
    int oom;
} unsure_list;

static void add_unsure(unsure_list *u, nn_query q)
{
#pragma omp critical(cfpo_unresolved)
    {
        if (u->n == u->cap) {
            size_t cap = u->cap * 2 + 64;
            nn_query *p = realloc(u->q, cap * sizeof *p);
            if (p) { u->q = p; u->cap = cap; }
            else u->oom = 1;
        }
        if (u->n < u->cap) u->q[u->n++] = q;
    }
}

/* Recomputes one marked block: its sum and minimum of the distances that
 * are sure inside it; the others go to u. Returns whether any was not. */
/* (Inlined by force: as a call, the pass costs 2.6% more instructions.) */
static inline __attribute__((always_inline)) int block_pass(cfpo_engine *E, int64_t bi, double inv,
                                                            unsure_list *u)
{
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
                const double d2 = nn2_block(E, lx, ly, k, &sure);
                if (!sure) {
                    unsure = 1;
                    add_unsure(u, (nn_query){E->px[k], E->py[k], d2, E->pid[k], E->rank});
                    continue;
                }
                const double d = sqrt(d2) * inv;
                bs += sum_units(d);
                if (d < bm) bm = d;
            }
        }
    E->bsum[bi] = bs;
    E->bmin[bi] = bm;
    return unsure;
}

/* Is query i's answer res certain with the search radius B cells? */
static int settled(const cfpo_engine *E, const nn_query *q, double res, int64_t B)
{
    const double L = E->G.L;
    const int64_t cx = cfpo_grid_cx(&E->G, q->x), cy = cfpo_grid_cy(&E->G, q->y);
    const double ex = cell_offset(E, q->x, cx, E->G.shift_x), ey = cell_offset(E, q->y, cy, E->G.shift_y);
    const double edge = fmax(0, fmin(fmin(ex, L - ex), fmin(ey, L - ey)));
    const double reach = (double)B * L + edge;
    return res <= reach * reach || 2 * B + 1 >= E->G.g;
}

/* Points whose nearest neighbour may lie outside their block: ask every
 * rank for its nearest points within B cells, doubling B until the answer
 * is certain. Rare after the first iteration. Adds the owned ones to
 * *sum and *mn. */
static void resolve_unsure(cfpo_engine *E, const nn_query *Q, size_t nq, double inv, uint64_t *sum, double *mn)
{
    double *res = malloc(nq * sizeof *res);
    int64_t *B = malloc(nq * sizeof *B);
    uint8_t *done = calloc(nq, 1);
    if (!res || !B || !done) stats_oom(E);
    for (size_t i = 0; i < nq; i++) B[i] = 2;
    for (int left = 1; left;) {
#pragma omp parallel for schedule(dynamic, 64) num_threads(E->nthreads)
        for (size_t i = 0; i < nq; i++) res[i] = done[i] ? INFINITY : box_min(E, &Q[i], B[i]);
        comm_min_d(res, (int)nq);
        left = 0;
        for (size_t i = 0; i < nq; i++) {
            if (done[i]) continue;
            if (!settled(E, &Q[i], res[i], B[i])) {
                B[i] *= 2;
                left = 1;
                continue;
            }
            done[i] = 1;
            if (Q[i].owner != E->rank) continue;
            const double d = sqrt(res[i]) * inv;
            *sum += sum_units(d);
            if (d < *mn) *mn = d;
        }
    }
    free(res);
    free(B);
    free(done);
}

void cfpo_engine_deltas(cfpo_engine *E, double *dmin, double *davg)
{
    const double inv = 1.0 / E->G.delta;
    unsure_list u = {0};
    /* Blocks whose cells' neighbourhoods did not change keep their sums;
     * blocks with unresolved points are recomputed every time. */
    const int64_t nb = E->nbx * E->nby;
#pragma omp parallel for schedule(dynamic, 4) num_threads(E->nthreads)
    for (int64_t bi = 0; bi < nb; bi++)
        if (E->bdirty[bi]) E->bdirty[bi] = (uint8_t)block_pass(E, bi, inv, &u);
    uint64_t sum = 0;
    double mn = INFINITY;
    for (int64_t bi = 0; bi < nb; bi++) {
        sum += E->bsum[bi];
        if (E->bmin[bi] < mn) mn = E->bmin[bi];
    }
    if (!comm_all(!u.oom)) stats_oom(E);
    void *allv;
    size_t total;
    if (comm_allgatherv(u.q, u.n * sizeof *u.q, &allv, &total) != 0) stats_oom(E);
    free(u.q);
    const size_t nq = total / sizeof(nn_query);
    if (nq) resolve_unsure(E, allv, nq, inv, &sum, &mn);
    free(allv);
    /* Exact integer sums: the same bits for any split into ranks. */
    int64_t *all = malloc((size_t)E->nranks * sizeof *all);
    if (!all) stats_oom(E);
    comm_allgather_i64((int64_t)sum, all);
    unsigned __int128 S = 0;
    for (int r = 0; r < E->nranks; r++) S += (uint64_t)all[r];
    free(all);
    comm_min_d(&mn, 1);
    E->dmin_now = mn;
    *dmin = mn;
    *davg = (double)((long double)S / SUM_SCALE / (long double)E->n);
}
