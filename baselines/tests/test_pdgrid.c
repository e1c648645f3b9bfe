/* test_pdgrid.c - the Poisson-disk background grid against brute force:
 * the conflict test and the neighbour query give exactly the answers of a
 * scan over all points, for radii whose windows wrap onto themselves too. */
#include <stdlib.h>

#include "geom.h"
#include "pdgrid.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static void check_radius(double r, int npts, uint64_t seed)
{
    pdgrid G;
    CHECK(pdgrid_init(&G, r) == 0, "init r=%g", r);
    CHECK(sqrt(2.0) * G.c <= r, "cell diagonal %g > r %g", sqrt(2.0) * G.c, r);
    double *xy = malloc(2 * (size_t)npts * sizeof *xy);
    int n = 0;
    /* A Poisson-disk set made by brute force, stored in the grid. */
    for (int k = 0; k < 50 * npts && n < npts; k++) {
        double x = cfpo_rand01(seed, 1, 2 * (uint64_t)k), y = cfpo_rand01(seed, 1, 2 * (uint64_t)k + 1);
        int bad = 0;
        for (int j = 0; j < n && !bad; j++) bad = cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]) < r * r;
        CHECK(pdgrid_conflict(&G, x, y) == bad, "conflict r=%g dart %d: grid %d brute %d", r, k,
              pdgrid_conflict(&G, x, y), bad);
        if (!bad) {
            xy[2 * n] = x, xy[2 * n + 1] = y;
            pdgrid_put(&G, x, y, (uint32_t)n);
            n++;
        }
    }
    /* Neighbours within R: the same set as a scan. */
    uint32_t ids[4096];
    for (int q = 0; q < 200; q++) {
        double x = cfpo_rand01(seed, 2, 2 * (uint64_t)q), y = cfpo_rand01(seed, 2, 2 * (uint64_t)q + 1);
        double R = 2.0 * r < 0.49 ? 2.0 * r : 0.49;
        int m = pdgrid_near(&G, x, y, R, ids, 4096), want = 0, found = 0;
        for (int j = 0; j < n; j++)
            if (cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]) < R * R) {
                want++;
                for (int i = 0; i < m; i++) found += ids[i] == (uint32_t)j;
            }
        CHECK(m == want && found == want, "near r=%g query %d: %d ids, %d wanted, %d matched", r,
              q, m, want, found);
    }
    free(xy);
    pdgrid_free(&G);
}

int main(void)
{
    check_radius(0.02, 1500, 1);  /* ordinary windows */
    check_radius(0.11, 60, 2);    /* the 2r window nearly wraps */
    check_radius(0.3, 10, 3);     /* windows wider than the torus */
    return test_report(passed_, failed_);
}
