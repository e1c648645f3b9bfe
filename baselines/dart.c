/* dart.c - brute-force dart throwing (Cook 1986), the paper's DT.
 *
 * Darts are uniform on the torus; a dart is accepted when no earlier point
 * lies within r. The grid (pdgrid.h) only makes the conflict test O(1); the
 * method is unchanged. Dart k is (rand01(seed, DART_STREAM, 2k),
 * rand01(seed, DART_STREAM, 2k+1)).
 * Saturation: a dart throwing set never knows that no dart can land any
 * more, so the run stops when max_fails consecutive darts are rejected
 * (probability that a free area fraction p is missed: (1 - p)^max_fails);
 * the caller reports how many points were placed. */
#include <stdlib.h>

#include "pd.h"
#include "pdgrid.h"
#include "rng.h"

#include <stdio.h>

#define DART_STREAM 0x4441525453ULL /* "DARTS" */

int dart_sample(const pd_params *p, pd_result *res, char *err, size_t errlen)
{
    res->xy = NULL;
    res->n = 0;
    res->trials = 0;
    res->saturated = 0;
    pdgrid G;
    double *xy = malloc(2 * (size_t)p->target * sizeof *xy);
    if (!xy || pdgrid_init(&G, p->r) != 0) {
        free(xy);
        snprintf(err, errlen, "out of memory for %lld points at radius %g", (long long)p->target,
                 p->r);
        return -1;
    }
    int64_t placed = 0;
    uint64_t dart = 0, fails = 0;
    while (placed < p->target) {
        const double x = cfpo_rand01(p->seed, DART_STREAM, 2 * dart);
        const double y = cfpo_rand01(p->seed, DART_STREAM, 2 * dart + 1);
        dart++;
        if ((dart & ((1u << 22) - 1)) == 0 && p->report) p->report(p->user, placed, dart, (int64_t)fails);
        if (pdgrid_conflict(&G, x, y)) {
            if (++fails >= p->max_fails) {
                res->saturated = 1;
                break;
            }
            continue;
        }
        fails = 0;
        pdgrid_put(&G, x, y, (uint32_t)placed);
        xy[2 * placed] = x;
        xy[2 * placed + 1] = y;
        placed++;
        if (p->report && placed % p->report_step == 0) p->report(p->user, placed, dart, 0);
    }
    pdgrid_free(&G);
    res->xy = xy;
    res->n = placed;
    res->trials = dart;
    return 0;
}
