/* cellgrid.c - see cellgrid.h. */
#include "cellgrid.h"

#include <math.h>
#include <stdlib.h>

static size_t coord(double v, size_t g)
{
    size_t c = (size_t)(v * (double)g);
    return c >= g ? g - 1 : c;
}

int an_cellgrid_build(const double *xy, size_t n, an_cellgrid *G)
{
    size_t g = (size_t)floor(sqrt((double)n / 2.0));
    G->g = g = g < 1 ? 1 : g;
    G->L = 1.0 / (double)g;
    G->start = calloc(g * g + 1, sizeof *G->start);
    G->idx = malloc(n * sizeof *G->idx);
    if (!G->start || !G->idx) return -1;
    for (size_t i = 0; i < n; i++) G->start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g) + 1]++;
    for (size_t c = 0; c < g * g; c++) G->start[c + 1] += G->start[c];
    for (size_t i = 0; i < n; i++) G->idx[G->start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g)]++] = i;
    for (size_t c = g * g; c > 0; c--) G->start[c] = G->start[c - 1];
    G->start[0] = 0;
    return 0;
}

void an_cellgrid_free(an_cellgrid *G)
{
    free(G->start);
    free(G->idx);
    G->start = G->idx = NULL;
}
