/* bricks3.c - see bricks3.h. */
#include "bricks3.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int64_t cfpo3_bricks_max(int g)
{
    const int64_t s = g / 3;
    return s * s * s;
}

/* Halo cells of one brick of the cut (px, py, pz) of the g^3 grid, run
 * widths taken as g / p: the faces of the cut axes (a measure for choosing
 * the factors, not a count). */
static double halo_cells(int g, const int p[3])
{
    double h = 0.0;
    for (int a = 0; a < 3; a++) {
        if (p[a] == 1) continue;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        h += 2.0 * ((double)g / p[b] + (p[b] > 1 ? 2 : 0)) * ((double)g / p[c] + (p[c] > 1 ? 2 : 0));
    }
    return h;
}

int cfpo3_bricks_init(cfpo3_bricks *B, int g, int P, int rank, char *err, size_t errlen)
{
    memset(B, 0, sizeof *B);
    const int s = g / 3;
    int best[3] = {0, 0, 0};
    double bh = 0.0;
    for (int pz = P; pz >= 1; pz--) { /* more cuts along z first: wins ties */
        if (P % pz != 0 || pz > s) continue;
        for (int py = P / pz; py >= 1; py--) {
            if ((P / pz) % py != 0 || py > s) continue;
            const int px = P / pz / py;
            if (px > s) continue;
            const int p[3] = {px, py, pz};
            const double h = halo_cells(g, p);
            if (best[0] == 0 || h < bh) {
                memcpy(best, p, sizeof best);
                bh = h;
            }
        }
    }
    if (best[0] == 0) {
        snprintf(err, errlen, "%d ranks cannot cut the %dx%dx%d grid into bricks of at least 3 cells a side "
                 "(the rank count must be px py pz with each factor at most %d: at most %lld rank%s): use fewer "
                 "ranks or more points", P, g, g, g, s, (long long)cfpo3_bricks_max(g),
                 cfpo3_bricks_max(g) == 1 ? "" : "s");
        return -1;
    }
    B->g = g, B->P = P, B->rank = rank;
    memcpy(B->p, best, sizeof best);
    for (int a = 0; a < 3; a++) {
        B->lo[a] = malloc(sizeof(int) * (size_t)(B->p[a] + 1));
        if (!B->lo[a]) {
            cfpo3_bricks_free(B);
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        for (int k = 0; k <= B->p[a]; k++) B->lo[a][k] = (int)((int64_t)k * g / B->p[a]);
    }
    cfpo3_bricks_runs(B, rank, B->me);
    /* neighbours: runs within one of ours on every axis (cyclically) */
    unsigned char *seen = calloc((size_t)P, 1);
    if (!seen) {
        cfpo3_bricks_free(B);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int dz = -1; dz <= 1; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int i = (B->me[0] + dx + B->p[0]) % B->p[0], j = (B->me[1] + dy + B->p[1]) % B->p[1],
                          k = (B->me[2] + dz + B->p[2]) % B->p[2];
                seen[cfpo3_bricks_rank(B, i, j, k)] = 1;
            }
    seen[rank] = 0;
    for (int r = 0; r < P; r++)
        if (seen[r]) B->nb[B->nnb++] = r;
    free(seen);
    return 0;
}

void cfpo3_bricks_free(cfpo3_bricks *B)
{
    for (int a = 0; a < 3; a++) free(B->lo[a]), B->lo[a] = NULL;
}
