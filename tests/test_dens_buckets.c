/* test_dens_buckets.c - the bucket grid of a density block (src/density/dens_buckets.c),
 * against brute force, with and without wrap:
 *  - every point is in the bucket its position names, each exactly once,
 *    also after random moves;
 *  - ring k around a bucket is exactly the buckets at (periodic) Chebyshev
 *    distance k, and -1 once rings 0..k-1 held every bucket;
 *  - the distance bound the engine relies on: a point outside rings 0..k
 *    around a query's bucket is at least k h from the query;
 *  - a span covers every bucket column that meets [lo, hi), each once. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dens_buckets.h"
#include "testutil.h"

static int passed_, failed_;

static double urand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (double)((*s >> 8) & 0xffffff) / 16777216.0;
}

static int cheb(int a, int b, int B, int wrap)
{
    int ax = a % B, ay = a / B, bx = b % B, by = b / B;
    int dx = abs(ax - bx), dy = abs(ay - by);
    if (wrap) {
        if (B - dx < dx) dx = B - dx;
        if (B - dy < dy) dy = B - dy;
    }
    return dx > dy ? dx : dy;
}

static void run(int m, int wrap, unsigned seed)
{
    const double x0 = wrap ? -1.0 / 3 : -0.1, side = wrap ? 1.0 : 0.3;
    double *x = malloc((size_t)m * sizeof *x), *y = malloc((size_t)m * sizeof *y);
    for (int i = 0; i < m; i++) {
        x[i] = x0 + side * urand(&seed);
        y[i] = x0 + side * urand(&seed);
    }
    cfpo_dens_buckets b;
    memset(&b, 0, sizeof b);
    CHECK(cfpo_dens_buckets_build(&b, x, y, m, x0, x0, side, wrap, 2.0) == 0, "build");
    const int B = b.B;
    int *ring = malloc((size_t)(8 * B + 1) * sizeof *ring), *seen = malloc((size_t)B * B * sizeof *seen);
    int *where = malloc((size_t)m * sizeof *where);
    for (int mv = 0; mv < 3 * m; mv++) { /* random moves, lists kept */
        const int p = (int)(urand(&seed) * m);
        const int from = cfpo_dens_bucket_of(&b, x[p], y[p]);
        x[p] = x0 + side * urand(&seed);
        y[p] = x0 + side * urand(&seed);
        cfpo_dens_buckets_move(&b, p, from, cfpo_dens_bucket_of(&b, x[p], y[p]));
    }
    int bad = 0;
    for (int i = 0; i < m; i++) where[i] = -1;
    for (int c = 0; c < B * B; c++)
        for (int j = b.head[c]; j >= 0; j = b.next[j]) {
            if (where[j] != -1) bad++;
            where[j] = c;
        }
    for (int i = 0; i < m; i++)
        if (where[i] != cfpo_dens_bucket_of(&b, x[i], y[i])) bad++;
    CHECK(bad == 0, "m=%d wrap=%d: %d points in a wrong bucket or twice", m, wrap, bad);
    int badr = 0, badd = 0;
    for (int q = 0; q < 40; q++) {
        const double qx = x0 + side * urand(&seed), qy = x0 + side * urand(&seed);
        const int c = cfpo_dens_bucket_of(&b, qx, qy);
        memset(seen, 0, (size_t)B * B * sizeof *seen);
        int k = 0;
        for (;; k++) {
            const int nb = cfpo_dens_ring(&b, c, k, ring);
            if (nb < 0) break;
            for (int r = 0; r < nb; r++) {
                const int d = cheb(c, ring[r], B, wrap);
                if (d != k && !(wrap && 2 * k + 1 > B)) badr++;
                seen[ring[r]] = 1;
            }
            /* every bucket not yet seen is at distance > k; its points at least k h away */
            for (int cc = 0; cc < B * B; cc++) {
                if (seen[cc]) continue;
                if (cheb(c, cc, B, wrap) <= k) badr++;
                for (int j = b.head[cc]; j >= 0; j = b.next[j]) {
                    double ex = x[j] - qx, ey = y[j] - qy;
                    if (wrap) { ex -= rint(ex); ey -= rint(ey); }
                    if (sqrt(ex * ex + ey * ey) < k * b.h * (1 - 1e-12)) badd++;
                }
            }
        }
        for (int cc = 0; cc < B * B; cc++)
            if (!seen[cc]) badr++;
        /* a span of the query +- a random reach */
        const double R = side * urand(&seed) * 0.6;
        int f, n;
        cfpo_dens_span(&b, qx - R, qx + R, b.x0, &f, &n);
        memset(seen, 0, (size_t)B * sizeof *seen);
        for (int i = 0; i < n; i++) {
            if (seen[(f + i) % B]) badr++;
            seen[(f + i) % B] = 1;
        }
        for (int j = 0; j < m; j++) {
            double ex = x[j] - qx;
            if (wrap) ex -= rint(ex);
            if (fabs(ex) <= R && !seen[cfpo_dens_bucket_of(&b, x[j], y[j]) % B]) badr++;
        }
    }
    CHECK(badr == 0, "m=%d wrap=%d B=%d: %d ring/span faults", m, wrap, B, badr);
    CHECK(badd == 0, "m=%d wrap=%d B=%d: %d points nearer than the ring bound", m, wrap, B, badd);
    cfpo_dens_buckets_free(&b);
    free(x); free(y); free(ring); free(seen); free(where);
}

int main(void)
{
    run(1, 0, 1);
    run(50, 0, 2);
    run(2000, 0, 3);
    run(2000, 1, 4);
    run(7, 1, 5);
    run(333, 1, 6);
    return test_report(passed_, failed_);
}
