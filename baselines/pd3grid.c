/* pd3grid.c - see pd3grid.h. */
#include "pd3grid.h"

#include <math.h>
#include <stdlib.h>

#include "nn3.h"

static long cell1(double x, long G)
{
    long c = (long)(x * (double)G);
    return c < 0 ? 0 : (c >= G ? G - 1 : c);
}

int pd3grid_init(pd3grid *g, double r, const double *points)
{
    g->r = r, g->r2 = r * r, g->p = points, g->cell = NULL;
    const double G = ceil(sqrt(3.0) / r);
    if (!(r > 0) || G > 1290) return -1; /* 1290^3 < 2^31 */
    g->G = G < 5 ? 5 : (long)G;
    const size_t cells = (size_t)g->G * (size_t)g->G * (size_t)g->G;
    g->cell = malloc(cells * sizeof *g->cell);
    if (!g->cell) return -1;
    for (size_t i = 0; i < cells; i++) g->cell[i] = -1;
    return 0;
}

void pd3grid_free(pd3grid *g)
{
    free(g->cell);
    g->cell = NULL;
}

int pd3grid_conflict(const pd3grid *g, const double *x)
{
    const long G = g->G, cx = cell1(x[0], G), cy = cell1(x[1], G), cz = cell1(x[2], G);
    /* a point within r lies at most ceil(r G) cells away (2 for the grid's
     * own G; more only when G was raised to 5 for a large r) */
    const long reach = (long)ceil(g->r * (double)G);
    for (long dz = -reach; dz <= reach; dz++) {
        const long z = ((cz + dz) % G + G) % G;
        for (long dy = -reach; dy <= reach; dy++) {
            const long y = ((cy + dy) % G + G) % G;
            for (long dx = -reach; dx <= reach; dx++) {
                const int32_t id = g->cell[(z * G + y) * G + ((cx + dx) % G + G) % G];
                if (id < 0) continue;
                const double *q = g->p + 3 * (size_t)id;
                const double a = cfpo3_pdiff(x[0], q[0]), b = cfpo3_pdiff(x[1], q[1]), c = cfpo3_pdiff(x[2], q[2]);
                if (a * a + b * b + c * c < g->r2) return 1;
            }
        }
    }
    return 0;
}

void pd3grid_put(pd3grid *g, const double *x, int32_t id)
{
    const long G = g->G;
    g->cell[(cell1(x[2], G) * G + cell1(x[1], G)) * G + cell1(x[0], G)] = id;
}
