/* engine_init.c - the initial set of each variant, made cell by cell
 * on the rank that owns the cell (see cells.h). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "start.h"

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
    int64_t m = cfpo_start_band(&E->G, r0, r1, E->nthreads, !E->start_raw, &pt);
    if (m < 0) goto oom;
    for (int64_t i = 0; i < m; i++) rowsum[pt[i].cell / g]++;
    comm_sum_i64(rowsum, (int)g); /* rows are disjoint: the sum gathers them */
    int64_t id = 0;
    for (int64_t y = 0; y < E->y0; y++) id += rowsum[y];
    if (r0 != E->y0 || r1 != E->y0 + E->h) { /* else the band made is the tile's */
        free(pt);
        pt = NULL;
        m = cfpo_start_band(&E->G, E->y0, E->y0 + E->h, E->nthreads, !E->start_raw, &pt);
    }
    if (m < 0) goto oom;
    int64_t nloc = 0;
    for (int64_t i = 0; i < m; i++) {
        const int64_t lx = pt[i].cell % g - E->x0;
        if (lx >= 0 && lx < E->w) nloc++;
    }
    if (eng_ensure_cap(E, (size_t)nloc) != 0) goto oom;
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

int eng_make_initial(cfpo_engine *E, char *err, size_t errlen)
{
    if (E->G.variant == CFPO_VARIANT_ADAPTIVE || E->G.variant == CFPO_VARIANT_HYPERUNIFORM) return make_initial_adaptive(E, err, errlen);
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
    if (eng_ensure_cap(E, (size_t)nloc) != 0) {
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
