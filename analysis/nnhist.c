/* nnhist.c - see nnhist.h. */
#include "nnhist.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"
#include "stats.h"

int an_nn_compute(const double *xy, size_t n, an_nn *out, uint64_t *hist)
{
    out->nn = malloc(n * sizeof *out->nn);
    if (!out->nn) return -1;
    if (cfpo_nn_stats(xy, n, out->nn, &out->delta_min, &out->delta_avg) != 0) {
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
