/* dart3.c - dart throwing (Cook 1986) on the unit 3-torus, the command
 * cfpo3d-dart (bl3.h).
 *
 * Darts are uniform; a dart is accepted when no earlier point lies within
 * r = REL * Delta3(N). The grid (pd3grid.h) only makes the test O(1). Dart
 * k is (u(3k), u(3k+1), u(3k+2)) of stream DART3. The run ends when N
 * points are placed (stop=target) or at saturation: F consecutive darts
 * rejected (stop=saturated; the free volume fraction then is below about
 * 1/F with probability 1 - 1/e), and writes what it placed. Random
 * sequential addition saturates near packing fraction 0.384 (Torquato,
 * Uche and Stillinger 2006), REL about 0.80: with a smaller REL the run
 * reaches N first. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bl3.h"
#include "pd3grid.h"
#include "rng.h"
#include "solve3.h"

#define DART3_STREAM 0x4441525433ULL /* "DART3" */

enum { REL, MAX_FAILS };

static int run_dart(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                    int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    (void)cb, (void)user;
    const double r = opt[REL] * cfpo3_delta_bound((double)n);
    const uint64_t max_fails = (uint64_t)opt[MAX_FAILS];
    double *p = calloc(3 * (size_t)n, sizeof *p);
    pd3grid G;
    if (!p || n > INT32_MAX || pd3grid_init(&G, r, p) != 0) {
        free(p);
        snprintf(err, errlen, "out of memory for %lld points at radius %g", (long long)n, r);
        return -1;
    }
    int64_t placed = 0;
    uint64_t dart = 0, fails = 0;
    info->stop = "target";
    while (placed < n) {
        double x[3];
        for (int a = 0; a < 3; a++) x[a] = cfpo_rand01(seed, DART3_STREAM, 3 * dart + (uint64_t)a);
        dart++;
        if (pd3grid_conflict(&G, x)) {
            if (++fails >= max_fails) {
                info->stop = "saturated";
                break;
            }
            continue;
        }
        fails = 0;
        for (int a = 0; a < 3; a++) p[3 * placed + a] = x[a];
        pd3grid_put(&G, x, (int32_t)placed);
        placed++;
    }
    pd3grid_free(&G);
    info->trials = (int64_t)dart;
    *xyz = p;
    *n_out = placed;
    return 0;
}

const bl3_method bl3_dart = {
    .name = "dart3d", .prog = "cfpo3d-dart", .min_n = 2, .run = run_dart, .noptions = 2,
    .options = {{"rel-radius", 0.78, 0.01, 1.0,
                 "      --rel-radius REL r = REL * Delta3(N), Delta3(N) = (sqrt(2)/N)^(1/3) (default %g)\n"},
                {"max-fails", 1e6, 1, 1e12,
                 "      --max-fails F    saturation: stop after F consecutive rejected darts and write\n"
                 "                       the points placed (default %g)\n"}},
    .about = "Dart throwing (Cook 1986) on the unit 3-torus: uniform darts, each kept when no\n"
             "earlier point lies within r, until N are placed or the set saturates (F darts\n"
             "rejected in a row). Direct. SUMMARY n is the count placed."};
