/* nnhist.c - see nnhist.h. */
#include "nnhist.h"

#include <math.h>
#include <string.h>
#include <stdlib.h>

#include "geom.h"
#include "stats.h"

static size_t coord(double v, size_t g)
{
    size_t c = (size_t)(v * (double)g);
    return c >= g ? g - 1 : c;
}

/* The most points in one cell of the core's grid (about 2 per cell). */
static size_t crowding(const double *xy, size_t n)
{
    size_t g = (size_t)floor(sqrt((double)n / 2.0));
    if (g < 1) g = 1;
    size_t *count = calloc(g * g, sizeof *count), most = n;
    if (!count) return most;
    most = 0;
    for (size_t i = 0; i < n; i++) {
        const size_t c = coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g);
        if (++count[c] > most) most = count[c];
    }
    free(count);
    return most;
}

int an_nn_stats(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg)
{
    if (n < 2) return -1;
    /* A spread set: the core's grid is faster than the tree (and gives the
     * same bits). */
    if (crowding(xy, n) <= AN_NN_CROWDED) return cfpo_nn_stats(xy, n, nn, delta_min, delta_avg);
    return an_nn_stats_tree(xy, n, T, nn, delta_min, delta_avg);
}

int an_nn_stats_tree(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg)
{
    if (n < 2) return -1;
    an_ptree own;
    int built = 0;
    if (!T) {
        if (an_ptree_build(&own, xy, n) != 0) { an_ptree_free(&own); return -1; }
        T = &own;
        built = 1;
    }
    /* The core's order: cells of its grid by rows, points by index in a
     * cell; a sum per row, then the rows. */
    size_t g = (size_t)floor(sqrt((double)n / 2.0));
    if (g < 1) g = 1;
    size_t *start = calloc(g * g + 1, sizeof *start), *idx = malloc(n * sizeof *idx);
    double *d = malloc(n * sizeof *d);
    if (!start || !idx || !d) {
        free(start); free(idx); free(d);
        if (built) an_ptree_free(&own);
        return -1;
    }
    for (size_t i = 0; i < n; i++) start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g) + 1]++;
    for (size_t c = 0; c < g * g; c++) start[c + 1] += start[c];
    for (size_t i = 0; i < n; i++) idx[start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g)]++] = i;
    for (size_t c = g * g; c > 0; c--) start[c] = start[c - 1];
    start[0] = 0;
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t i = 0; i < n; i++) d[i] = sqrt(an_ptree_nearest_torus(T, xy[2 * i], xy[2 * i + 1], i));
    double sum = 0, mn = INFINITY;
    for (size_t cy = 0; cy < g; cy++) {
        double rs = 0, rm = INFINITY;
        for (size_t k = start[cy * g]; k < start[(cy + 1) * g]; k++) {
            rs += d[idx[k]];
            if (d[idx[k]] < rm) rm = d[idx[k]];
        }
        sum += rs;
        if (rm < mn) mn = rm;
    }
    const double D = cfpo_delta_bound((double)n);
    *delta_min = mn / D;
    *delta_avg = sum / (double)n / D;
    if (nn) memcpy(nn, d, n * sizeof *d);
    free(start); free(idx); free(d);
    if (built) an_ptree_free(&own);
    return 0;
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
