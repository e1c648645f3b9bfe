/* test_pmj.c - progressive multi-jittered (0,2) sequences (pmj.h):
 *  - the (0,2)-sequence property of every power-of-two prefix, by brute
 *    force: for k = 0..12 and every shape a = 0..k, the first 2^k points
 *    map one to one onto the 2^a x 2^(k-a) cells (pmj02 and pmj02bn, three
 *    seeds each, 4,096 points and a prefix of 3,000); the same check fails
 *    on a jittered set, on white noise and on a pmj02 set with two points'
 *    y swapped;
 *  - progressive: the first m points of a run for n are the run for m;
 *    the same bytes twice; every coordinate in [0, 1);
 *  - the paper's progressive order (pmj02 and pmj02bn): with N = 4^m,
 *    points i, N + i, 2N + i, 3N + i in the four subquadrants of one cell of
 *    the 2^m grid, N + i diagonally opposite i; white noise is not;
 *  - the --global variant (candidates from every valid subquadrant): nets
 *    too; delta_min and the median nearest-predecessor distance of the three
 *    are printed (not asserted: see docs/results);
 *  - bad arguments are refused with a message. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "jitter.h"
#include "pmj.h"
#include "stats.h"
#include "testutil.h"

static int passed_, failed_;

/* 1 when every prefix 2^k <= n (k <= kmax) is a (0,k,2)-net, else 0 with the
 * first failure in *bk, *ba: the cells of each shape counted one by one. */
static int nets(const double *xy, int64_t n, int kmax, int *bk, int *ba)
{
    for (int k = 0; k <= kmax && ((int64_t)1 << k) <= n; k++) {
        const int64_t m = (int64_t)1 << k;
        int *count = malloc((size_t)m * sizeof *count);
        for (int a = 0; a <= k; a++) {
            memset(count, 0, (size_t)m * sizeof *count);
            int ok = 1;
            for (int64_t i = 0; i < m; i++) {
                const int64_t cx = (int64_t)floor(xy[2 * i] * (double)((int64_t)1 << a));
                const int64_t cy = (int64_t)floor(xy[2 * i + 1] * (double)((int64_t)1 << (k - a)));
                if (count[cx * ((int64_t)1 << (k - a)) + cy]++) ok = 0;
            }
            if (!ok) {
                free(count);
                *bk = k, *ba = a;
                return 0;
            }
        }
        free(count);
    }
    return 1;
}

/* The paper's progressive order: with N = 4^m, points i, N + i, 2N + i and
 * 3N + i (i < N) lie in the four different subquadrants of one cell of the
 * 2^m x 2^m grid, N + i diagonally opposite i (as far as n goes). */
static int progressive_order(const double *xy, int64_t n)
{
    for (int64_t N = 1, side = 1; N < n; N *= 4, side *= 2)
        for (int64_t i = 0; i < N; i++) {
            int cx = -1, cy = -1, seen = 0, q0 = -1;
            for (int64_t t = 0; t < 4 && t * N + i < n; t++) {
                const double x = xy[2 * (t * N + i)] * (double)side, y = xy[2 * (t * N + i) + 1] * (double)side;
                const int X = (int)x, Y = (int)y, q = (int)(2 * (x - X)) + 2 * (int)(2 * (y - Y));
                if (t == 0) cx = X, cy = Y, q0 = q;
                if (X != cx || Y != cy || (seen >> q & 1) || (t == 1 && q != 3 - q0)) return 0;
                seen |= 1 << q;
            }
        }
    return 1;
}

static double nearest_before(const double *xy, int64_t j)
{
    double best = INFINITY;
    for (int64_t i = 0; i < j; i++) {
        double dx = fabs(xy[2 * i] - xy[2 * j]), dy = fabs(xy[2 * i + 1] - xy[2 * j + 1]);
        dx = dx > 0.5 ? 1 - dx : dx;
        dy = dy > 0.5 ? 1 - dy : dy;
        const double d = sqrt(dx * dx + dy * dy);
        best = d < best ? d : best;
    }
    return best;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median_nearest_before(const double *xy, int64_t n)
{
    double *d = malloc((size_t)n * sizeof *d);
    for (int64_t j = 1; j < n; j++) d[j - 1] = nearest_before(xy, j);
    qsort(d, (size_t)(n - 1), sizeof *d, cmp);
    const double m = d[(n - 1) / 2];
    free(d);
    return m;
}

int main(void)
{
    const int64_t n = 4096;
    double *a = malloc(2 * (size_t)n * sizeof *a), *b = malloc(2 * (size_t)n * sizeof *b);
    char err[256];
    int bk = -1, ba = -1, redone = 0;
    for (uint64_t seed = 1; seed <= 3; seed++) {
        double dmin[3], davg, med[3];
        for (int bn = 0; bn < 3; bn++) {
            const int cand = bn ? PMJ_CANDIDATES : 1;
            const pmj_params prm = {.candidates = cand, .global = bn == 2};
            int rc = pmj_points(n, seed, &prm, a, &redone, err, sizeof err);
            CHECK(rc == 0, "seed %llu %d candidates: %s", (unsigned long long)seed, cand, err);
            if (rc) continue;
            CHECK(nets(a, n, 12, &bk, &ba), "seed %llu %d candidates: prefix 2^%d, shape 2^-%d x 2^-%d not a net",
                  (unsigned long long)seed, cand, bk, ba, bk - ba);
            int inside = 1;
            for (int64_t i = 0; i < 2 * n; i++) inside &= a[i] >= 0 && a[i] < 1;
            CHECK(inside, "seed %llu: a coordinate outside [0, 1)", (unsigned long long)seed);
            /* progressive: a shorter run is the prefix, and again the same bytes */
            rc = pmj_points(3000, seed, &prm, b, NULL, err, sizeof err);
            CHECK(rc == 0 && memcmp(a, b, 2 * 3000 * sizeof *a) == 0, "seed %llu %d candidates: n = 3000 is not "
                  "the prefix of n = 4096", (unsigned long long)seed, cand);
            CHECK(nets(b, 3000, 12, &bk, &ba), "prefix 3000: 2^%d not a net", bk);
            rc = pmj_points(n, seed, &prm, b, NULL, err, sizeof err);
            CHECK(rc == 0 && memcmp(a, b, 2 * (size_t)n * sizeof *a) == 0, "seed %llu: not the same bytes twice",
                  (unsigned long long)seed);
            if (bn < 2)
                CHECK(progressive_order(a, n), "seed %llu %d candidates: not in the paper's progressive order",
                      (unsigned long long)seed, cand);
            cfpo_nn_stats(a, (size_t)n, NULL, &dmin[bn], &davg);
            med[bn] = median_nearest_before(a, n);
            if (!bn && seed == 1) {
                /* the check itself: two points' y swapped breaks a net */
                int64_t i = 100, j = 1000;
                const double t = b[2 * i + 1];
                b[2 * i + 1] = b[2 * j + 1];
                b[2 * j + 1] = t;
                CHECK(!nets(b, n, 12, &bk, &ba), "two y swapped: still every prefix a net");
            }
        }
        printf("seed %llu: delta_min pmj02 %.3f pmj02bn %.3f global %.3f; median nearest predecessor %.5f %.5f "
               "%.5f\n", (unsigned long long)seed, dmin[0], dmin[1], dmin[2], med[0], med[1], med[2]);
    }
    printf("steps redone after a dead end (last run): %d\n", redone);
    /* the check fails on sets that are not nets */
    jitter_points(n, 1, b);
    CHECK(!nets(b, n, 12, &bk, &ba), "a jittered set passes the net check");
    printf("jittered: first failure at prefix 2^%d, shape 2^-%d x 2^-%d\n", bk, ba, bk - ba);
    white_points(n, 1, b);
    CHECK(!nets(b, n, 12, &bk, &ba), "white noise passes the net check");
    /* bad arguments */
    const pmj_params one = {.candidates = 1}, none = {.candidates = 0};
    CHECK(!progressive_order(b, n), "white noise in the progressive order");
    CHECK(pmj_points(0, 1, &one, a, NULL, err, sizeof err) == -1 && strstr(err, "out of range"), "n = 0 accepted");
    CHECK(pmj_points(16, 1, &none, a, NULL, err, sizeof err) == -1, "0 candidates accepted");
    CHECK(pmj_points(PMJ_MAX_N + 1, 1, &one, a, NULL, err, sizeof err) == -1, "n past PMJ_MAX_N accepted");
    free(a);
    free(b);
    return test_report(passed_, failed_);
}
