/* engine_check.c - the --check verifications (cfpo_engine_config.check,
 * for tests): after every migration, point counts, the id checksum and
 * that every point sits in the cell that holds it; after every halo
 * refresh, that every halo cell equals its owner's cell. */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void eng_check_fail(const cfpo_engine *E, const char *what)
{
    fprintf(stderr, "cfpo: rank %d: check failed: %s\n", E->rank, what);
    comm_abort(3);
}

void eng_check_migration(cfpo_engine *E)
{
    int64_t v[2] = {E->nloc, 0};
    uint64_t sum = 0;
    for (int64_t c = 0; c < E->cells; c++)
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
            sum += cfpo_mix64(E->pid[k]);
            if (!in_cell(E, E->px[k], E->py[k], c % E->w, c / E->w)) eng_check_fail(E, "a point lies outside its cell");
            if (k > E->start[c] && E->pid[k - 1] >= E->pid[k]) eng_check_fail(E, "ids out of order in a cell");
        }
    comm_sum_i64(v, 1);
    int64_t s = (int64_t)sum;
    comm_sum_i64(&s, 1);
    if (v[0] != E->n) eng_check_fail(E, "the global point count changed");
    if ((uint64_t)s != E->id_sum) eng_check_fail(E, "the checksum of point ids changed");
    E->chk_mig++;
}

typedef struct {
    double x, y;
    uint64_t id;
} pt_rec;

static int cmp_cell_id(const void *a, const void *b, const cfpo_grid *G)
{
    const pt_rec *p = a, *q = b;
    int64_t cp = cfpo_grid_cy(G, p->y) * G->g + cfpo_grid_cx(G, p->x);
    int64_t cq = cfpo_grid_cy(G, q->y) * G->g + cfpo_grid_cx(G, q->x);
    if (cp != cq) return cp < cq ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}
static const cfpo_grid *sort_grid;
static int cmp_cell_id_q(const void *a, const void *b) { return cmp_cell_id(a, b, sort_grid); }

/* Every halo cell equals its owner's cell: gathers the whole (small) set. */
void eng_check_halo(cfpo_engine *E)
{
    if (E->n > 200000) return;
    pt_rec *mine = malloc(((size_t)E->nloc + 1) * sizeof *mine);
    if (!mine) eng_check_fail(E, "out of memory");
    for (int64_t k = 0; k < E->nloc; k++) mine[k] = (pt_rec){E->px[k], E->py[k], E->pid[k]};
    void *all;
    size_t total;
    if (comm_allgatherv(mine, (size_t)E->nloc * sizeof *mine, &all, &total) != 0) eng_check_fail(E, "out of memory");
    free(mine);
    pt_rec *A = all;
    size_t na = total / sizeof *A;
    if ((int64_t)na != E->n) eng_check_fail(E, "gathered set has the wrong size");
    sort_grid = &E->G;
    qsort(A, na, sizeof *A, cmp_cell_id_q);
    const int64_t g = E->G.g;
    int64_t *first = malloc(((size_t)(g * g) + 1) * sizeof *first);
    if (!first) eng_check_fail(E, "out of memory");
    size_t j = 0;
    for (int64_t c = 0; c <= g * g; c++) {
        while (j < na && cfpo_grid_cy(&E->G, A[j].y) * g + cfpo_grid_cx(&E->G, A[j].x) < c) j++;
        first[c] = (int64_t)j;
    }
    for (int64_t i = 0; i < E->nring; i++) {
        int64_t lx, ly;
        ring_coords(E, i, &lx, &ly);
        if (locate(E, lx, ly) != -1 - i) continue;
        int64_t gx = (E->x0 + lx + g) % g, gy = (E->y0 + ly + g) % g, c = gy * g + gx;
        uint32_t a = E->hstart[i], b = E->hstart[i + 1];
        if ((int64_t)(b - a) != first[c + 1] - first[c]) eng_check_fail(E, "a halo cell has the wrong point count");
        for (uint32_t k = a; k < b; k++) {
            const pt_rec *p = &A[first[c] + (k - a)];
            if (p->x != E->hx[k] || p->y != E->hy[k]) eng_check_fail(E, "a halo cell differs from its owner's cell");
        }
    }
    free(first);
    free(A);
    E->chk_halo++;
}
