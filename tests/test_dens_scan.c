/* test_dens_scan.c - the accept check's scan of a one-bucket block
 * (src/density/dens_scan.c) against the scalar scan in block order: on
 * 20,000 random blocks of 1-64 points (on a lattice, three values of q,
 * copies of points), a random spot and a threshold drawn around the
 * block's values, the same answer: the first j != p, in order, whose
 * value at the spot is not above the threshold, or none. Where the CPU
 * lacks the AVX-512 route the scan says so (-2) and the test checks that
 * only. Fails when the vector scan answers the last such point, or
 * forgets to leave out the moving point. */
#include <stdio.h>

#include "dens_scan.h"
#include "testutil.h"

static int passed_, failed_;

static unsigned long long rng = 777;
static double urand(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) / 9007199254740992.0;
}

int main(void)
{
    double bx[64], by[64], br[64];
    const double qs[3] = {1.0, 0.75, 1.3};
    int n = 0, bad = 0, none = 0, first = 0, later = 0, unavailable = 0;
    for (int t = 0; t < 20000; t++) {
        const int m = 1 + (int)(urand() * 64);
        for (int j = 0; j < m; j++) {
            if (j > 0 && urand() < 0.2) {
                const int c = (int)(urand() * j);
                bx[j] = bx[c]; by[j] = by[c]; br[j] = br[c];
                continue;
            }
            bx[j] = -0.03 + (double)(int)(urand() * 16) * 0.005;
            by[j] = -0.03 + (double)(int)(urand() * 16) * 0.005;
            br[j] = qs[(int)(urand() * 3)];
        }
        const int p = (int)(urand() * m);
        const double px = (t & 1) ? bx[p] : -0.03 + 0.08 * urand(), py = (t & 1) ? by[p] : -0.03 + 0.08 * urand();
        const double rc = qs[(int)(urand() * 3)], thr = 0.002 * urand() * urand();
        int want = -1;
        for (int j = 0; j < m && want < 0; j++) {
            if (j == p) continue;
            const double ex = bx[j] - px, ey = by[j] - py;
            if (!((ex * ex + ey * ey) * br[j] * rc > thr)) want = j;
        }
        const int got = cfpo_dens_scan_block(bx, by, br, m, p, px, py, rc, thr);
        if (got == -2) { unavailable++; continue; }
        n++;
        bad += got != want;
        none += want < 0;
        first += want >= 0 && want < 8;
        later += want >= 8;
    }
    CHECK(bad == 0, "%d of %d scans differ from the scalar scan", bad, n);
    CHECK(n == 0 || (none > n / 20 && first > n / 20 && later > n / 20),
          "the cases are not all met: %d clear, %d in the first eight, %d later", none, first, later);
    printf("%d scans (%d clear, %d refused by one of the first eight, %d by a later one); %d without the route\n", n,
           none, first, later, unavailable);
    return test_report(passed_, failed_);
}
