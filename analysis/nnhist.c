/* nnhist.c - see nnhist.h. */
#include "nnhist.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"
#include "cellgrid.h"
#include "stats.h"

/* Through the tree (T, or one built here), summed in G's order: the
 * core's, a sum per row of cells, then the rows. */
static int tree_stats(const double *xy, size_t n, const an_cellgrid *G, const an_ptree *T, double *nn,
                      double *delta_min, double *delta_avg)
{
    an_ptree own = {0};
    double *d = nn ? nn : malloc(n * sizeof *d);
    int status = -1;
    if (!d) return -1;
    if (!T) {
        if (an_ptree_build(&own, xy, n) != 0) goto done;
        T = &own;
    }
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t i = 0; i < n; i++) d[i] = sqrt(an_ptree_nearest_torus(T, xy[2 * i], xy[2 * i + 1], i));
    const size_t g = G->g;
    double sum = 0, mn = INFINITY;
    for (size_t cy = 0; cy < g; cy++) {
        double rs = 0, rm = INFINITY;
        for (size_t k = G->start[cy * g]; k < G->start[(cy + 1) * g]; k++) {
            rs += d[G->idx[k]];
            if (d[G->idx[k]] < rm) rm = d[G->idx[k]];
        }
        sum += rs;
        if (rm < mn) mn = rm;
    }
    const double D = cfpo_delta_bound((double)n);
    *delta_min = mn / D;
    *delta_avg = sum / (double)n / D;
    status = 0;
done:
    if (d != nn) free(d);
    an_ptree_free(&own);
    return status;
}

int an_nn_stats(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg)
{
    if (n < 2) return -1;
    an_cellgrid G;
    int status = -1;
    if (an_cellgrid_build(xy, n, &G) == 0) {
        size_t most = 0; /* the most points in one cell */
        for (size_t c = 0; c < G.g * G.g; c++)
            if (G.start[c + 1] - G.start[c] > most) most = G.start[c + 1] - G.start[c];
        /* A spread set: the core's grid is faster than the tree (and gives
         * the same bits). */
        status = most <= AN_NN_CROWDED ? cfpo_nn_stats(xy, n, nn, delta_min, delta_avg)
                                       : tree_stats(xy, n, &G, T, nn, delta_min, delta_avg);
    }
    an_cellgrid_free(&G);
    return status;
}

int an_nn_stats_tree(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg)
{
    if (n < 2) return -1;
    an_cellgrid G;
    const int status = an_cellgrid_build(xy, n, &G) == 0 ? tree_stats(xy, n, &G, T, nn, delta_min, delta_avg) : -1;
    an_cellgrid_free(&G);
    return status;
}

int an_nn_compute(const double *xy, size_t n, an_nn *out, uint64_t *hist)
{
    out->nn = malloc(n * sizeof *out->nn);
    if (!out->nn) return -1;
    if (an_nn_stats(xy, n, NULL, out->nn, &out->delta_min, &out->delta_avg) != 0) {
        free(out->nn);
        out->nn = NULL;
        return -1;
    }
    const double D = cfpo_delta_bound((double)n);
    for (size_t i = 0; i < n; i++) {
        double b = floor(out->nn[i] / D / AN_NN_BIN);
        hist[b >= AN_NN_BINS - 1 ? AN_NN_BINS - 1 : (size_t)b]++;
    }
    return 0;
}
