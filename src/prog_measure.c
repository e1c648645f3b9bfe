/* prog_measure.c - see prog_measure.h. */
#include "prog_measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_buckets.h"

#include <omp.h>

int cfpo_prog_measure_groups(const double *xy, const int64_t *sizes, int K, int classes, int nth, double *dmin,
                             double *davg, double *raw, char *err, size_t errlen)
{
    double *nd = malloc((size_t)(sizes[K - 1] > 0 ? sizes[K - 1] : 1) * sizeof *nd);
    if (!nd) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int k = 0; k < K + (classes ? 1 : 0); k++) {
        const int64_t lo0 = classes && k > 0 && k < K ? sizes[k - 1] : 0;
        const int64_t m = (k < K ? sizes[k] : sizes[K - 1]) - lo0;
        xy += 2 * lo0;
        prog_buckets B = {0};
        if (prog_buckets_build(&B, xy, m) != 0) {
            prog_buckets_free(&B);
            free(nd);
            snprintf(err, errlen, "out of memory");
            return -1;
        }
#pragma omp parallel for schedule(static) num_threads(nth)
        for (int64_t i = 0; i < m; i++) nd[i] = sqrt(prog_buckets_nearest2(&B, xy[2 * i], xy[2 * i + 1], i, -1.0));
        double lo = INFINITY, sum = 0;
        for (int64_t i = 0; i < m; i++) {
            if (nd[i] < lo) lo = nd[i];
            sum += nd[i];
        }
        prog_buckets_free(&B);
        const double D = cfpo_delta_bound((double)m);
        dmin[k] = lo / D;
        davg[k] = sum / (double)m / D;
        if (raw) raw[k] = lo;
        xy -= 2 * lo0;
    }
    free(nd);
    return 0;
}

int cfpo_prog_measure(const double *xy, const int64_t *sizes, int K, double *dmin, double *davg, char *err,
                      size_t errlen)
{
    return cfpo_prog_measure_groups(xy, sizes, K, 0, 1, dmin, davg, NULL, err, errlen);
}
