/* bench_plain.c - `cfpo-bench plain`: the paper's CFPO written the
 * plainest way, as the yardstick for the engine's own work (the engine's
 * whole process should be no slower than this with the same solver) and
 * as a reference for its bytes (tests/test_plain.sh: the engine's paper
 * variant gives the same points after the same iterations).
 *
 * One thread, one process, points in id order; a cell list (ids sorted by
 * cell, ascending inside each) sorted again by counting after every phase;
 * every point of every cell of the phase's colour solved with the exact
 * solver on its 3x3 block, read in the canonical order (cells row by row,
 * ids ascending) and unwrapped around the block; no skipping, no halo, no
 * tiles. After each iteration delta_min and delta_avg over the 3x3
 * blocks. */
#include "bench_plain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "geom.h"
#include "grid.h"
#include "pointfile.h"

typedef struct {
    cfpo_grid G;
    int64_t n, g;
    double *x, *y;   /* by id */
    int64_t *cell;   /* row-major cell of each id */
    int64_t *start;  /* g^2 + 1 offsets into list */
    int64_t *list;   /* ids by cell, ascending inside each */
    double *bx, *by, *sol; /* one block and the solver's scratch */
    int64_t *bid;
    int cap;
} plain;

static void *need(const char *prog, size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) cli_fail(prog, "out of memory");
    return p;
}

/* The cell list from cell[]: counting sort, ids in ascending order. Makes
 * the block buffers hold 9 of the fullest cell. */
static void sort_cells(const char *prog, plain *P)
{
    const int64_t cells = P->g * P->g;
    memset(P->start, 0, (size_t)(cells + 1) * sizeof *P->start);
    for (int64_t i = 0; i < P->n; i++) P->start[P->cell[i] + 1]++;
    int64_t most = 0;
    for (int64_t c = 0; c < cells; c++) {
        if (P->start[c + 1] > most) most = P->start[c + 1];
        P->start[c + 1] += P->start[c];
    }
    for (int64_t i = 0; i < P->n; i++) P->list[P->start[P->cell[i]]++] = i;
    for (int64_t c = cells; c > 0; c--) P->start[c] = P->start[c - 1];
    P->start[0] = 0;
    if (9 * most > P->cap) {
        P->cap = (int)(9 * most);
        free(P->bx);
        free(P->by);
        free(P->sol);
        free(P->bid);
        P->bx = need(prog, (size_t)P->cap * sizeof(double));
        P->by = need(prog, (size_t)P->cap * sizeof(double));
        P->bid = need(prog, (size_t)P->cap * sizeof(int64_t));
        P->sol = need(prog, cfpo_solver_scratch((size_t)P->cap) * sizeof(double));
    }
}

/* The 3x3 block around cell (cx, cy) in the cell's frame, each point
 * unwrapped to the copy nearest its cell's centre. Returns the count;
 * *centre is the index of the centre cell's first point. */
static int gather(plain *P, int64_t cx, int64_t cy, int *centre)
{
    const int64_t g = P->g;
    const double L = P->G.L, ox = (double)cx * L, oy = (double)cy * L;
    int m = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            if (dx == 0 && dy == 0) *centre = m;
            const int64_t c = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
            const double mx = ((double)(cx + dx) + 0.5) * L, my = ((double)(cy + dy) + 0.5) * L;
            for (int64_t j = P->start[c]; j < P->start[c + 1]; j++, m++) {
                const int64_t id = P->list[j];
                const double X = P->x[id], Y = P->y[id];
                P->bx[m] = (X + nearbyint(mx - X)) - ox;
                P->by[m] = (Y + nearbyint(my - Y)) - oy;
                P->bid[m] = id;
            }
        }
    return m;
}

static void solve_cell(plain *P, int64_t cx, int64_t cy, double tolL)
{
    int off = 0;
    const int m = gather(P, cx, cy, &off);
    const int64_t c = cy * P->g + cx, k1 = P->start[c + 1] - P->start[c];
    const double ox = (double)cx * P->G.L, oy = (double)cy * P->G.L;
    const cfpo_square S = cfpo_grid_square(&P->G);
    for (int64_t k = 0; k < k1; k++) {
        const int gi = off + (int)k;
        const double x = P->bx[gi], y = P->by[gi];
        const double r02 = cfpo_min_dist2(x, y, P->bx, P->by, m, gi);
        if (isinf(r02)) continue;
        const double thr = sqrt(r02) + tolL, floor2 = thr * thr;
        double nx, ny;
        const double v = cfpo_local_solve(P->bx, P->by, m, gi, S, x, y, floor2, &nx, &ny, P->sol);
        if (!(v > floor2)) continue;
        P->bx[gi] = nx;
        P->by[gi] = ny;
        const int64_t id = P->bid[gi];
        P->x[id] = cfpo_wrap01(nx + ox);
        P->y[id] = cfpo_wrap01(ny + oy);
        P->cell[id] = cfpo_grid_cy(&P->G, P->y[id]) * P->g + cfpo_grid_cx(&P->G, P->x[id]);
    }
}

/* delta_min and delta_avg (over Delta(n)) with each point's nearest
 * neighbour sought in its 3x3 block. */
static void deltas(plain *P, double *dmin, double *davg)
{
    double lo = INFINITY, sum = 0;
    for (int64_t cy = 0; cy < P->g; cy++)
        for (int64_t cx = 0; cx < P->g; cx++) {
            int off = 0;
            const int m = gather(P, cx, cy, &off);
            const int64_t c = cy * P->g + cx, k1 = P->start[c + 1] - P->start[c];
            for (int64_t k = 0; k < k1; k++) {
                const int gi = off + (int)k;
                const double d = sqrt(cfpo_min_dist2(P->bx[gi], P->by[gi], P->bx, P->by, m, gi));
                if (d < lo) lo = d;
                sum += d;
            }
        }
    *dmin = lo / P->G.delta;
    *davg = sum / (double)P->n / P->G.delta;
}

int bench_plain(const char *prog, int64_t n, uint64_t seed, int iters, const char *path)
{
    const double t0 = cli_now();
    plain P;
    memset(&P, 0, sizeof P);
    char err[256];
    if (cfpo_grid_init(&P.G, n, CFPO_VARIANT_PAPER, seed, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    P.n = n;
    P.g = P.G.g;
    const int64_t cells = P.g * P.g;
    P.x = need(prog, (size_t)n * sizeof(double));
    P.y = need(prog, (size_t)n * sizeof(double));
    P.cell = need(prog, (size_t)n * sizeof(int64_t));
    P.list = need(prog, (size_t)n * sizeof(int64_t));
    P.start = need(prog, (size_t)(cells + 1) * sizeof(int64_t));
    /* The paper's start: ids cell by cell in row-major order. */
    int64_t id = 0;
    for (int64_t c = 0; c < cells; c++) {
        const uint64_t k1 = cfpo_grid_cell_count(&P.G, (uint64_t)c);
        for (uint64_t k = 0; k < k1; k++, id++) {
            cfpo_grid_cell_point(&P.G, c % P.g, c / P.g, k, &P.x[id], &P.y[id]);
            P.cell[id] = c;
        }
    }
    if (id != n) cli_fail(prog, "the start made %lld of %lld points", (long long)id, (long long)n);
    sort_cells(prog, &P);
    const double tolL = cfpo_default_tol(CFPO_VARIANT_PAPER) * P.G.L;
    const int p = P.G.period;
    double dmin = 0, davg = 0;
    for (int it = 0; it < iters; it++) {
        for (int colour = 0; colour < p * p; colour++) {
            for (int64_t cy = colour / p; cy < P.g; cy += p)
                for (int64_t cx = colour % p; cx < P.g; cx += p) solve_cell(&P, cx, cy, tolL);
            sort_cells(prog, &P);
        }
        deltas(&P, &dmin, &davg);
    }
    const double secs = cli_now() - t0;
    printf("RESULT plain n=%lld seed=%llu iterations=%d seconds=%.4f delta_min=%.6f delta_avg=%.6f\n",
           (long long)n, (unsigned long long)seed, iters, secs, dmin, davg);
    int rc = 0;
    if (path) {
        double *xy = need(prog, 2 * (size_t)n * sizeof(double));
        for (int64_t i = 0; i < n; i++) {
            xy[2 * i] = P.x[i];
            xy[2 * i + 1] = P.y[i];
        }
        if (pf_write(path, xy, (size_t)n, err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s\n", prog, err);
            rc = 1;
        }
        free(xy);
    }
    free(P.x);
    free(P.y);
    free(P.cell);
    free(P.list);
    free(P.start);
    free(P.bx);
    free(P.by);
    free(P.bid);
    free(P.sol);
    return rc;
}
