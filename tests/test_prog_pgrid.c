/* test_prog_pgrid.c - the nested grids of the progressive joint move
 * (src/prog_pgrid.c) against brute force on the torus:
 *  - after rounds of moves (far jumps and small steps, stamped with the
 *    round's time), the measure that finds a point's nearest distance again
 *    only where a stamp changed gives every prefix's delta_min, delta_avg
 *    and smallest distance as the O(m^2) values;
 *  - every grid holds exactly its prefix (its level alone for the level
 *    grids) after the moves;
 *  - prog_pgrid_changed sees a move within its radius and not one far
 *    outside it. */
#include <math.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_pgrid.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

static double nn(const double *xy, int64_t m, int64_t i)
{
    double b = INFINITY;
    for (int64_t j = 0; j < m; j++)
        if (j != i) {
            const double d = sqrt(prog_torus_d2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]));
            b = d < b ? d : b;
        }
    return b;
}

static int64_t count(const prog_buckets *B)
{
    int64_t c = 0;
    for (int64_t b = 0; b < B->gs * B->gs; b++)
        for (int64_t k = B->head[b]; k >= 0; k = B->next[k]) c++;
    return c;
}

int main(void)
{
    enum { N = 1500, K = 4 };
    const int64_t sizes[K] = {150, 400, 800, N};
    double *xy = malloc(2 * N * sizeof *xy);
    int lev[N];
    for (int64_t i = 0, l = 0; i < N; i++) {
        while (i >= sizes[l]) l++;
        lev[i] = (int)l;
        xy[2 * i] = cfpo_rand01(7, 1, 2 * (uint64_t)i);
        xy[2 * i + 1] = cfpo_rand01(7, 1, 2 * (uint64_t)i + 1);
    }
    prog_pgrid P = {0};
    CHECK(prog_pgrid_init(&P, xy, sizes, K, lev, 1.2) == 0, "init");
    uint32_t now = 1;
    int bad = 0;
    uint64_t c = 0;
    for (int round = 0; round < 12; round++) {
        double dmin[K], davg[K], raw[K];
        prog_pgrid_measure(&P, 2, now, dmin, davg, raw);
        for (int k = 0; k < K; k++) {
            double lo = INFINITY, sum = 0;
            for (int64_t i = 0; i < sizes[k]; i++) {
                const double d = nn(xy, sizes[k], i);
                lo = d < lo ? d : lo;
                sum += d;
            }
            const double D = cfpo_delta_bound((double)sizes[k]);
            if (fabs(lo / D - dmin[k]) > 1e-12 || fabs(sum / (double)sizes[k] / D - davg[k]) > 1e-12 || raw[k] != lo)
                bad++;
        }
        now++;
        for (int t = 0; t < 120; t++) { /* far jumps, then small steps */
            const int64_t k = (int64_t)(cfpo_rand01(9, 2, c++) * N) % N;
            double x, y;
            if (t < 30) {
                x = cfpo_rand01(9, 3, c++), y = cfpo_rand01(9, 3, c++);
            } else {
                x = xy[2 * k] + 0.01 * (cfpo_rand01(9, 4, c++) - 0.5), y = xy[2 * k + 1] + 0.01 * (cfpo_rand01(9, 4, c++) - 0.5);
                x -= floor(x), y -= floor(y);
            }
            prog_pgrid_move(&P, xy, k, x, y, now);
        }
    }
    CHECK(bad == 0, "the measure after moves equals brute force (%d differences)", bad);
    int held = 1;
    for (int g = 0; g < K; g++) {
        if (count(&P.G[g]) != sizes[g]) held = 0;
        if (g > 0 && count(&P.V[g]) != sizes[g] - sizes[g - 1]) held = 0;
    }
    CHECK(held, "each grid holds its prefix, each level grid its level");
    /* one more move: seen within reach, not from the far side */
    now++;
    prog_pgrid_move(&P, xy, 5, 0.25, 0.25, now);
    CHECK(prog_pgrid_changed(&P, 3, 0.26, 0.25, 0.02, now), "a move within reach is seen");
    CHECK(!prog_pgrid_changed(&P, 3, 0.75, 0.75, 0.02, now), "a move far away is not");
    prog_pgrid_free(&P);
    free(xy);
    return test_report(passed_, failed_);
}
