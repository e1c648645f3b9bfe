/* prog_insert.c - see prog_insert.h. */
#include "prog_insert.h"

#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_buckets.h"
#include "rng.h"

int cfpo_prog_insert(double *xy, int64_t m0, int64_t m1, int cand, uint64_t seed, uint64_t stream, char *err,
                     size_t errlen)
{
    prog_buckets B = {0};
    if (prog_buckets_init(&B, xy, m1, m1) != 0) {
        prog_buckets_free(&B);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int64_t k = 0; k < m0; k++) prog_buckets_link(&B, k);
    uint64_t counter = 0;
    for (int64_t k = m0; k < m1; k++) {
        double bx = 0, by = 0, bd = -1;
        for (int c = 0; c < cand; c++) {
            const double x = cfpo_rand01(seed, stream, counter++), y = cfpo_rand01(seed, stream, counter++);
            const double d2 = k > 0 ? prog_buckets_nearest2(&B, x, y, -1, bd) : 1.0;
            if (d2 > bd) bx = x, by = y, bd = d2;
        }
        xy[2 * k] = bx;
        xy[2 * k + 1] = by;
        prog_buckets_link(&B, k);
    }
    prog_buckets_free(&B);
    return 0;
}
