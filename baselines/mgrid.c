/* mgrid.c - see mgrid.h. */
#include "mgrid.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"

int mgrid_init(mgrid *M, size_t cap, size_t expected, const double *xy, const double *q, double qmin)
{
    int64_t g = (int64_t)floor(sqrt((double)expected / 2));
    if (g < 1) g = 1;
    if (g > 4096) g = 4096;
    M->g = g;
    M->xy = xy;
    M->q = q;
    M->qmin = qmin;
    M->head = malloc((size_t)(g * g) * sizeof *M->head);
    M->next = malloc((cap ? cap : 1) * sizeof *M->next);
    M->prev = malloc((cap ? cap : 1) * sizeof *M->prev);
    M->cell = malloc((cap ? cap : 1) * sizeof *M->cell);
    if (!M->head || !M->next || !M->prev || !M->cell) {
        mgrid_free(M);
        return -1;
    }
    for (int64_t c = 0; c < g * g; c++) M->head[c] = -1;
    for (size_t i = 0; i < cap; i++) M->cell[i] = -1;
    return 0;
}

void mgrid_free(mgrid *M)
{
    free(M->head);
    free(M->next);
    free(M->prev);
    free(M->cell);
    M->head = M->next = M->prev = M->cell = NULL;
}

static int64_t coord(const mgrid *M, double v)
{
    int64_t k = (int64_t)(v * (double)M->g);
    return k >= M->g ? M->g - 1 : (k < 0 ? 0 : k);
}

void mgrid_insert(mgrid *M, int64_t id)
{
    const int64_t c = coord(M, M->xy[2 * id + 1]) * M->g + coord(M, M->xy[2 * id]);
    M->cell[id] = c;
    M->prev[id] = -1;
    M->next[id] = M->head[c];
    if (M->head[c] >= 0) M->prev[M->head[c]] = id;
    M->head[c] = id;
}

void mgrid_remove(mgrid *M, int64_t id)
{
    const int64_t c = M->cell[id];
    if (c < 0) return;
    if (M->prev[id] >= 0) M->next[M->prev[id]] = M->next[id];
    else M->head[c] = M->next[id];
    if (M->next[id] >= 0) M->prev[M->next[id]] = M->prev[id];
    M->cell[id] = -1;
}

/* The ring search: the smallest v below `best` (stop_at >= 0: return as
 * soon as some v < stop_at). */
static double search(const mgrid *M, double x, double y, double qx, const int64_t *ex, int nex, double best,
                     double stop_at)
{
    const int64_t g = M->g, cx = coord(M, x), cy = coord(M, y);
    const double L = 1.0 / (double)g, lo = qx * M->qmin;
    for (int64_t k = 0;; k++) {
        for (int64_t dy = -k; dy <= k; dy++)
            for (int64_t dx = -k; dx <= k; dx += (dy == -k || dy == k || k == 0) ? 1 : 2 * k) {
                const int64_t c = ((cy + dy) % g + g) % g * g + ((cx + dx) % g + g) % g;
                for (int64_t j = M->head[c]; j >= 0; j = M->next[j]) {
                    int skip = 0;
                    for (int e = 0; e < nex; e++) skip |= ex[e] == j;
                    if (skip) continue;
                    const double v = cfpo_torus_dist2(x, y, M->xy[2 * j], M->xy[2 * j + 1]) * (qx * M->q[j]);
                    if (v < best) {
                        best = v;
                        if (v < stop_at) return v;
                    }
                }
            }
        if (2 * k + 1 >= g) break; /* every cell seen */
        const double reach = (double)k * L;
        if (reach * reach * lo >= best) break;
    }
    return best;
}

double mgrid_min(const mgrid *M, double x, double y, double qx, const int64_t *ex, int nex, double bound)
{
    if (!(qx > 0)) return bound > 0 ? 0 : bound; /* v = 0 to every point (the set is never empty here) */
    return search(M, x, y, qx, ex, nex, bound, -1);
}

int mgrid_conflict(const mgrid *M, double x, double y, double qx, double r2)
{
    if (!(qx > 0)) return 1;
    return search(M, x, y, qx, NULL, 0, r2, r2) < r2;
}
