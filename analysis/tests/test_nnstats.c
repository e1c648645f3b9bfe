/* test_nnstats.c - an_nn_stats_tree (the points' tree), and an_nn_stats
 * (the tree or the core's grid, as the set crowds), give the core's
 * cfpo_nn_stats bit for bit: every nearest-neighbour distance, delta_min
 * and delta_avg (summed in the core's order), on uniform sets, clusters of
 * 1e-3 and 1e-9, a cluster across the torus's corner, lines, repeated
 * positions, a lattice (exact ties) and coordinates at the torus's edge;
 * with and without a tree given. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nnhist.h"
#include "ptree.h"
#include "rng.h"
#include "stats.h"
#include "testutil.h"

static int passed_, failed_;

static void same(const char *what, const double *xy, size_t n)
{
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b), amin, aavg, bmin, bavg;
    CHECK(cfpo_nn_stats(xy, n, a, &amin, &aavg) == 0, "%s: core", what);
    an_ptree T;
    CHECK(an_ptree_build(&T, xy, n) == 0, "%s: tree", what);
    for (int way = 0; way < 3; way++) { /* the tree, built or given, and the choice */
        const int with_tree = way == 1;
        CHECK((way < 2 ? an_nn_stats_tree(xy, n, with_tree ? &T : NULL, b, &bmin, &bavg)
                       : an_nn_stats(xy, n, &T, b, &bmin, &bavg)) == 0,
              "%s: an_nn_stats", what);
        size_t bad = 0;
        for (size_t i = 0; i < n; i++) bad += memcmp(&a[i], &b[i], sizeof a[i]) != 0;
        CHECK(bad == 0, "%s: %zu of %zu distances differ (tree given: %d)", what, bad, n, with_tree);
        CHECK(memcmp(&amin, &bmin, sizeof amin) == 0 && memcmp(&aavg, &bavg, sizeof aavg) == 0,
              "%s: delta_min %.17g / %.17g, delta_avg %.17g / %.17g", what, amin, bmin, aavg, bavg);
    }
    an_ptree_free(&T);
    free(a);
    free(b);
}

int main(void)
{
    const size_t N = 5000;
    double *xy = malloc(2 * N * sizeof *xy);
    const size_t sizes[] = {2, 3, 10, 999, 5000};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        for (size_t i = 0; i < sizes[s]; i++) {
            xy[2 * i] = cfpo_rand01(31, i, 0);
            xy[2 * i + 1] = cfpo_rand01(31, i, 1);
        }
        same("uniform", xy, sizes[s]);
    }
    for (size_t i = 0; i < 3000; i++) {
        xy[2 * i] = 0.5 + 1e-3 * cfpo_rand01(32, i, 0);
        xy[2 * i + 1] = 0.5 + 1e-3 * cfpo_rand01(32, i, 1);
    }
    same("cluster 1e-3", xy, 3000);
    for (size_t i = 0; i < 2000; i++) {
        xy[2 * i] = 0.3 + 1e-9 * cfpo_rand01(33, i, 0);
        xy[2 * i + 1] = 0.6 + 1e-9 * cfpo_rand01(33, i, 1);
    }
    same("cluster 1e-9", xy, 2000);
    for (size_t i = 0; i < 2000; i++) { /* across the corner: coordinates near 0 and near 1 */
        const double u = 2e-3 * cfpo_rand01(34, i, 0) - 1e-3, v = 2e-3 * cfpo_rand01(34, i, 1) - 1e-3;
        xy[2 * i] = u < 0 ? 1 + u : u;
        xy[2 * i + 1] = v < 0 ? 1 + v : v;
        if (xy[2 * i] >= 1) xy[2 * i] = nextafter(1.0, 0.0);
        if (xy[2 * i + 1] >= 1) xy[2 * i + 1] = nextafter(1.0, 0.0);
    }
    same("cluster across the corner", xy, 2000);
    for (size_t i = 0; i < 1000; i++) { xy[2 * i] = (double)i / 1000; xy[2 * i + 1] = 0.5; }
    same("horizontal line", xy, 1000);
    for (size_t i = 0; i < 1000; i++) { xy[2 * i] = 0.1 + 5e-4 * (double)i; xy[2 * i + 1] = 0.3 + 5e-4 * (double)i; }
    same("diagonal segment", xy, 1000);
    for (size_t i = 0; i < 600; i++) { xy[2 * i] = i % 3 ? 0.25 : 0.75; xy[2 * i + 1] = i % 2 ? 0.125 : 0.5; }
    same("repeated positions", xy, 600);
    for (size_t i = 0; i < 1024; i++) { xy[2 * i] = (double)(i % 32) / 32; xy[2 * i + 1] = (double)(i / 32) / 32; }
    same("32 x 32 lattice", xy, 1024);
    const double edge[] = {0, 5e-324, 1e-300, 0.5, nextafter(1.0, 0.0), nextafter(0.5, 0.0)};
    for (size_t i = 0; i < 36; i++) { xy[2 * i] = edge[i % 6]; xy[2 * i + 1] = edge[i / 6]; }
    same("torus edge", xy, 36);
    free(xy);
    return test_report(passed_, failed_);
}
