/* engine_given.c - a start given by the caller (cfpo --init FILE): the
 * points of a set made elsewhere, point k with id k, bucketed into this
 * rank's cells (see cells.h). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>

int eng_take_points(cfpo_engine *E, const double *xy, char *err, size_t errlen)
{
    const int64_t g = E->G.g, n = E->n;
    uint32_t *cnt = calloc((size_t)E->cells + 1, sizeof *cnt);
    if (!cnt) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int64_t nloc = 0, full = -1;
    for (int64_t k = 0; k < n; k++) {
        const int64_t c = own_cell_of(E, xy[2 * k], xy[2 * k + 1]);
        if (c < 0) continue;
        if (++cnt[c] > CFPO_CELL_MAX && full < 0) full = c;
        nloc++;
    }
    if (full >= 0) {
        snprintf(err, errlen, "cell (%lld, %lld) of the %lld x %lld grid holds more than %d points; "
                 "such a clump would make one cell's work grow with the cube of its count",
                 (long long)(E->x0 + full % E->w), (long long)(E->y0 + full / E->w), (long long)g, (long long)g,
                 CFPO_CELL_MAX);
        free(cnt);
        return -1;
    }
    if (eng_ensure_cap(E, (size_t)nloc) != 0) {
        free(cnt);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int maxcell = 0;
    E->start[0] = 0;
    for (int64_t c = 0; c < E->cells; c++) {
        E->start[c + 1] = E->start[c] + cnt[c];
        if ((int)cnt[c] > maxcell) maxcell = (int)cnt[c];
        cnt[c] = E->start[c]; /* now the next free slot */
    }
    for (int64_t k = 0; k < n; k++) { /* ids ascending inside every cell */
        const int64_t c = own_cell_of(E, xy[2 * k], xy[2 * k + 1]);
        if (c < 0) continue;
        const uint32_t s = cnt[c]++;
        E->px[s] = xy[2 * k];
        E->py[s] = xy[2 * k + 1];
        E->pid[s] = (uint64_t)k;
    }
    E->nloc = nloc;
    E->maxcell = maxcell;
    free(cnt);
    return 0;
}
